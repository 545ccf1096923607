#include "solvers/ucp/recovery.h"

#include <algorithm>
#include <boost/container/small_vector.hpp>
#include <cassert>

#include "exact/fraction_free.h"
#include "exact/int_matrix.h"
#include "exact/linalg.h"
#include "solvers/ucp/integer_rows.h"

// Everything here runs in integers: the problem's data once per call (IntegerData: each row of P and of [Jn; Jt]
// times the lcm of its denominators, dense and sparse exact::IntMatrix rows with their scales), every rational vector
// over one common denominator, so that each equality of (2)-(5) is an integer dot product equal to 0 and each friction
// condition an integer comparison; the physics stays in that form (exact::RationalVector). Int128 first and, when a
// number does not fit (RingOverflow), again in Z (in_ring: straight in Z when the sizes of P show Int128 would
// overflow): exact either way, 128 bits are only a speed-up.

namespace contactcert::solvers::ucp {

namespace {

using exact::Int128;
using Index = Eigen::Index;
namespace ring = exact::ring;

/// Scratch integers: on the stack up to 64 of them (the paper's problems need fewer), so that the few microseconds
/// of a recovery are not spent in the allocator.
template <class R>
using Buffer = boost::container::small_vector<R, 64>;

/// a f, without a product when f = 1 (the scales of many rows are: a normal's, a point finger's).
template <class R>
R times(const R& a, const R& f) {
  return f == 1 ? a : ring::mul(a, f);
}

/// The data of the problem as integers, once per call: every row of P and of [Jn; Jt] over the lcm of its
/// denominators, and mu, d' = d below its first nc entries (g_obj, (g_man - tau)_abar) and theta_dot each over a
/// common denominator. [Jn; Jt] keeps only its non-zero entries (a point finger's row has one).
template <class R>
struct IntegerData {
  Index nc, nq, nt, m;
  exact::IntMatrix<R> P;        ///< P_r = P.row(r) / Lp_r (2nc x m)
  exact::SparseIntMatrix<R> J;  ///< [Jn; Jt]_r = (row r of J) / Lj_r (2nc x nt)
  Buffer<R> Lp, Lj;
  Buffer<R> scale;   ///< scale_r = Lp_r Lj_r
  R LP, LJ;          ///< the lcms of the Lp_r and of the Lj_r
  Buffer<R> factor;  ///< factor_r = LJ / Lj_r: [Jn; Jt]_r = J[r] factor_r / LJ
  Buffer<R> mu, d, theta;
  R Dmu, Dd, Dt;  ///< mu = mu / Dmu, d' = d / Dd, theta_dot = theta / Dt

  explicit IntegerData(const QuasistaticProblem& p)
      : nc(p.nc),
        nq(p.nq),
        nt(p.ntheta),
        m(p.P.cols()),
        P(2 * nc, m),
        J(nt),
        Lp(static_cast<std::size_t>(2 * nc)),
        Lj(static_cast<std::size_t>(2 * nc)),
        scale(static_cast<std::size_t>(2 * nc)),
        LP(1),
        LJ(1),
        factor(static_cast<std::size_t>(2 * nc)),
        mu(static_cast<std::size_t>(nc)),
        d(static_cast<std::size_t>(m)),
        theta(static_cast<std::size_t>(nt)) {
    for (Index r = 0; r < 2 * nc; ++r) {
      const auto k = static_cast<std::size_t>(r);
      Lp[k] = ring::to_common_denominator<R>(
          m, [&](Index j) -> const Q& { return p.P(r, j); }, P.row(r));
      const Mat<Q>& Jm = r < nc ? p.Jn : p.Jt;
      const Index i = r < nc ? r : r - nc;
      J.add_row();
      for (Index j = 0; j < nt; ++j)
        if (sgn(Jm(i, j)) != 0) J.push(j, R(0));
      const Index start = J.begin(r);
      Lj[k] = ring::to_common_denominator<R>(
          J.end(r) - start, [&](Index t) -> const Q& { return Jm(i, J.col(start + t)); }, J.values(r));
      scale[k] = times(Lp[k], Lj[k]);
      LP = ring::lcm(LP, Lp[k]);
      LJ = ring::lcm(LJ, Lj[k]);
    }
    for (std::size_t k = 0; k < factor.size(); ++k) factor[k] = ring::divexact(LJ, Lj[k]);
    Dmu = ring::to_common_denominator<R>(
        nc, [&](Index i) -> const Q& { return p.mu(i); }, mu.data());
    Dd = ring::to_common_denominator<R>(
        m, [&](Index j) -> const Q& { return p.d(nc + j); }, d.data());
    Dt = ring::to_common_denominator<R>(
        nt, [&](Index j) -> const Q& { return p.theta_dot(j); }, theta.data());
  }
  /// J[r] . x over the joints (times Lj_r: the row of [Jn; Jt] against x).
  R J_dot(Index r, const R* x) const {
    R sum(0);
    for (Index t = J.begin(r); t < J.end(r); ++t) ring::add_mul(sum, J.value(t), x[J.col(t)]);
    return sum;
  }
  /// out_j += J[r]_j c for every joint j (times Lj_r: c times the row of [Jn; Jt]).
  void J_scatter(Index r, const R& c, R* out) const {
    for (Index t = J.begin(r); t < J.end(r); ++t) ring::add_mul(out[J.col(t)], J.value(t), c);
  }
};

/// a . b over k entries.
template <class R>
R dot(const R* a, const R* b, Index k) {
  R sum(0);
  for (Index i = 0; i < k; ++i)
    if (ring::sign(a[i]) != 0) ring::add_mul(sum, a[i], b[i]);
  return sum;
}

/// Rows r of (4), (5), P_r u = v_r + h_r with u = [q_dot; -theta_abar] and h = J_alpha theta_alpha, in integers
/// for v = 0 and the joint velocities T / D (those of abar 0): J_r . T / D = h'_r / (Lj_r D) with h'_r = J[r] . T,
/// M_r = [Lj_r P[r] | Lp_r h'_r] (row-major, 2nc x (m + 1)), so that M_r (D u) - M_r[m] = scale_r D (P_r u - h_r).
template <class R>
void velocity_rows(const IntegerData<R>& g, const R* T, R* M) {
  const Index w = g.m + 1;
  for (Index r = 0; r < 2 * g.nc; ++r) {
    const auto k = static_cast<std::size_t>(r);
    R* M_r = M + r * w;
    const R* P_r = g.P.row(r);
    for (Index j = 0; j < g.m; ++j) M_r[j] = times(P_r[j], g.Lj[k]);
    M_r[g.m] = times(g.J_dot(r, T), g.Lp[k]);
  }
}

/// q_dot and theta_dot for u = [q_dot; -theta_abar] = N / (d D) and the given joint velocities T / D (0 in abar).
template <class R>
void set_generalized_velocities(const QuasistaticProblem& p, const R* N, const R& d, const R* T, const R& D,
                                PhysicalSolution& s) {
  const R dD = ring::mul(d, D);
  s.q_dot = exact::RationalVector(N, p.nq, dD);
  Buffer<R> theta(static_cast<std::size_t>(p.ntheta));
  for (Index j = 0; j < p.ntheta; ++j) theta[static_cast<std::size_t>(j)] = ring::mul(T[j], d);
  for (std::size_t k = 0; k < p.abar.size(); ++k)
    theta[static_cast<std::size_t>(p.abar[k])] = ring::sub(R(0), N[p.nq + static_cast<Index>(k)]);
  s.theta_dot = exact::RationalVector(theta.data(), p.ntheta, dD);
}

/// (4), (5) solved for u given v = (v_n, v_t^+ - v_t^-) from x; nullopt if no u reproduces v.
template <class R>
std::optional<PhysicalSolution> velocities_in(const QuasistaticProblem& p, const IntegerData<R>& g, const Vec<Q>& x) {
  const Index nc = p.nc, nt = p.ntheta, m = p.P.cols(), w = m + 1;
  // W = (x, theta_dot) over Dw; V = (v_n, v_t) over Dw; M: velocity_rows; N the solution's numerators.
  Buffer<R> buf(static_cast<std::size_t>(3 * nc + nt + 2 * nc + m));
  exact::IntMatrix<R> velocity(2 * nc, w);
  R *W = buf.data(), *V = W + 3 * nc + nt, *M = velocity.row(0), *N = V + 2 * nc;
  const R Dw = ring::to_common_denominator<R>(
      3 * nc + nt, [&](Index i) -> const Q& { return i < 3 * nc ? x(i) : p.theta_dot(i - 3 * nc); }, W);
  for (Index r = 0; r < 2 * nc; ++r) V[r] = r < nc ? W[r] : ring::sub(W[r], W[r + nc]);
  PhysicalSolution s;
  s.v_n = exact::RationalVector(V, nc, Dw);
  s.v_t = exact::RationalVector(V + nc, nc, Dw);
  // P_r (Dw u) = Dw (v_r + h_r): M_r's right-hand side gains scale_r V_r.
  velocity_rows<R>(g, W + 3 * nc, M);
  for (Index r = 0; r < 2 * nc; ++r) ring::add_mul(M[r * w + m], g.scale[static_cast<std::size_t>(r)], V[r]);
  R d;
  const exact::SolutionKind kind = velocity.solve(N, d);
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
/// (pattern_solution).
template <class R>
bool pattern_velocities_in(const QuasistaticProblem& p, const IntegerData<R>& g, const std::vector<bool>& x_zero,
                           exact::RationalVector& x, PhysicalSolution& s) {
  const Index nc = p.nc, m = p.P.cols(), w = m + 1;
  const auto zero = [&](Index i) { return x_zero[static_cast<std::size_t>(i)]; };
  // Row r < nc is v_n,r; row nc + i is v_t,i = v_t,i^+ - v_t,i^-, 0 when both are fixed to 0.
  const auto fixed = [&](Index r) { return r < nc ? zero(r) : zero(r) && zero(r + nc); };
  Index k = 0;
  for (Index r = 0; r < 2 * nc; ++r) k += fixed(r);
  if (k < m) return false;
  // M: velocity_rows with theta_dot = theta / Dt; E the fixed rows; N the solution's numerators; V = (v_n, v_t).
  Buffer<R> buf(static_cast<std::size_t>(2 * nc * w + m + 2 * nc));
  exact::IntMatrix<R> fixed_rows(k, w);
  const R* scale = g.scale.data();
  R *M = buf.data(), *E = fixed_rows.row(0), *N = M + 2 * nc * w, *V = N + m;
  velocity_rows<R>(g, g.theta.data(), M);
  for (Index r = 0, e = 0; r < 2 * nc; ++r)
    if (fixed(r)) std::move(M + r * w, M + (r + 1) * w, E + (e++) * w);  // only the free rows of M are read below
  R d;
  if (fixed_rows.solve(N, d) != exact::SolutionKind::kUnique) return false;  // d > 0
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
    for (Index j = 0; j < m; ++j) ring::add_mul(v, M_r[j], N[j]);
    const int sv = ring::sign(v);
    if (r < nc ? sv < 0 : (sv > 0 && zero(r)) || (sv < 0 && zero(r + nc))) return false;
    V[r] = ring::mul(v, ring::divexact(L, scale[r]));
  }
  const R D = ring::mul(d, ring::mul(g.Dt, L));
  s.v_n = exact::RationalVector(V, nc, D);
  s.v_t = exact::RationalVector(V + nc, nc, D);
  set_generalized_velocities(p, N, d, g.theta.data(), g.Dt, s);
  Buffer<R> X(static_cast<std::size_t>(3 * nc));  // (v_n, v_t^+, v_t^-) over D
  for (Index i = 0; i < nc; ++i) {
    const auto k = static_cast<std::size_t>(i);
    X[k] = V[i];
    const int st = ring::sign(V[nc + i]);
    if (st > 0) X[k + static_cast<std::size_t>(nc)] = V[nc + i];
    if (st < 0) X[k + static_cast<std::size_t>(2 * nc)] = ring::sub(R(0), V[nc + i]);
  }
  x = exact::RationalVector(X.data(), 3 * nc, D);
  return true;
}

/// c_n, c_t and (3): tau - g_man = Jn^T c_n + Jt^T c_t for c = (c_n, c_t) = C / Dc.
template <class R>
void set_forces(const IntegerData<R>& g, const R* C, const R& Dc, PhysicalSolution& s) {
  const Index nc = g.nc, nt = g.nt;
  s.c_n = exact::RationalVector(C, nc, Dc);
  s.c_t = exact::RationalVector(C + nc, nc, Dc);
  // tau_j = sum_r J[r]_j factor_r C_r / (LJ Dc).
  Buffer<R> t(static_cast<std::size_t>(nt));
  for (Index r = 0; r < 2 * nc; ++r)
    if (ring::sign(C[r]) != 0) g.J_scatter(r, times(C[r], g.factor[static_cast<std::size_t>(r)]), t.data());
  s.tau = exact::RationalVector(t.data(), nt, ring::mul(g.LJ, Dc));
}

/// c_n, c_t = s_t^+ - U c_n and tau (3) from y = (c_n, s_t^+, s_t^-).
template <class R>
void forces_in(const IntegerData<R>& g, const Vec<Q>& y, PhysicalSolution& s) {
  const Index nc = g.nc;
  // Y = (c_n, s_t^+) over Dy; C = (c_n, c_t) over Dc = Dy Dmu.
  Buffer<R> buf(static_cast<std::size_t>(2 * nc + 2 * nc));
  R *Y = buf.data(), *C = Y + 2 * nc;
  const R Dy = ring::to_common_denominator<R>(
      2 * nc, [&](Index i) -> const Q& { return y(i); }, Y);
  for (Index i = 0; i < nc; ++i) {  // c_t = s_t^+ - U c_n
    C[i] = ring::mul(Y[i], g.Dmu);
    C[nc + i] = ring::sub(ring::mul(Y[nc + i], g.Dmu), ring::mul(g.mu[static_cast<std::size_t>(i)], Y[i]));
  }
  set_forces(g, C, ring::mul(Dy, g.Dmu), s);
}

/// The unknowns of pattern_forces_in at contact i: none (c_n = c_t = 0), c_n with c_t = sigma mu c_n (on an edge of
/// the friction cone, or mu = 0), or c_n and c_t both free.
struct ContactForce {
  enum Kind { kZero, kEdge, kFree } kind = kZero;
  int sigma = 1;
};

/// c from the rows of (2), (3), P^T c + d' = 0, after y's pattern fixed c_n or c_t = -/+ mu c_n (pattern_solution);
/// y = (c_n, s_t^+, s_t^-).
template <class R>
std::optional<exact::RationalVector> pattern_forces_in(const QuasistaticProblem& p, const IntegerData<R>& g,
                                                       const std::vector<bool>& y_zero, PhysicalSolution& s) {
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
  // E = [K | -Dd d'] (m x (k + 1)) with column j of K the unknown's column of P^T times D_j; N the solution.
  const Index w = k + 1;
  Buffer<R> buf(static_cast<std::size_t>(2 * k + 2 * nc));
  exact::IntMatrix<R> system(m, w);
  R *E = system.row(0), *D = buf.data(), *N = D + k, *C = N + k;
  const R *Lp = g.Lp.data(), *Mu = g.mu.data();
  for (Index row = 0; row < m; ++row) E[row * w + k] = ring::sub(R(0), g.d[static_cast<std::size_t>(row)]);
  Index j = 0;
  for (Index i = 0; i < nc; ++i) {
    const ContactForce& f = contact[static_cast<std::size_t>(i)];
    const R *Pn = g.P.row(i), *Pt = g.P.row(nc + i);
    if (f.kind == ContactForce::kEdge) {
      // P_n + sigma mu P_t = (Dmu Lp_t Pn - b Pt) / (Lp_n Lp_t Dmu) with b = -sigma Mu Lp_n
      const R a = times(Lp[nc + i], g.Dmu), b = ring::mul(ring::mul(R(-f.sigma), Mu[i]), Lp[i]);
      for (Index row = 0; row < m; ++row) ring::mul_sub(a, Pn[row], b, Pt[row], E[row * w + j]);
      D[j++] = ring::mul(Lp[i], ring::mul(Lp[nc + i], g.Dmu));
    } else if (f.kind == ContactForce::kFree) {
      for (Index row = 0; row < m; ++row) E[row * w + j] = Pn[row], E[row * w + j + 1] = Pt[row];
      D[j++] = Lp[i], D[j++] = Lp[nc + i];
    }
  }
  // K (Dd z) = -Dd d' with z_j = c_j / D_j: c_j = D_j N_j / (d Dd).
  R d;
  if (k > 0) {
    if (system.solve(N, d) != exact::SolutionKind::kUnique) return std::nullopt;  // d > 0
  } else {
    for (Index row = 0; row < m; ++row)
      if (ring::sign(g.d[static_cast<std::size_t>(row)]) != 0) return std::nullopt;  // no force, but a load
    d = 1;
  }
  // c_n = Cn / Den and C = (c_n, c_t) over Dc = Den Dmu; mu c_n = Mu Cn / Dc, s_t^+- = (Mu Cn +- c_t) / Dc.
  const R Dc = ring::mul(ring::mul(d, g.Dd), g.Dmu);
  Buffer<R> Y(static_cast<std::size_t>(3 * nc));  // (c_n, s_t^+, s_t^-) over Dc
  j = 0;
  for (Index i = 0; i < nc; ++i) {
    const ContactForce& f = contact[static_cast<std::size_t>(i)];
    const R Cn = f.kind == ContactForce::kZero ? R(0) : ring::mul(D[j], N[j]);
    if (ring::sign(Cn) < 0) return std::nullopt;
    const R mu_cn = ring::mul(Mu[i], Cn);
    C[i] = ring::mul(Cn, g.Dmu);
    C[nc + i] = f.kind == ContactForce::kZero   ? R(0)
                : f.kind == ContactForce::kEdge ? ring::mul(R(f.sigma), mu_cn)
                                                : ring::mul(ring::mul(D[j + 1], N[j + 1]), g.Dmu);
    const R plus = ring::add(mu_cn, C[nc + i]), minus = ring::sub(mu_cn, C[nc + i]);
    if (ring::sign(plus) < 0 || ring::sign(minus) < 0) return std::nullopt;  // |c_t| > mu c_n
    Y[static_cast<std::size_t>(i)] = C[i];
    Y[static_cast<std::size_t>(nc + i)] = plus;
    Y[static_cast<std::size_t>(2 * nc + i)] = minus;
    j += f.kind == ContactForce::kZero ? 0 : f.kind == ContactForce::kEdge ? 1 : 2;
  }
  set_forces(g, C, Dc, s);
  return exact::RationalVector(Y.data(), 3 * nc, Dc);
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

/// a / Da = b / Db for Da, Db > 0: the numerators when the denominators agree (as recovered), else crosswise.
template <class R>
bool same_ratio(const R& a, const R& Da, const R& b, const R& Db) {
  return Da == Db ? a == b : ring::mul(a, Db) == ring::mul(b, Da);
}

template <class R>
ConditionsCheck check_in(const QuasistaticProblem& p, const IntegerData<R>& g, const PhysicalSolution& s) {
  ConditionsCheck out;
  auto bad = [&](const std::string& what) {
    out.status = ConditionsStatus::kViolated;
    out.violations.push_back(what);
  };
  const Index nc = p.nc, nq = p.nq, nt = p.ntheta;
  // F = (c_n, c_t) over Df, T = tau over Dtau, G = (q_dot, theta_dot) over Dg, V = (v_n, v_t) over Dv: each pair
  // as recovered shares its denominator, and the equations compare across them without rescaling the vectors.
  Buffer<R> buf(static_cast<std::size_t>(2 * nc + nt + nq + nt + 2 * nc + nt + 2 * nc));
  R *F = buf.data(), *T = F + 2 * nc, *G = T + nt, *V = G + nq + nt, *sums = V + 2 * nc, *wF = sums + nt;
  const R Df = over_common_denominator<R>({&s.c_n, &s.c_t}, F);
  const R Dtau = over_common_denominator<R>({&s.tau}, T);
  const R Dg = over_common_denominator<R>({&s.q_dot, &s.theta_dot}, G);
  const R Dv = over_common_denominator<R>({&s.v_n, &s.v_t}, V);
  const R *Gq = G, *Gt = G + nq;
  // (2) W_n c_n + W_t c_t + g_obj = 0: row k is column k of P against (c_n, c_t), and g_obj(k) = d'(k): over
  // LP Df Dd, Dd sum_r P[r]_k wF_r + (LP Df) d'_k = 0 with wF_r = (LP / Lp_r) F_r.
  for (Index r = 0; r < 2 * nc; ++r)
    wF[r] = ring::sign(F[r]) == 0 ? R(0) : times(F[r], ring::divexact(g.LP, g.Lp[static_cast<std::size_t>(r)]));
  const R LP_Df = ring::mul(g.LP, Df);
  for (Index k = 0; k < nq; ++k) {
    R sum(0);
    for (Index r = 0; r < 2 * nc; ++r)
      if (ring::sign(wF[r]) != 0) ring::add_mul(sum, g.P.row(r)[k], wF[r]);
    sum = times(sum, g.Dd);
    ring::add_mul(sum, LP_Df, g.d[static_cast<std::size_t>(k)]);
    if (ring::sign(sum) != 0) bad("(2) equilibrium row " + std::to_string(k) + " is not zero");
  }
  // (3) Jn^T c_n + Jt^T c_t = tau - g_man: sums_j = sum_r J[r]_j factor_r F_r over LJ Df against T_j over Dtau.
  for (Index r = 0; r < 2 * nc; ++r)
    if (ring::sign(F[r]) != 0) g.J_scatter(r, times(F[r], g.factor[static_cast<std::size_t>(r)]), sums);
  const R LJ_Df = ring::mul(g.LJ, Df);
  for (Index j = 0; j < nt; ++j)
    if (!same_ratio(sums[j], LJ_Df, T[j], Dtau)) bad("(3) joint " + std::to_string(j) + " equilibrium fails");
  // For the effort-controlled joints tau - g_man = -(d)_abar: -tau = d' / Dd.
  for (std::size_t k = 0; k < p.abar.size(); ++k)
    if (!same_ratio(ring::sub(R(0), T[p.abar[k]]), Dtau, g.d[static_cast<std::size_t>(p.nq) + k], g.Dd))
      bad("(3) joint " + std::to_string(p.abar[k]) + " does not carry its given effort");
  // (4), (5) with the given velocities of the joints in alpha
  for (int j : p.alpha)
    if (!same_ratio(Gt[j], Dg, g.theta[static_cast<std::size_t>(j)], g.Dt))
      bad("theta_dot of joint " + std::to_string(j) + " differs from its given value");
  // Row r of (4) (r = i) and of (5) (r = nc + i): P_r's first nq columns against q_dot, minus J_r theta_dot, minus
  // v_r; times scale_r = Lp_r Lj_r and over Du = lcm(Dg, Dv): (Lj_r P[r] . Gq - Lp_r J[r] . Gt) (Du / Dg) -
  // scale_r V_r (Du / Dv) = 0.
  const R Du = ring::lcm(Dg, Dv), fg = ring::divexact(Du, Dg), fv = ring::divexact(Du, Dv);
  const auto residual = [&](Index r) {
    const auto k = static_cast<std::size_t>(r);
    R x = dot(g.P.row(r), Gq, nq);
    ring::mul_sub(g.Lj[k], x, g.Lp[k], g.J_dot(r, Gt), x);
    ring::mul_sub(fg, x, times(g.scale[k], fv), V[r], x);
    return ring::sign(x);
  };
  const R zero(0);
  for (Index i = 0; i < nc; ++i) {
    const auto c = [i] { return " contact " + std::to_string(i); };
    if (residual(i) != 0) bad("(4)" + c() + ": v_n != Wn^T q_dot - Jn theta_dot");
    if (residual(nc + i) != 0) bad("(5)" + c() + ": v_t != Wt^T q_dot - Jt theta_dot");
    const int vn = ring::sign(V[i]), vt = ring::sign(V[nc + i]), cn = ring::sign(F[i]), ctn = ring::sign(F[nc + i]);
    if (vn < 0) bad("(6)" + c() + ": v_n < 0");
    // mu c_n = (Mu / Dmu) Cn / Df and c_t = Ct / Df.
    const R &Cn = F[i], &Ct = F[nc + i];
    const R bound = ring::mul(g.mu[static_cast<std::size_t>(i)], Cn), ct = times(Ct, g.Dmu);
    if ((ring::sign(ct) < 0 ? ring::sub(zero, ct) : ct) > bound) bad("(7)" + c() + ": |c_t| > mu c_n");
    if (cn > 0 && vn != 0) bad("(8)" + c() + ": c_n > 0 but v_n != 0");
    if (vn > 0 && (cn != 0 || ctn != 0)) bad("(9)" + c() + ": v_n > 0 but c != 0");
    if (vt > 0 && ring::add(ct, bound) != 0) bad("(10)" + c() + ": v_t > 0 but c_t != -mu c_n");
    if (vt < 0 && ct != bound) bad("(10)" + c() + ": v_t < 0 but c_t != mu c_n");
  }
  return out;
}

template <class R>
std::optional<PatternSolution> pattern_solution_in(const QuasistaticProblem& p, const std::vector<bool>& x_zero,
                                                   const std::vector<bool>& y_zero) {
  const IntegerData<R> g(p);
  PatternSolution out;
  if (!pattern_velocities_in(p, g, x_zero, out.x, out.physical)) return std::nullopt;
  std::optional<exact::RationalVector> y = pattern_forces_in(p, g, y_zero, out.physical);
  if (!y) return std::nullopt;
  out.y = std::move(*y);
  out.conditions = check_in(p, g, out.physical);
  return out;
}

}  // namespace

std::optional<PhysicalSolution> recover(const QuasistaticProblem& p, const Vec<Q>& x, const Vec<Q>& y) {
  return in_ring(elimination_bits(p.P, true), [&]<class R>() {
    const IntegerData<R> g(p);
    std::optional<PhysicalSolution> s = velocities_in<R>(p, g, x);
    if (s) forces_in<R>(g, y, *s);
    return s;
  });
}

std::optional<PatternSolution> pattern_solution(const QuasistaticProblem& p, const std::vector<bool>& x_zero,
                                                const std::vector<bool>& y_zero) {
  return in_ring(elimination_bits(p.P, true), [&]<class R>() { return pattern_solution_in<R>(p, x_zero, y_zero); });
}

ConditionsCheck check_conditions(const QuasistaticProblem& p, const PhysicalSolution& s) {
  return in_ring(elimination_bits(p.P, true), [&]<class R>() { return check_in<R>(p, IntegerData<R>(p), s); });
}

}  // namespace contactcert::solvers::ucp
