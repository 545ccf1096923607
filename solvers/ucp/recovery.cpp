#include "solvers/ucp/recovery.h"

#include <numeric>

#include "exact/fraction_free.h"
#include "exact/linalg.h"
#include "exact/rounded_certificate.h"

// Both functions run in integers: every rational vector over one common denominator, every data row (of P,
// Jn, Jt, d, mu) times the lcm of its denominators, so that each equality of (2)-(5) is an integer dot product
// equal to 0 and each friction condition an integer comparison. They run in Int128 first and, when a number
// does not fit (RingOverflow), again in Z (with_exact_ring): exact either way, 128 bits are only a speed-up.

namespace contactcert::solvers::ucp {

namespace {

using exact::Int128;
using Index = Eigen::Index;
namespace ring = exact::ring;

using ring::is_integer;

/// sum_i a(i) u(i) over rationals a(i) (zeros skipped) and ring elements u(i), times the lcm L of the
/// denominators of the a(i) (set): the rational sum is (returned) / L.
template <class R, class A, class U>
R scaled_dot(Index k, A a, U u, R& L) {
  R sum(0), num, den;
  L = 1;
  for (Index i = 0; i < k; ++i) {
    const Q& ai = a(i);
    if (sgn(ai) == 0) continue;
    ring::from_integer(ai.get_num(), num);
    if (!is_integer(ai)) {
      ring::from_integer(ai.get_den(), den);
      const R grown = ring::lcm(L, den);
      if (grown != L) sum = ring::mul(sum, ring::divexact(grown, L)), L = grown;
      if (den != L) num = ring::mul(num, ring::divexact(L, den));
    } else if (L != 1) {
      num = ring::mul(num, L);
    }
    sum = ring::add(sum, ring::mul(num, u(i)));
  }
  return sum;
}

/// a = -b, without a rational temporary (both in lowest terms).
bool is_negation(const Q& a, const Q& b) {
  return sgn(a) == -sgn(b) && mpz_cmpabs(a.get_num_mpz_t(), b.get_num_mpz_t()) == 0 &&
         mpz_cmp(a.get_den_mpz_t(), b.get_den_mpz_t()) == 0;
}

template <class R>
std::optional<PhysicalSolution> recover_in(const QuasistaticProblem& p, const Vec<Q>& x, const Vec<Q>& y) {
  const Index nc = p.nc, nq = p.nq, nt = p.ntheta, m = p.P.cols(), w = m + 1;
  // One buffer: W = (x, theta_dot_alpha) over Dw; Y = (c_n, s_t^+) over Dy; Mu = mu over Dmu; C = (c_n, c_t)
  // over Dc = Dy Dmu; M = [P | rhs] scaled to integers (2nc x (m + 1)); N the solution's numerators.
  std::vector<R> buf(static_cast<std::size_t>(3 * nc + nt + 2 * nc + nc + 2 * nc + 2 * nc * w + m));
  R *W = buf.data(), *Y = W + 3 * nc + nt, *Mu = Y + 2 * nc, *C = Mu + nc, *M = C + 2 * nc, *N = M + 2 * nc * w;
  PhysicalSolution s;
  s.v_n = x.segment(0, nc);
  s.c_n = y.segment(0, nc);
  const R Dw = ring::to_common_denominator<R>(
      3 * nc + nt, [&](Index i) -> const Q& { return i < 3 * nc ? x(i) : p.theta_dot(i - 3 * nc); }, W);
  for (int j : p.abar) W[3 * nc + j] = 0;
  s.v_t.resize(nc);
  for (Index i = 0; i < nc; ++i) {
    const Q &plus = x(nc + i), &minus = x(2 * nc + i);
    if (sgn(minus) == 0)
      s.v_t(i) = plus;
    else if (sgn(plus) == 0)
      mpq_neg(s.v_t(i).get_mpq_t(), minus.get_mpq_t());
    else
      ring::to_rational(ring::sub(W[nc + i], W[2 * nc + i]), Dw, s.v_t(i));
  }
  const R Dy = ring::to_common_denominator<R>(
      2 * nc, [&](Index i) -> const Q& { return y(i); }, Y);
  const R Dmu = ring::to_common_denominator<R>(
      nc, [&](Index i) -> const Q& { return p.mu(i); }, Mu);
  const R Dc = ring::mul(Dy, Dmu);
  s.c_t.resize(nc);
  for (Index i = 0; i < nc; ++i) {  // c_t = s_t^+ - U c_n
    C[i] = ring::mul(Y[i], Dmu);
    C[nc + i] = ring::sub(ring::mul(Y[nc + i], Dmu), ring::mul(Mu[i], Y[i]));
    if (sgn(p.mu(i)) == 0 || sgn(y(i)) == 0)
      s.c_t(i) = y(nc + i);
    else
      ring::to_rational(C[nc + i], Dc, s.c_t(i));
  }
  // (4), (5): [v_n; v_t] + J_alpha theta_alpha = P [q_dot; -theta_abar]. Row r of P times the lcm Lp of its
  // denominators and the lcm Lh of those of J's row r: (Lh Lp P_r) b Dw = Lp (Lh v_r + h_r) with
  // h_r = Lh Dw (J_alpha theta_alpha)_r, so b = N / (d Dw) for the integer solution N / d.
  for (Index r = 0; r < 2 * nc; ++r) {
    R* M_r = M + r * w;
    const R Lp = ring::to_common_denominator<R>(
        m, [&](Index j) -> const Q& { return p.P(r, j); }, M_r);
    R Lh;
    const R h = scaled_dot<R>(
        nt, [&](Index j) -> const Q& { return r < nc ? p.Jn(r, j) : p.Jt(r - nc, j); },
        [&](Index j) -> const R& { return W[3 * nc + j]; }, Lh);
    const R v = r < nc ? W[r] : ring::sub(W[r], W[r + nc]);
    M_r[m] = ring::mul(Lp, ring::add(ring::mul(Lh, v), h));
    if (Lh != 1)
      for (Index j = 0; j < m; ++j) M_r[j] = ring::mul(M_r[j], Lh);
  }
  R d;
  const exact::SolutionKind kind = exact::unique_solution(M, 2 * nc, m, N, d);
  if (kind == exact::SolutionKind::kInconsistent) return std::nullopt;
  s.q_dot.resize(nq);
  s.theta_dot = p.theta_dot;
  if (kind == exact::SolutionKind::kUnique) {
    const R D = ring::mul(d, Dw);
    for (Index k = 0; k < nq; ++k) ring::to_rational(N[k], D, s.q_dot(k));
    for (std::size_t k = 0; k < p.abar.size(); ++k)
      ring::to_rational(ring::sub(R(0), N[nq + static_cast<Index>(k)]), D, s.theta_dot(p.abar[k]));
  } else {
    // P without full column rank (not in practice): some solution, by elimination in Q.
    Vec<Q> v(2 * nc);
    v << s.v_n, s.v_t;
    const std::optional<Vec<Q>> b = exact::solve<Q>(p.P, Vec<Q>(v + p.J_alpha_theta_alpha()));
    if (!b) return std::nullopt;
    s.q_dot = b->segment(0, nq);
    for (std::size_t k = 0; k < p.abar.size(); ++k) s.theta_dot(p.abar[k]) = -(*b)(nq + static_cast<Index>(k));
  }
  // (3): tau - g_man = Jn^T c_n + Jt^T c_t, a copy of c_n(i) or c_t(i) for a joint that only meets a
  // contact's normal or tangent with coefficient 1 (point fingers).
  s.tau.resize(nt);
  for (Index j = 0; j < nt; ++j) {
    auto J = [&](Index i) -> const Q& { return i < nc ? p.Jn(i, j) : p.Jt(i - nc, j); };
    Index nonzeros = 0, at = 0;
    for (Index i = 0; i < 2 * nc && nonzeros < 2; ++i)
      if (sgn(J(i)) != 0) ++nonzeros, at = i;
    if (nonzeros == 0) {
      s.tau(j) = 0;
    } else if (nonzeros == 1 && J(at) == 1) {
      s.tau(j) = at < nc ? s.c_n(at) : s.c_t(at - nc);
    } else {
      R L;
      const R t = scaled_dot<R>(
          2 * nc, J, [&](Index i) -> const R& { return C[i]; }, L);
      ring::to_rational(t, ring::mul(L, Dc), s.tau(j));
    }
  }
  return s;
}

template <class R>
ConditionsCheck check_in(const QuasistaticProblem& p, const PhysicalSolution& s) {
  ConditionsCheck out;
  auto bad = [&](const std::string& what) {
    out.status = ConditionsStatus::kViolated;
    out.violations.push_back(what);
  };
  const Index nc = p.nc, nq = p.nq, nt = p.ntheta;
  // F = (c_n, c_t, tau) over Df, U = (q_dot, theta_dot, v_n, v_t) over Du.
  std::vector<R> buf(static_cast<std::size_t>(2 * nc + nt + nq + nt + 2 * nc));
  R *F = buf.data(), *U = F + 2 * nc + nt;
  const R Df = ring::to_common_denominator<R>(
      2 * nc + nt,
      [&](Index i) -> const Q& { return i < nc       ? s.c_n(i)
                                        : i < 2 * nc ? s.c_t(i - nc)
                                                     : s.tau(i - 2 * nc); }, F);
  ring::to_common_denominator<R>(
      nq + nt + 2 * nc,
      [&](Index i) -> const Q& {
        return i < nq             ? s.q_dot(i)
               : i < nq + nt      ? s.theta_dot(i - nq)
               : i < nq + nt + nc ? s.v_n(i - nq - nt)
                                  : s.v_t(i - nq - nt - nc);
      },
      U);
  const R *Uq = U, *Ut = U + nq, *Uvn = Ut + nt, *Uvt = Uvn + nc;
  R L;
  // (2) W_n c_n + W_t c_t + g_obj = 0: row k is column k of P against (c_n, c_t), and g_obj(k) = d(nc + k).
  for (Index k = 0; k < nq; ++k) {
    const R r2 = scaled_dot<R>(
        2 * nc + 1, [&](Index i) -> const Q& { return i < 2 * nc ? p.P(i, k) : p.d(nc + k); },
        [&](Index i) -> const R& { return i < 2 * nc ? F[i] : Df; }, L);
    if (ring::sign(r2) != 0) bad("(2) equilibrium row " + std::to_string(k) + " is not zero");
  }
  // (3) Jn^T c_n + Jt^T c_t = tau - g_man; for the effort-controlled joints tau - g_man = -(d)_abar.
  for (Index j = 0; j < nt; ++j) {
    const R r3 = scaled_dot<R>(
        2 * nc, [&](Index i) -> const Q& { return i < nc ? p.Jn(i, j) : p.Jt(i - nc, j); },
        [&](Index i) -> const R& { return F[i]; }, L);
    if (r3 != ring::mul(L, F[2 * nc + j])) bad("(3) joint " + std::to_string(j) + " equilibrium fails");
  }
  for (std::size_t k = 0; k < p.abar.size(); ++k)
    if (!is_negation(s.tau(p.abar[k]), p.d(nc + p.nq + static_cast<Index>(k))))
      bad("(3) joint " + std::to_string(p.abar[k]) + " does not carry its given effort");
  // (4), (5) with the given velocities of the joints in alpha
  for (int j : p.alpha)
    if (s.theta_dot(j) != p.theta_dot(j))
      bad("theta_dot of joint " + std::to_string(j) + " differs from its given value");
  const R zero(0);
  for (Index i = 0; i < nc; ++i) {
    // Row i of (4) and of (5): [P_i (first nq columns) | -J_i] against (q_dot, theta_dot), minus v.
    const auto residual = [&](Index row, const Mat<Q>& J, const R& v) {
      const R r = scaled_dot<R>(
          nq + nt, [&](Index k) -> const Q& { return k < nq ? p.P(row, k) : J(i, k - nq); },
          [&](Index k) -> R { return k < nq ? Uq[k] : ring::sub(zero, Ut[k - nq]); }, L);
      return ring::sub(r, ring::mul(L, v));
    };
    const auto c = [i] { return " contact " + std::to_string(i); };
    if (ring::sign(residual(i, p.Jn, Uvn[i])) != 0) bad("(4)" + c() + ": v_n != Wn^T q_dot - Jn theta_dot");
    if (ring::sign(residual(nc + i, p.Jt, Uvt[i])) != 0) bad("(5)" + c() + ": v_t != Wt^T q_dot - Jt theta_dot");
    if (sgn(s.v_n(i)) < 0) bad("(6)" + c() + ": v_n < 0");
    // mu c_n = (a / e) Cn / Df and c_t = Ct / Df.
    R a, e;
    ring::from_rational(p.mu(i), a, e);
    const R &Cn = F[i], &Ct = F[nc + i];
    const R bound = ring::mul(a, Cn), ct = ring::mul(Ct, e);
    if ((ring::sign(ct) < 0 ? ring::sub(zero, ct) : ct) > bound) bad("(7)" + c() + ": |c_t| > mu c_n");
    if (sgn(s.c_n(i)) > 0 && sgn(s.v_n(i)) != 0) bad("(8)" + c() + ": c_n > 0 but v_n != 0");
    if (sgn(s.v_n(i)) > 0 && (sgn(s.c_n(i)) != 0 || sgn(s.c_t(i)) != 0)) bad("(9)" + c() + ": v_n > 0 but c != 0");
    if (sgn(s.v_t(i)) > 0 && ring::add(ct, bound) != 0) bad("(10)" + c() + ": v_t > 0 but c_t != -mu c_n");
    if (sgn(s.v_t(i)) < 0 && ct != bound) bad("(10)" + c() + ": v_t < 0 but c_t != mu c_n");
  }
  return out;
}

}  // namespace

std::optional<PhysicalSolution> recover(const QuasistaticProblem& p, const Vec<Q>& x, const Vec<Q>& y) {
  return exact::with_exact_ring<Q, Int128>([&]<class R>() { return recover_in<R>(p, x, y); });
}

ConditionsCheck check_conditions(const QuasistaticProblem& p, const PhysicalSolution& s) {
  return exact::with_exact_ring<Q, Int128>([&]<class R>() { return check_in<R>(p, s); });
}

}  // namespace contactcert::solvers::ucp
