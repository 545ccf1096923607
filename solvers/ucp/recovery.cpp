#include "solvers/ucp/recovery.h"

#include "exact/linalg.h"
#include "exact/rounded_certificate.h"

namespace contactcert::solvers::ucp {

namespace {
using Index = Eigen::Index;
}

std::optional<PhysicalSolution> recover(const QuasistaticProblem& p, const Vec<Q>& x, const Vec<Q>& y) {
  const Index nc = p.nc, nq = p.nq;
  PhysicalSolution s;
  s.v_n = x.segment(0, nc);
  s.v_t = x.segment(nc, nc) - x.segment(2 * nc, nc);
  s.c_n = y.segment(0, nc);
  s.c_t = Vec<Q>(nc);
  for (Index i = 0; i < nc; ++i) s.c_t(i) = y(nc + i) - p.mu(i) * s.c_n(i);  // c_t = s_t^+ - U c_n
  // (4), (5): [v_n; v_t] + J_alpha theta_alpha = W^T q_dot - J_abar theta_abar = P [q_dot; -theta_abar].
  Vec<Q> v(2 * nc);
  v << s.v_n, s.v_t;
  const Vec<Q> rhs = v + p.J_alpha_theta_alpha();
  // P has full column rank in practice: its one solution in 128-bit integers (GMP on overflow), else
  // elimination in Q.
  std::vector<Index> columns(static_cast<std::size_t>(p.P.cols()));
  for (Index j = 0; j < p.P.cols(); ++j) columns[static_cast<std::size_t>(j)] = j;
  std::optional<Vec<Q>> b = exact::with_exact_ring<Q, exact::Int128>(
      [&]<class R>() { return exact::unique_solution(exact::integer_system<R>(p.P, rhs), columns); });
  if (!b) b = exact::solve<Q>(p.P, rhs);
  if (!b) return std::nullopt;
  s.q_dot = b->segment(0, nq);
  s.theta_dot = p.theta_dot;
  for (std::size_t k = 0; k < p.abar.size(); ++k) s.theta_dot(p.abar[k]) = -(*b)(nq + static_cast<Index>(k));
  s.tau = p.Jn.transpose() * s.c_n + p.Jt.transpose() * s.c_t;
  return s;
}

ConditionsCheck check_conditions(const QuasistaticProblem& p, const PhysicalSolution& s) {
  ConditionsCheck out;
  auto bad = [&](const std::string& what) {
    out.status = ConditionsStatus::kViolated;
    out.violations.push_back(what);
  };
  const Index nc = p.nc;
  const Mat<Q> Wn = p.Wn(), Wt = p.Wt();
  // (2) W_n c_n + W_t c_t + g_obj = 0
  const Vec<Q> r2 = Wn * s.c_n + Wt * s.c_t + p.g_obj();
  for (Index k = 0; k < r2.size(); ++k)
    if (sgn(r2(k)) != 0) bad("(2) equilibrium row " + std::to_string(k) + " is not zero");
  // (3) Jn^T c_n + Jt^T c_t = tau - g_man; for the effort-controlled joints tau - g_man = -(d)_abar.
  const Vec<Q> r3 = p.Jn.transpose() * s.c_n + p.Jt.transpose() * s.c_t - s.tau;
  for (Index k = 0; k < r3.size(); ++k)
    if (sgn(r3(k)) != 0) bad("(3) joint " + std::to_string(k) + " equilibrium fails");
  for (std::size_t k = 0; k < p.abar.size(); ++k)
    if (s.tau(p.abar[k]) != -p.d(nc + p.nq + static_cast<Index>(k)))
      bad("(3) joint " + std::to_string(p.abar[k]) + " does not carry its given effort");
  // (4), (5) with the given velocities of the joints in alpha
  for (int j : p.alpha)
    if (s.theta_dot(j) != p.theta_dot(j))
      bad("theta_dot of joint " + std::to_string(j) + " differs from its given value");
  const Vec<Q> r4 = Wn.transpose() * s.q_dot - p.Jn * s.theta_dot - s.v_n;
  const Vec<Q> r5 = Wt.transpose() * s.q_dot - p.Jt * s.theta_dot - s.v_t;
  for (Index i = 0; i < nc; ++i) {
    const std::string c = " contact " + std::to_string(i);
    if (sgn(r4(i)) != 0) bad("(4)" + c + ": v_n != Wn^T q_dot - Jn theta_dot");
    if (sgn(r5(i)) != 0) bad("(5)" + c + ": v_t != Wt^T q_dot - Jt theta_dot");
    if (sgn(s.v_n(i)) < 0) bad("(6)" + c + ": v_n < 0");
    const Q bound = p.mu(i) * s.c_n(i);
    if (abs(s.c_t(i)) > bound) bad("(7)" + c + ": |c_t| > mu c_n");
    if (sgn(s.c_n(i)) > 0 && sgn(s.v_n(i)) != 0) bad("(8)" + c + ": c_n > 0 but v_n != 0");
    if (sgn(s.v_n(i)) > 0 && (sgn(s.c_n(i)) != 0 || sgn(s.c_t(i)) != 0)) bad("(9)" + c + ": v_n > 0 but c != 0");
    if (sgn(s.v_t(i)) > 0 && s.c_t(i) != -bound) bad("(10)" + c + ": v_t > 0 but c_t != -mu c_n");
    if (sgn(s.v_t(i)) < 0 && s.c_t(i) != bound) bad("(10)" + c + ": v_t < 0 but c_t != mu c_n");
  }
  return out;
}

}  // namespace contactcert::solvers::ucp
