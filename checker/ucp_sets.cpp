#include "checker/ucp_sets.h"

#include "checker/assembly_ucp_check.h"
#include "exact/linalg.h"
#include "geometry/assembly.h"

namespace contactcert::checker::ucp_sets {

using Index = Eigen::Index;
using exact::JsonInput;
using solvers::ucp::QuasistaticProblem;
using solvers::ucp::UcpInstance;
using solvers::ucp::UcpProblem;

CheckData derive(const UcpProblem& u) {
  CheckData c;
  if (!u.quasistatic) {
    const UcpInstance<Q>& ucp = u.ucp();
    c.n = ucp.n();
    c.AX = ucp.X.A, c.bX = ucp.X.b, c.AY = ucp.Y.A, c.bY = ucp.Y.b;
    return c;
  }
  const QuasistaticProblem& p = *u.quasistatic;
  const Index nc = p.nc, nq = p.nq, na = static_cast<Index>(p.abar.size());
  c.quasistatic = true;
  c.n = 3 * nc;
  c.P = p.P;
  c.h = Vec<Q>::Zero(2 * nc);
  for (int j : p.alpha)
    for (Index i = 0; i < nc; ++i) {
      c.h(i) += p.Jn(i, j) * p.theta_dot(j);
      c.h(nc + i) += p.Jt(i, j) * p.theta_dot(j);
    }
  // Y = {(c_n, s+, s-) >= 0 : 2U c_n - s+ - s- = 0, (W_n - W_t U) c_n + W_t s+ = -g_obj,
  //      ((J_n^T)_abar - (J_t^T)_abar U) c_n + (J_t^T)_abar s+ = (tau - g_man)_abar}.
  c.AY = Mat<Q>::Zero(nc + nq + na, 3 * nc);
  for (Index i = 0; i < nc; ++i) {
    c.AY(i, i) = 2 * p.mu(i);
    c.AY(i, nc + i) = -1;
    c.AY(i, 2 * nc + i) = -1;
    for (Index k = 0; k < nq; ++k) {
      const Q wn = p.P(i, k), wt = p.P(nc + i, k);
      c.AY(nc + k, i) = wn - wt * p.mu(i);
      c.AY(nc + k, nc + i) = wt;
    }
    for (Index a = 0; a < na; ++a) {
      const int j = p.abar[static_cast<std::size_t>(a)];
      c.AY(nc + nq + a, i) = p.Jn(i, j) - p.Jt(i, j) * p.mu(i);
      c.AY(nc + nq + a, nc + i) = p.Jt(i, j);
    }
  }
  c.bY = -p.d;
  return c;
}

std::string check_farkas(const Mat<Q>& A, const Vec<Q>& b, const std::vector<bool>& zero, const Vec<Q>& u) {
  if (u.size() != A.rows())
    return "Farkas vector has " + std::to_string(u.size()) + " entries, expected " + std::to_string(A.rows());
  const Vec<Q> g = A.transpose() * u;
  for (Index j = 0; j < g.size(); ++j)
    if (!zero[static_cast<std::size_t>(j)] && sgn(g(j)) < 0)
      return "u^T A_" + std::to_string(j) + " < 0 on a column that is not fixed to zero";
  const Q ub = u.dot(b);
  if (sgn(ub) >= 0) return "u^T b >= 0";
  return "";
}

std::string check_velocity_farkas(const CheckData& c, const std::vector<bool>& zero, const Vec<Q>& w) {
  const Index nc = c.n / 3;
  if (w.size() != 2 * nc)
    return "Farkas vector has " + std::to_string(w.size()) + " entries, expected 2nc = " + std::to_string(2 * nc);
  const Vec<Q> wP = c.P.transpose() * w;
  for (Index k = 0; k < wP.size(); ++k)
    if (sgn(wP(k)) != 0) return "w^T P is not zero in column " + std::to_string(k);
  for (Index j = 0; j < c.n; ++j) {
    if (zero[static_cast<std::size_t>(j)]) continue;
    const Q g = j < 2 * nc ? w(j) : Q(-w(j - nc));
    if (sgn(g) < 0) return "w^T B_" + std::to_string(j) + " < 0 on a column that is not fixed to zero";
  }
  if (sgn(Q(w.dot(c.h))) <= 0) return "w^T J_alpha theta_dot_alpha <= 0";
  return "";
}

bool primitive_or_zero(const Vec<Q>& u) {
  exact::Z g = 0;
  for (Index i = 0; i < u.size(); ++i) {
    if (u(i).get_den() != 1) return false;
    g = gcd(g, u(i).get_num());
  }
  return g == 0 || g == 1;
}

Vec<Q> contact_velocity(const CheckData& c, const Vec<Q>& x) {
  const Index nc = c.n / 3;
  Vec<Q> v(2 * nc);
  v << x.head(nc), Vec<Q>(x.segment(nc, nc) - x.tail(nc));
  return v;
}

bool satisfies_X(const CheckData& c, const Vec<Q>& x) {
  if (!c.quasistatic) return c.AX * x == c.bX;
  return exact::solve<Q>(c.P, Vec<Q>(contact_velocity(c, x) + c.h)).has_value();
}

std::string embedding_violation(const JsonInput& cert, const UcpProblem& problem) {
  if (cert.at("problem_sha256").string() != cert.at("problem").canonical_sha256())
    return "problem_sha256 is not the digest of the embedded problem";
  const auto text = cert.find("assembly");
  if (!text) return "";
  const geometry::Assembly a =
      geometry::read_assembly(JsonInput::parse(text->string(), cert.file() + " (embedded assembly)"));
  const std::string why =
      problem.quasistatic ? assembly_problem_violation(a, *problem.quasistatic) : "it is not a quasistatic problem";
  return why.empty() ? "" : "the embedded problem is not the quasistatic problem of the embedded assembly: " + why;
}

}  // namespace contactcert::checker::ucp_sets
