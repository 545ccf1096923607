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

/// Rows r of (4), (5), P_r u = v_r + h_r with u = [q_dot; -theta_abar] and h = J_alpha theta_alpha, in integers
/// for v = 0: with P_r = Pint_r / Lp_r, the joint velocities T / D (those of abar 0) and J_r . T = h'_r / Lh_r,
/// M_r = [Lh_r Pint_r | Lp_r h'_r] (row-major, 2nc x (m + 1)), so that M_r (D u) - M_r[m] = scale_r D (P_r u - h_r)
/// with scale_r = Lp_r Lh_r.
template <class R>
void velocity_rows(const QuasistaticProblem& p, const R* T, R* M, R* scale) {
  const Index nc = p.nc, nt = p.ntheta, m = p.P.cols(), w = m + 1;
  for (Index r = 0; r < 2 * nc; ++r) {
    R* M_r = M + r * w;
    const R Lp = ring::to_common_denominator<R>(
        m, [&](Index j) -> const Q& { return p.P(r, j); }, M_r);
    R Lh;
    const R h = scaled_dot<R>(
        nt, [&](Index j) -> const Q& { return r < nc ? p.Jn(r, j) : p.Jt(r - nc, j); },
        [&](Index j) -> const R& { return T[j]; }, Lh);
    M_r[m] = ring::mul(Lp, h);
    if (Lh != 1)
      for (Index j = 0; j < m; ++j) M_r[j] = ring::mul(M_r[j], Lh);
    scale[r] = ring::mul(Lp, Lh);
  }
}

/// q_dot and the unknown theta_dot of u = N / D, with the given joint velocities.
template <class R>
void set_generalized_velocities(const QuasistaticProblem& p, const R* N, const R& D, PhysicalSolution& s) {
  s.q_dot.resize(p.nq);
  for (Index k = 0; k < p.nq; ++k) ring::to_rational(N[k], D, s.q_dot(k));
  s.theta_dot = p.theta_dot;
  for (std::size_t k = 0; k < p.abar.size(); ++k)
    ring::to_rational(ring::sub(R(0), N[p.nq + static_cast<Index>(k)]), D, s.theta_dot(p.abar[k]));
}

/// (4), (5) solved for u given v = (v_n, v_t^+ - v_t^-) from x; nullopt if no u reproduces v.
template <class R>
std::optional<PhysicalSolution> velocities_in(const QuasistaticProblem& p, const Vec<Q>& x) {
  const Index nc = p.nc, nt = p.ntheta, m = p.P.cols(), w = m + 1;
  // W = (x, theta_dot) over Dw; M, scale: velocity_rows; N the solution's numerators.
  std::vector<R> buf(static_cast<std::size_t>(3 * nc + nt + 2 * nc * w + 2 * nc + m));
  R *W = buf.data(), *M = W + 3 * nc + nt, *scale = M + 2 * nc * w, *N = scale + 2 * nc;
  PhysicalSolution s;
  s.v_n = x.segment(0, nc);
  const R Dw = ring::to_common_denominator<R>(
      3 * nc + nt, [&](Index i) -> const Q& { return i < 3 * nc ? x(i) : p.theta_dot(i - 3 * nc); }, W);
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
  // P_r (Dw u) = Dw (v_r + h_r): M_r's right-hand side gains scale_r V_r for v_r = V_r / Dw.
  velocity_rows<R>(p, W + 3 * nc, M, scale);
  for (Index r = 0; r < 2 * nc; ++r) {
    const R v = r < nc ? W[r] : ring::sub(W[r], W[r + nc]);
    M[r * w + m] = ring::add(M[r * w + m], ring::mul(scale[r], v));
  }
  R d;
  const exact::SolutionKind kind = exact::unique_solution(M, 2 * nc, m, N, d);
  if (kind == exact::SolutionKind::kInconsistent) return std::nullopt;
  if (kind == exact::SolutionKind::kUnique) {
    set_generalized_velocities(p, N, ring::mul(d, Dw), s);
  } else {
    // P without full column rank (not in practice): some solution, by elimination in Q.
    Vec<Q> v(2 * nc);
    v << s.v_n, s.v_t;
    const std::optional<Vec<Q>> b = exact::solve<Q>(p.P, Vec<Q>(v + p.J_alpha_theta_alpha()));
    if (!b) return std::nullopt;
    s.q_dot = b->segment(0, p.nq);
    s.theta_dot = p.theta_dot;
    for (std::size_t k = 0; k < p.abar.size(); ++k) s.theta_dot(p.abar[k]) = -(*b)(p.nq + static_cast<Index>(k));
  }
  return s;
}

/// u from the rows of (4), (5) where x's pattern fixes v to 0, then v = P u - h (recover_velocities).
template <class R>
std::optional<PhysicalSolution> pattern_velocities_in(const QuasistaticProblem& p, const std::vector<bool>& x_zero) {
  const Index nc = p.nc, nt = p.ntheta, m = p.P.cols(), w = m + 1;
  const auto zero = [&](Index i) { return x_zero[static_cast<std::size_t>(i)]; };
  // Row r < nc is v_n,r; row nc + i is v_t,i = v_t,i^+ - v_t,i^-, 0 when both are fixed to 0.
  const auto fixed = [&](Index r) { return r < nc ? zero(r) : zero(r) && zero(r + nc); };
  Index k = 0;
  for (Index r = 0; r < 2 * nc; ++r) k += fixed(r);
  if (k < m) return std::nullopt;
  // T = theta_dot over Dt; M, scale: velocity_rows; E the fixed rows; N the solution's numerators.
  std::vector<R> buf(static_cast<std::size_t>(nt + 2 * nc * w + 2 * nc + k * w + m));
  R *T = buf.data(), *M = T + nt, *scale = M + 2 * nc * w, *E = scale + 2 * nc, *N = E + k * w;
  const R Dt = ring::to_common_denominator<R>(
      nt, [&](Index j) -> const Q& { return p.theta_dot(j); }, T);
  velocity_rows<R>(p, T, M, scale);
  for (Index r = 0, e = 0; r < 2 * nc; ++r)
    if (fixed(r)) std::copy(M + r * w, M + (r + 1) * w, E + (e++) * w);
  R d;
  if (exact::unique_solution(E, k, m, N, d) != exact::SolutionKind::kUnique) return std::nullopt;
  // D u = N / d, so v_r = (M_r N - d M_r[m]) / (d scale_r Dt); v_r = 0 on the fixed rows.
  PhysicalSolution s;
  s.v_n.resize(nc);
  s.v_t.resize(nc);
  const int sd = ring::sign(d);
  for (Index r = 0; r < 2 * nc; ++r) {
    Q& v = r < nc ? s.v_n(r) : s.v_t(r - nc);
    if (fixed(r)) continue;  // a default rational is 0
    const R* M_r = M + r * w;
    R V = ring::mul(ring::sub(R(0), d), M_r[m]);
    for (Index j = 0; j < m; ++j) V = ring::add(V, ring::mul(M_r[j], N[j]));
    const int sv = ring::sign(V) * sd;
    if (r < nc ? sv < 0 : (sv > 0 && zero(r)) || (sv < 0 && zero(r + nc))) return std::nullopt;
    ring::to_rational(V, ring::mul(d, ring::mul(scale[r], Dt)), v);
  }
  set_generalized_velocities(p, N, ring::mul(d, Dt), s);
  return s;
}

/// (3): tau - g_man = Jn^T c_n + Jt^T c_t for c = (c_n, c_t) = C / Dc (s.c_n, s.c_t set): a copy of c_n(i) or c_t(i)
/// for a joint that only meets a contact's normal or tangent with coefficient 1 (point fingers).
template <class R>
void set_efforts(const QuasistaticProblem& p, const R* C, const R& Dc, PhysicalSolution& s) {
  const Index nc = p.nc, nt = p.ntheta;
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
}

/// c_n, c_t = s_t^+ - U c_n and tau (3) from y = (c_n, s_t^+, s_t^-).
template <class R>
void forces_in(const QuasistaticProblem& p, const Vec<Q>& y, PhysicalSolution& s) {
  const Index nc = p.nc;
  // Y = (c_n, s_t^+) over Dy; Mu = mu over Dmu; C = (c_n, c_t) over Dc = Dy Dmu.
  std::vector<R> buf(static_cast<std::size_t>(2 * nc + nc + 2 * nc));
  R *Y = buf.data(), *Mu = Y + 2 * nc, *C = Mu + nc;
  s.c_n = y.segment(0, nc);
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
  set_efforts(p, C, Dc, s);
}

/// The unknowns of pattern_forces_in at contact i: none (c_n = c_t = 0), c_n with c_t = sigma mu c_n (on an edge of
/// the friction cone, or mu = 0), or c_n and c_t both free.
struct ContactForce {
  enum Kind { kZero, kEdge, kFree } kind = kZero;
  int sigma = 1;
};

/// c from the rows of (2), (3), P^T c + d' = 0 (d' = d below its first nc entries: g_obj and (g_man - tau)_abar),
/// after y's pattern fixed c_n or c_t = -/+ mu c_n (recover_forces with a pattern); y = (c_n, s_t^+, s_t^-).
template <class R>
std::optional<Vec<Q>> pattern_forces_in(const QuasistaticProblem& p, const std::vector<bool>& y_zero,
                                        PhysicalSolution& s) {
  const Index nc = p.nc, m = p.P.cols();
  const auto zero = [&](Index i) { return y_zero[static_cast<std::size_t>(i)]; };
  std::vector<ContactForce> contact(static_cast<std::size_t>(nc));
  Index k = 0;  // unknowns
  for (Index i = 0; i < nc; ++i) {
    ContactForce& f = contact[static_cast<std::size_t>(i)];
    const bool plus = zero(nc + i), minus = zero(2 * nc + i);      // s_t^+ = c_t + mu c_n, s_t^- = mu c_n - c_t
    if (zero(i) || (plus && minus && sgn(p.mu(i)) > 0)) continue;  // c_n = 0 forces c_t = 0 (s_t^+, s_t^- >= 0)
    f.kind = plus || minus ? ContactForce::kEdge : ContactForce::kFree;
    f.sigma = plus ? -1 : 1;
    k += f.kind == ContactForce::kEdge ? 1 : 2;
  }
  if (k > m) return std::nullopt;
  // Pi = P over the row denominators Lp (2nc x m); Mu = mu over Dmu, with mu_i = a_i / e_i; Dd: d' over Dd;
  // E = [K | -Dd d'] (m x (k + 1)) with column j of K the unknown's column of P^T times D_j; N the solution.
  const Index w = k + 1;
  std::vector<R> buf(static_cast<std::size_t>(2 * nc * m + 2 * nc + nc + m + m * w + 2 * k + 2 * nc));
  R *Pi = buf.data(), *Lp = Pi + 2 * nc * m, *Mu = Lp + 2 * nc, *Dint = Mu + nc, *E = Dint + m, *D = E + m * w,
    *N = D + k, *C = N + k;
  for (Index r = 0; r < 2 * nc; ++r)
    Lp[r] = ring::to_common_denominator<R>(
        m, [&](Index j) -> const Q& { return p.P(r, j); }, Pi + r * m);
  const R Dmu = ring::to_common_denominator<R>(
      nc, [&](Index i) -> const Q& { return p.mu(i); }, Mu);
  const R Dd = ring::to_common_denominator<R>(
      m, [&](Index j) -> const Q& { return p.d(nc + j); }, Dint);
  for (Index row = 0; row < m; ++row) E[row * w + k] = ring::sub(R(0), Dint[row]);
  Index j = 0;
  for (Index i = 0; i < nc; ++i) {
    const ContactForce& f = contact[static_cast<std::size_t>(i)];
    const R *Pn = Pi + i * m, *Pt = Pi + (nc + i) * m;
    if (f.kind == ContactForce::kEdge) {
      // P_n + sigma mu P_t = (Dmu Lp_t Pn + sigma Mu Lp_n Pt) / (Lp_n Lp_t Dmu)
      const R a = ring::mul(Dmu, Lp[nc + i]), b = ring::mul(ring::mul(R(f.sigma), Mu[i]), Lp[i]);
      for (Index row = 0; row < m; ++row) E[row * w + j] = ring::add(ring::mul(a, Pn[row]), ring::mul(b, Pt[row]));
      D[j++] = ring::mul(Lp[i], ring::mul(Lp[nc + i], Dmu));
    } else if (f.kind == ContactForce::kFree) {
      for (Index row = 0; row < m; ++row) E[row * w + j] = Pn[row], E[row * w + j + 1] = Pt[row];
      D[j++] = Lp[i], D[j++] = Lp[nc + i];
    }
  }
  // K (Dd z) = -Dd d' with z_j = c_j / D_j: c_j = D_j N_j / (d Dd).
  R d;
  if (k > 0) {
    if (exact::unique_solution(E, m, k, N, d) != exact::SolutionKind::kUnique) return std::nullopt;
    if (ring::sign(d) < 0) {
      d = ring::sub(R(0), d);
      for (Index t = 0; t < k; ++t) N[t] = ring::sub(R(0), N[t]);
    }
  } else {
    for (Index row = 0; row < m; ++row)
      if (ring::sign(Dint[row]) != 0) return std::nullopt;  // no force, but a load
    d = 1;
  }
  // c_n = Cn / Den and C = (c_n, c_t) over Dc = Den Dmu; mu c_n = Mu Cn / Dc, s_t^+- = (Mu Cn +- c_t) / Dc.
  const R Den = ring::mul(d, Dd), Dc = ring::mul(Den, Dmu);
  j = 0;
  for (Index i = 0; i < nc; ++i) {
    const ContactForce& f = contact[static_cast<std::size_t>(i)];
    const R Cn = f.kind == ContactForce::kZero ? R(0) : ring::mul(D[j], N[j]);
    if (ring::sign(Cn) < 0) return std::nullopt;
    const R mu_cn = ring::mul(Mu[i], Cn);
    C[i] = ring::mul(Cn, Dmu);
    C[nc + i] = f.kind == ContactForce::kZero   ? R(0)
                : f.kind == ContactForce::kEdge ? ring::mul(R(f.sigma), mu_cn)
                                                : ring::mul(ring::mul(D[j + 1], N[j + 1]), Dmu);
    if (ring::sign(ring::add(mu_cn, C[nc + i])) < 0 || ring::sign(ring::sub(mu_cn, C[nc + i])) < 0)
      return std::nullopt;  // |c_t| > mu c_n
    j += f.kind == ContactForce::kZero ? 0 : f.kind == ContactForce::kEdge ? 1 : 2;
  }
  Vec<Q> y(3 * nc);  // zeros (a default rational is 0)
  s.c_n.resize(nc);
  s.c_t.resize(nc);
  for (Index i = 0; i < nc; ++i) {
    if (ring::sign(C[i]) == 0 && ring::sign(C[nc + i]) == 0) {
      s.c_n(i) = 0, s.c_t(i) = 0;
      continue;
    }
    ring::to_rational(C[i], Dc, s.c_n(i));
    ring::to_rational(C[nc + i], Dc, s.c_t(i));
    const R mu_cn = ring::mul(Mu[i], ring::divexact(C[i], Dmu));
    y(i) = s.c_n(i);
    ring::to_rational(ring::add(mu_cn, C[nc + i]), Dc, y(nc + i));
    ring::to_rational(ring::sub(mu_cn, C[nc + i]), Dc, y(2 * nc + i));
  }
  set_efforts(p, C, Dc, s);
  return y;
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
  std::optional<PhysicalSolution> s =
      exact::with_exact_ring<Q, Int128>([&]<class R>() { return velocities_in<R>(p, x); });
  if (s) recover_forces(p, y, *s);
  return s;
}

std::optional<PhysicalSolution> pattern_velocities(const QuasistaticProblem& p, const std::vector<bool>& x_zero) {
  return exact::with_exact_ring<Q, Int128>([&]<class R>() { return pattern_velocities_in<R>(p, x_zero); });
}

Vec<Q> velocity_point(const PhysicalSolution& s) {
  const Index nc = s.v_n.size();
  Vec<Q> x(3 * nc);  // zeros (a default rational is 0)
  x.segment(0, nc) = s.v_n;
  for (Index i = 0; i < nc; ++i) {
    const int sv = sgn(s.v_t(i));
    if (sv > 0) x(nc + i) = s.v_t(i);
    if (sv < 0) mpq_neg(x(2 * nc + i).get_mpq_t(), s.v_t(i).get_mpq_t());
  }
  return x;
}

void recover_forces(const QuasistaticProblem& p, const Vec<Q>& y, PhysicalSolution& s) {
  exact::with_exact_ring<Q, Int128>([&]<class R>() { forces_in<R>(p, y, s); });
}

std::optional<Vec<Q>> pattern_forces(const QuasistaticProblem& p, const std::vector<bool>& y_zero,
                                     PhysicalSolution& s) {
  return exact::with_exact_ring<Q, Int128>([&]<class R>() { return pattern_forces_in<R>(p, y_zero, s); });
}

ConditionsCheck check_conditions(const QuasistaticProblem& p, const PhysicalSolution& s) {
  return exact::with_exact_ring<Q, Int128>([&]<class R>() { return check_in<R>(p, s); });
}

}  // namespace contactcert::solvers::ucp
