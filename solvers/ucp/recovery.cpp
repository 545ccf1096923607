#include "solvers/ucp/recovery.h"

#include <cassert>
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

/// P's rows over their denominators: P_r = Pi_r / Lp_r (Pi row-major, 2nc x m).
template <class R>
void integer_P(const QuasistaticProblem& p, R* Pi, R* Lp) {
  const Index m = p.P.cols();
  for (Index r = 0; r < p.P.rows(); ++r)
    Lp[r] = ring::to_common_denominator<R>(
        m, [&](Index j) -> const Q& { return p.P(r, j); }, Pi + r * m);
}

/// Rows r of (4), (5), P_r u = v_r + h_r with u = [q_dot; -theta_abar] and h = J_alpha theta_alpha, in integers
/// for v = 0: with P_r = Pi_r / Lp_r (integer_P), the joint velocities T / D (those of abar 0) and
/// J_r . T = h'_r / Lh_r, M_r = [Lh_r Pi_r | Lp_r h'_r] (row-major, 2nc x (m + 1)), so that
/// M_r (D u) - M_r[m] = scale_r D (P_r u - h_r) with scale_r = Lp_r Lh_r.
template <class R>
void velocity_rows(const QuasistaticProblem& p, const R* Pi, const R* Lp, const R* T, R* M, R* scale) {
  const Index nc = p.nc, nt = p.ntheta, m = p.P.cols(), w = m + 1;
  for (Index r = 0; r < 2 * nc; ++r) {
    R* M_r = M + r * w;
    R Lh;
    const R h = scaled_dot<R>(
        nt, [&](Index j) -> const Q& { return r < nc ? p.Jn(r, j) : p.Jt(r - nc, j); },
        [&](Index j) -> const R& { return T[j]; }, Lh);
    for (Index j = 0; j < m; ++j) M_r[j] = Lh != 1 ? ring::mul(Pi[r * m + j], Lh) : Pi[r * m + j];
    M_r[m] = ring::mul(Lp[r], h);
    scale[r] = ring::mul(Lp[r], Lh);
  }
}

/// The exact vector num[0..k-1] / den.
template <class R>
exact::RationalVector rational_vector(const R* num, Index k, const R& den) {
  return exact::RationalVector(std::vector<R>(num, num + k), den);
}

/// q_dot and theta_dot for u = [q_dot; -theta_abar] = N / (d D) and the given joint velocities T / D (0 in abar).
template <class R>
void set_generalized_velocities(const QuasistaticProblem& p, const R* N, const R& d, const R* T, const R& D,
                                PhysicalSolution& s) {
  const R dD = ring::mul(d, D);
  s.q_dot = rational_vector(N, p.nq, dD);
  std::vector<R> theta(static_cast<std::size_t>(p.ntheta));
  for (Index j = 0; j < p.ntheta; ++j) theta[static_cast<std::size_t>(j)] = ring::mul(T[j], d);
  for (std::size_t k = 0; k < p.abar.size(); ++k)
    theta[static_cast<std::size_t>(p.abar[k])] = ring::sub(R(0), N[p.nq + static_cast<Index>(k)]);
  s.theta_dot = exact::RationalVector(std::move(theta), dD);
}

/// (4), (5) solved for u given v = (v_n, v_t^+ - v_t^-) from x; nullopt if no u reproduces v.
template <class R>
std::optional<PhysicalSolution> velocities_in(const QuasistaticProblem& p, const Vec<Q>& x) {
  const Index nc = p.nc, nt = p.ntheta, m = p.P.cols(), w = m + 1;
  // W = (x, theta_dot) over Dw; V = (v_n, v_t) over Dw; M, scale: velocity_rows; N the solution's numerators.
  std::vector<R> buf(static_cast<std::size_t>(3 * nc + nt + 2 * nc + 2 * nc * w + 2 * nc + m + 2 * nc * m + 2 * nc));
  R *W = buf.data(), *V = W + 3 * nc + nt, *M = V + 2 * nc, *scale = M + 2 * nc * w, *N = scale + 2 * nc, *Pi = N + m,
    *Lp = Pi + 2 * nc * m;
  const R Dw = ring::to_common_denominator<R>(
      3 * nc + nt, [&](Index i) -> const Q& { return i < 3 * nc ? x(i) : p.theta_dot(i - 3 * nc); }, W);
  for (Index r = 0; r < 2 * nc; ++r) V[r] = r < nc ? W[r] : ring::sub(W[r], W[r + nc]);
  PhysicalSolution s;
  s.v_n = rational_vector(V, nc, Dw);
  s.v_t = rational_vector(V + nc, nc, Dw);
  // P_r (Dw u) = Dw (v_r + h_r): M_r's right-hand side gains scale_r V_r.
  integer_P(p, Pi, Lp);
  velocity_rows<R>(p, Pi, Lp, W + 3 * nc, M, scale);
  for (Index r = 0; r < 2 * nc; ++r) M[r * w + m] = ring::add(M[r * w + m], ring::mul(scale[r], V[r]));
  R d;
  const exact::SolutionKind kind = exact::unique_solution(M, 2 * nc, m, N, d);
  if (kind == exact::SolutionKind::kInconsistent) return std::nullopt;
  if (kind == exact::SolutionKind::kUnique) {
    set_generalized_velocities(p, N, d, W + 3 * nc, Dw, s);
  } else {
    // P without full column rank (not in practice): some solution, by elimination in Q.
    Vec<Q> v(2 * nc);
    v << s.v_n.to_q(), s.v_t.to_q();
    const std::optional<Vec<Q>> b = exact::solve<Q>(p.P, Vec<Q>(v + p.J_alpha_theta_alpha()));
    if (!b) return std::nullopt;
    s.q_dot = exact::RationalVector(Vec<Q>(b->segment(0, p.nq)));
    Vec<Q> theta = p.theta_dot;
    for (std::size_t k = 0; k < p.abar.size(); ++k) theta(p.abar[k]) = -(*b)(p.nq + static_cast<Index>(k));
    s.theta_dot = exact::RationalVector(theta);
  }
  return s;
}

/// u from the rows of (4), (5) where x's pattern fixes v to 0, then v = P u - h, and x = (v_n, v_t^+, v_t^-)
/// (pattern_solution; Pi, Lp: integer_P).
template <class R>
bool pattern_velocities_in(const QuasistaticProblem& p, const std::vector<bool>& x_zero, const R* Pi, const R* Lp,
                           Vec<Q>& x, PhysicalSolution& s) {
  const Index nc = p.nc, nt = p.ntheta, m = p.P.cols(), w = m + 1;
  const auto zero = [&](Index i) { return x_zero[static_cast<std::size_t>(i)]; };
  // Row r < nc is v_n,r; row nc + i is v_t,i = v_t,i^+ - v_t,i^-, 0 when both are fixed to 0.
  const auto fixed = [&](Index r) { return r < nc ? zero(r) : zero(r) && zero(r + nc); };
  Index k = 0;
  for (Index r = 0; r < 2 * nc; ++r) k += fixed(r);
  if (k < m) return false;
  // T = theta_dot over Dt; M, scale: velocity_rows; E the fixed rows; N the solution's numerators; V = (v_n, v_t).
  std::vector<R> buf(static_cast<std::size_t>(nt + 2 * nc * w + 2 * nc + k * w + m + 2 * nc));
  R *T = buf.data(), *M = T + nt, *scale = M + 2 * nc * w, *E = scale + 2 * nc, *N = E + k * w, *V = N + m;
  const R Dt = ring::to_common_denominator<R>(
      nt, [&](Index j) -> const Q& { return p.theta_dot(j); }, T);
  velocity_rows<R>(p, Pi, Lp, T, M, scale);
  for (Index r = 0, e = 0; r < 2 * nc; ++r)
    if (fixed(r)) std::copy(M + r * w, M + (r + 1) * w, E + (e++) * w);
  R d;
  if (exact::unique_solution(E, k, m, N, d) != exact::SolutionKind::kUnique) return false;
  if (ring::sign(d) < 0) {
    d = ring::sub(R(0), d);
    for (Index j = 0; j < m; ++j) N[j] = ring::sub(R(0), N[j]);
  }
  // Dt u = N / d, so v_r = (M_r N - d M_r[m]) / (d scale_r Dt), 0 on the fixed rows: over D = d Dt L with L the
  // lcm of the free rows' scales.
  R L(1);
  for (Index r = 0; r < 2 * nc; ++r)
    if (!fixed(r)) L = ring::lcm(L, scale[r]);
  for (Index r = 0; r < 2 * nc; ++r) {
    V[r] = 0;
    if (fixed(r)) continue;
    const R* M_r = M + r * w;
    R v = ring::mul(ring::sub(R(0), d), M_r[m]);
    for (Index j = 0; j < m; ++j) v = ring::add(v, ring::mul(M_r[j], N[j]));
    const int sv = ring::sign(v);
    if (r < nc ? sv < 0 : (sv > 0 && zero(r)) || (sv < 0 && zero(r + nc))) return false;
    V[r] = ring::mul(v, ring::divexact(L, scale[r]));
  }
  const R D = ring::mul(d, ring::mul(Dt, L));
  s.v_n = rational_vector(V, nc, D);
  s.v_t = rational_vector(V + nc, nc, D);
  set_generalized_velocities(p, N, d, T, Dt, s);
  x = Vec<Q>(3 * nc);  // zeros (a default rational is 0)
  for (Index i = 0; i < nc; ++i) {
    if (ring::sign(V[i]) != 0) ring::to_rational(V[i], D, x(i));
    const int st = ring::sign(V[nc + i]);
    if (st > 0) ring::to_rational(V[nc + i], D, x(nc + i));
    if (st < 0) ring::to_rational(ring::sub(R(0), V[nc + i]), D, x(2 * nc + i));
  }
  return true;
}

/// c_n, c_t and (3): tau - g_man = Jn^T c_n + Jt^T c_t for c = (c_n, c_t) = C / Dc.
template <class R>
void set_forces(const QuasistaticProblem& p, const R* C, const R& Dc, PhysicalSolution& s) {
  const Index nc = p.nc, nt = p.ntheta;
  s.c_n = rational_vector(C, nc, Dc);
  s.c_t = rational_vector(C + nc, nc, Dc);
  // tau_j = t_j / (L_j Dc), over Lt Dc with Lt the lcm of the L_j.
  std::vector<R> t(static_cast<std::size_t>(nt));
  R L_small[16]{};
  std::vector<R> L_large(static_cast<std::size_t>(nt > 16 ? nt : 0));
  R* const L = nt > 16 ? L_large.data() : L_small;
  R Lt(1);
  for (Index j = 0; j < nt; ++j) {
    const auto k = static_cast<std::size_t>(j);
    t[k] = scaled_dot<R>(
        2 * nc, [&](Index i) -> const Q& { return i < nc ? p.Jn(i, j) : p.Jt(i - nc, j); },
        [&](Index i) -> const R& { return C[i]; }, L[k]);
    Lt = ring::lcm(Lt, L[k]);
  }
  if (Lt != 1)
    for (std::size_t k = 0; k < t.size(); ++k) t[k] = ring::mul(t[k], ring::divexact(Lt, L[k]));
  s.tau = exact::RationalVector(std::move(t), ring::mul(Lt, Dc));
}

/// c_n, c_t = s_t^+ - U c_n and tau (3) from y = (c_n, s_t^+, s_t^-).
template <class R>
void forces_in(const QuasistaticProblem& p, const Vec<Q>& y, PhysicalSolution& s) {
  const Index nc = p.nc;
  // Y = (c_n, s_t^+) over Dy; Mu = mu over Dmu; C = (c_n, c_t) over Dc = Dy Dmu.
  std::vector<R> buf(static_cast<std::size_t>(2 * nc + nc + 2 * nc));
  R *Y = buf.data(), *Mu = Y + 2 * nc, *C = Mu + nc;
  const R Dy = ring::to_common_denominator<R>(
      2 * nc, [&](Index i) -> const Q& { return y(i); }, Y);
  const R Dmu = ring::to_common_denominator<R>(
      nc, [&](Index i) -> const Q& { return p.mu(i); }, Mu);
  for (Index i = 0; i < nc; ++i) {  // c_t = s_t^+ - U c_n
    C[i] = ring::mul(Y[i], Dmu);
    C[nc + i] = ring::sub(ring::mul(Y[nc + i], Dmu), ring::mul(Mu[i], Y[i]));
  }
  set_forces(p, C, ring::mul(Dy, Dmu), s);
}

/// The unknowns of pattern_forces_in at contact i: none (c_n = c_t = 0), c_n with c_t = sigma mu c_n (on an edge of
/// the friction cone, or mu = 0), or c_n and c_t both free.
struct ContactForce {
  enum Kind { kZero, kEdge, kFree } kind = kZero;
  int sigma = 1;
};

/// c from the rows of (2), (3), P^T c + d' = 0 (d' = d below its first nc entries: g_obj and (g_man - tau)_abar),
/// after y's pattern fixed c_n or c_t = -/+ mu c_n (pattern_forces); y = (c_n, s_t^+, s_t^-).
template <class R>
std::optional<Vec<Q>> pattern_forces_in(const QuasistaticProblem& p, const std::vector<bool>& y_zero, const R* Pi,
                                        const R* Lp, PhysicalSolution& s) {
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
  // Mu = mu over Dmu, with mu_i = a_i / e_i; Dd: d' over Dd; E = [K | -Dd d'] (m x (k + 1)) with column j of K
  // the unknown's column of P^T times D_j; N the solution.
  const Index w = k + 1;
  std::vector<R> buf(static_cast<std::size_t>(nc + m + m * w + 2 * k + 2 * nc));
  R *Mu = buf.data(), *Dint = Mu + nc, *E = Dint + m, *D = E + m * w, *N = D + k, *C = N + k;
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
  const R Dc = ring::mul(ring::mul(d, Dd), Dmu);
  Vec<Q> y(3 * nc);  // zeros (a default rational is 0)
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
    const R plus = ring::add(mu_cn, C[nc + i]), minus = ring::sub(mu_cn, C[nc + i]);
    if (ring::sign(plus) < 0 || ring::sign(minus) < 0) return std::nullopt;  // |c_t| > mu c_n
    if (ring::sign(C[i]) != 0) ring::to_rational(C[i], Dc, y(i));
    if (ring::sign(plus) != 0) ring::to_rational(plus, Dc, y(nc + i));
    if (ring::sign(minus) != 0) ring::to_rational(minus, Dc, y(2 * nc + i));
    j += f.kind == ContactForce::kZero ? 0 : f.kind == ContactForce::kEdge ? 1 : 2;
  }
  set_forces(p, C, Dc, s);
  return y;
}

template <class R>
std::optional<PatternSolution> pattern_solution_in(const QuasistaticProblem& p, const std::vector<bool>& x_zero,
                                                   const std::vector<bool>& y_zero) {
  std::vector<R> buf(static_cast<std::size_t>(2 * p.nc * (p.P.cols() + 1)));
  R *Pi = buf.data(), *Lp = Pi + 2 * p.nc * p.P.cols();
  integer_P(p, Pi, Lp);
  PatternSolution out;
  if (!pattern_velocities_in(p, x_zero, Pi, Lp, out.x, out.physical)) return std::nullopt;
  std::optional<Vec<Q>> y = pattern_forces_in(p, y_zero, Pi, Lp, out.physical);
  if (!y) return std::nullopt;
  out.y = std::move(*y);
  return out;
}

/// The vectors `parts` over one common denominator (returned) in R, one after the other in out.
template <class R>
R over_common_denominator(std::initializer_list<const exact::RationalVector*> parts, R* out) {
  R L(1);
  R dens[4]{};
  assert(parts.size() <= 4);
  R* at = out;
  std::size_t k = 0;
  for (const exact::RationalVector* v : parts) {
    v->numerators(at, dens[k]);
    L = ring::lcm(L, dens[k++]);
    at += v->size();
  }
  at = out;
  k = 0;
  for (const exact::RationalVector* v : parts) {
    if (dens[k] != L) {
      const R f = ring::divexact(L, dens[k]);
      for (Index i = 0; i < v->size(); ++i) at[i] = ring::mul(at[i], f);
    }
    at += v->size();
    ++k;
  }
  return L;
}

/// u / D = q as rationals (q in lowest terms, D > 0).
template <class R>
bool equals(const R& u, const R& D, const Q& q) {
  R a, b;
  ring::from_rational(q, a, b);
  return ring::mul(u, b) == ring::mul(a, D);
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
  const R Df = over_common_denominator<R>({&s.c_n, &s.c_t, &s.tau}, F);
  const R Du = over_common_denominator<R>({&s.q_dot, &s.theta_dot, &s.v_n, &s.v_t}, U);
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
    if (!equals(ring::sub(R(0), F[2 * nc + p.abar[k]]), Df, p.d(nc + p.nq + static_cast<Index>(k))))
      bad("(3) joint " + std::to_string(p.abar[k]) + " does not carry its given effort");
  // (4), (5) with the given velocities of the joints in alpha
  for (int j : p.alpha)
    if (!equals(Ut[j], Du, p.theta_dot(j)))
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
    const int vn = ring::sign(Uvn[i]), vt = ring::sign(Uvt[i]), cn = ring::sign(F[i]), ctn = ring::sign(F[nc + i]);
    if (vn < 0) bad("(6)" + c() + ": v_n < 0");
    // mu c_n = (a / e) Cn / Df and c_t = Ct / Df.
    R a, e;
    ring::from_rational(p.mu(i), a, e);
    const R &Cn = F[i], &Ct = F[nc + i];
    const R bound = ring::mul(a, Cn), ct = ring::mul(Ct, e);
    if ((ring::sign(ct) < 0 ? ring::sub(zero, ct) : ct) > bound) bad("(7)" + c() + ": |c_t| > mu c_n");
    if (cn > 0 && vn != 0) bad("(8)" + c() + ": c_n > 0 but v_n != 0");
    if (vn > 0 && (cn != 0 || ctn != 0)) bad("(9)" + c() + ": v_n > 0 but c != 0");
    if (vt > 0 && ring::add(ct, bound) != 0) bad("(10)" + c() + ": v_t > 0 but c_t != -mu c_n");
    if (vt < 0 && ct != bound) bad("(10)" + c() + ": v_t < 0 but c_t != mu c_n");
  }
  return out;
}

}  // namespace

std::optional<PhysicalSolution> recover(const QuasistaticProblem& p, const Vec<Q>& x, const Vec<Q>& y) {
  std::optional<PhysicalSolution> s =
      exact::with_exact_ring<Q, Int128>([&]<class R>() { return velocities_in<R>(p, x); });
  if (s) exact::with_exact_ring<Q, Int128>([&]<class R>() { forces_in<R>(p, y, *s); });
  return s;
}

std::optional<PatternSolution> pattern_solution(const QuasistaticProblem& p, const std::vector<bool>& x_zero,
                                                const std::vector<bool>& y_zero) {
  return exact::with_exact_ring<Q, Int128>([&]<class R>() { return pattern_solution_in<R>(p, x_zero, y_zero); });
}

ConditionsCheck check_conditions(const QuasistaticProblem& p, const PhysicalSolution& s) {
  return exact::with_exact_ring<Q, Int128>([&]<class R>() { return check_in<R>(p, s); });
}

}  // namespace contactcert::solvers::ucp
