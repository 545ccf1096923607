#include "solvers/ucp/farkas_rounding.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "exact/int_matrix.h"
#include "exact/rational_reconstruction.h"
#include "exact/rounded_check.h"

namespace contactcert::solvers::ucp {

namespace {

using Index = Eigen::Index;
using exact::Int128;
using exact::Z;
using exact::ring::add;
using exact::ring::mul;
using exact::ring::sign;
using exact::ring::sub;

double to_double(Int128 v) { return static_cast<double>(v); }
double to_double(const Z& v) { return v.get_d(); }

/// Y as a Farkas vector of the rows of s if it is one: Y^T b < 0 and Y^T A_j >= 0 unless j is in `zero`; the
/// result is y_i = row_scale_i Y_i (for the rows before scaling) with its negative columns.
template <class R>
std::optional<FarkasVector> checked_farkas(const exact::IntegerSystem<R>& s, const std::vector<R>& Y,
                                           const std::vector<bool>& zero) {
  R acc(0);
  for (Index i = 0; i < s.m; ++i) acc = add(acc, mul(s.b[static_cast<std::size_t>(i)], Y[static_cast<std::size_t>(i)]));
  if (sign(acc) >= 0) return std::nullopt;
  FarkasVector f;
  const std::vector<R> yA = exact::left_product(s, Y);
  for (Index j = 0; j < s.n; ++j) {
    if (sign(yA[static_cast<std::size_t>(j)]) >= 0) continue;
    if (!zero[static_cast<std::size_t>(j)]) return std::nullopt;
    f.negative.push_back(j);
  }
  f.y = Vec<Q>(s.m);
  for (Index i = 0; i < s.m; ++i)
    f.y(i) = exact::ring::to_field<Q>(mul(s.row_scale[static_cast<std::size_t>(i)], Y[static_cast<std::size_t>(i)]));
  return f;
}

/// One equation of a square integer system: sum over terms (j, a) of a u_j = rhs.
template <class R>
struct Equation {
  std::vector<std::pair<Index, R>> terms;
  R rhs;
};

/// A positive multiple U of the unique solution u of the square system `eqs` in m unknowns; false if it has none
/// (singular). The basis systems of the UCP's faces are sparse: X's columns come from the sparse rows of P's left
/// null space, and an artificial's equation has one unknown. So the equations with one open unknown fix it first
/// (u_j = U_j / D over a common denominator D, each new value substituted into the other equations), repeatedly;
/// the rest, a small core, is solved by fraction-free elimination (exact::IntMatrix::solve). The matrix of the
/// system is block-triangular in that order, so it is singular exactly when a pivot or the core is.
template <class R>
bool solve_square(const std::vector<Equation<R>>& eqs, Index m, std::vector<R>& U) {
  const std::size_t ne = eqs.size();
  std::vector<std::vector<std::size_t>> occurs(static_cast<std::size_t>(m));
  std::vector<std::size_t> open(ne), ready;
  for (std::size_t e = 0; e < ne; ++e) {
    open[e] = eqs[e].terms.size();
    for (const auto& [j, a] : eqs[e].terms) occurs[static_cast<std::size_t>(j)].push_back(e);
    if (open[e] == 1) ready.push_back(e);
  }
  std::vector<bool> known(static_cast<std::size_t>(m), false), used(ne, false);
  U.assign(static_cast<std::size_t>(m), R(0));
  R D(1);
  // D (rhs - sum of the known terms of e): the right-hand side of e over D once its known unknowns are moved.
  const auto residual = [&](std::size_t e) {
    R t = mul(eqs[e].rhs, D);
    for (const auto& [j, a] : eqs[e].terms)
      if (known[static_cast<std::size_t>(j)]) t = sub(t, mul(a, U[static_cast<std::size_t>(j)]));
    return t;
  };
  while (!ready.empty()) {
    const std::size_t e = ready.back();
    ready.pop_back();
    if (used[e] || open[e] != 1) continue;
    const auto& [i, coef] = *std::find_if(eqs[e].terms.begin(), eqs[e].terms.end(),
                                          [&](const auto& t) { return !known[static_cast<std::size_t>(t.first)]; });
    // coef u_i = t / D: u_i = t / (coef D); with coef = g a, t = g t', a > 0: U_i = t' over the denominator D a.
    R t = residual(e);
    used[e] = true;
    known[static_cast<std::size_t>(i)] = true;
    if (sign(t) != 0) {
      const R g = exact::ring::gcd(coef, t);
      R a = exact::ring::divexact(coef, g);
      t = exact::ring::divexact(t, g);
      if (sign(a) < 0) a = sub(R(0), a), t = sub(R(0), t);
      if (!(a == R(1))) {
        for (Index j = 0; j < m; ++j)
          if (known[static_cast<std::size_t>(j)])
            U[static_cast<std::size_t>(j)] = mul(U[static_cast<std::size_t>(j)], a);
        D = mul(D, a);
      }
      U[static_cast<std::size_t>(i)] = t;
    }
    for (std::size_t e2 : occurs[static_cast<std::size_t>(i)])
      if (!used[e2] && --open[e2] == 1) ready.push_back(e2);
  }
  // The core: the open unknowns (column c of M) and the unused equations (rows of M = [A_core | residual]).
  std::vector<Index> column(static_cast<std::size_t>(m), -1);
  Index k = 0;
  for (Index j = 0; j < m; ++j)
    if (!known[static_cast<std::size_t>(j)]) column[static_cast<std::size_t>(j)] = k++;
  if (k == 0) return true;  // every equation was used (as many as unknowns)
  Index rows = 0;
  for (std::size_t e = 0; e < ne; ++e) rows += used[e] ? 0 : 1;
  if (rows != k) return false;
  exact::IntMatrix<R> M(k, k + 1);
  Index r = 0;
  for (std::size_t e = 0; e < ne; ++e) {
    if (used[e]) continue;
    R* row = M.row(r++);
    for (const auto& [j, a] : eqs[e].terms)
      if (!known[static_cast<std::size_t>(j)]) row[column[static_cast<std::size_t>(j)]] = a;
    row[k] = residual(e);
  }
  std::vector<R> N(static_cast<std::size_t>(k));
  R d;
  if (M.solve(N.data(), d) != exact::SolutionKind::kUnique) return false;
  // D u = N / d on the core (d > 0): U d over the common denominator D d.
  for (Index j = 0; j < m; ++j) {
    R& u = U[static_cast<std::size_t>(j)];
    u = known[static_cast<std::size_t>(j)] ? mul(u, d)
                                           : N[static_cast<std::size_t>(column[static_cast<std::size_t>(j)])];
  }
  return true;
}

}  // namespace

template <class R>
std::optional<FarkasVector> basis_farkas(const exact::IntegerSystem<R>& s, const Vec<double>& y_approx,
                                         const std::vector<Index>& basis, const std::vector<bool>& zero) {
  // Phase 1 ends with duals y, B^T y = c_B (cost 1 on artificials), and reports f = -y: f^T A_v = 0 for every
  // structural v of the basis, and f_i = -sign(b_i) w_i for the artificial n + i of row i, where w_i = 1, or
  // the power of two the float simplex scaled row i by. Those entries are taken from y_approx, rounded to
  // signed powers of two; in the rows of s (row i times L_i) they read L_i f'_i = f_i.
  const Index m = s.m;
  if (y_approx.size() != m) return std::nullopt;
  if (static_cast<Index>(basis.size()) != m) return std::nullopt;
  std::vector<Equation<R>> eqs(static_cast<std::size_t>(m));  // one per basis column, unknowns f'
  for (Index r = 0; r < m; ++r) {
    Equation<R>& eq = eqs[static_cast<std::size_t>(r)];
    const Index v = basis[static_cast<std::size_t>(r)];
    if (v < 0 || v >= s.n + m) return std::nullopt;
    if (v < s.n) {
      for (Index i = 0; i < m; ++i)
        if (sign(s.a(i, v)) != 0) eq.terms.push_back({i, s.a(i, v)});
      eq.rhs = R(0);
    } else {
      const Index i = v - s.n;
      const double f = y_approx(i);
      if (f == 0 || !std::isfinite(f)) return std::nullopt;
      const int e = static_cast<int>(std::lround(std::log2(std::abs(f))));  // |f_i| = 2^e
      if (e < -62 || e > 62) return std::nullopt;
      const R power(std::int64_t(1) << (e < 0 ? -e : e));
      const R& L = s.row_scale[static_cast<std::size_t>(i)];
      eq.terms.push_back({i, e < 0 ? mul(L, power) : L});
      eq.rhs = e < 0 ? R(f < 0 ? -1 : 1) : (f < 0 ? sub(R(0), power) : power);
    }
  }
  std::vector<R> F;
  if (!solve_square(eqs, m, F)) return std::nullopt;
  return checked_farkas(s, F, zero);  // F is a positive multiple of f'
}

template <class R>
std::optional<FarkasVector> rounded_farkas(const exact::IntegerSystem<R>& s, const Vec<double>& y_approx,
                                           const std::vector<bool>& zero) {
  // A positive multiple of a Farkas vector is one: scaled to max-norm 1 before rounding, so that a float
  // vector of tiny entries (rows equilibrated by the float simplex) does not round to 0.
  std::vector<double> ys(static_cast<std::size_t>(s.m));
  double norm = 0;
  for (Index i = 0; i < s.m; ++i) {
    ys[static_cast<std::size_t>(i)] = y_approx(i) / to_double(s.row_scale[static_cast<std::size_t>(i)]);
    norm = std::max(norm, std::abs(ys[static_cast<std::size_t>(i)]));
  }
  if (!(norm > 0) || !std::isfinite(norm)) return std::nullopt;
  for (double& v : ys) v /= norm;
  std::vector<R> Y;
  R E;
  if (!exact::reconstruct_vector(ys, Y, E)) return std::nullopt;
  return checked_farkas(s, Y, zero);
}

#define CONTACTCERT_FARKAS_ROUNDING_INSTANTIATE(R)                                                           \
  template std::optional<FarkasVector> basis_farkas<R>(const exact::IntegerSystem<R>&, const Vec<double>&,   \
                                                       const std::vector<Index>&, const std::vector<bool>&); \
  template std::optional<FarkasVector> rounded_farkas<R>(const exact::IntegerSystem<R>&, const Vec<double>&, \
                                                         const std::vector<bool>&);
CONTACTCERT_FARKAS_ROUNDING_INSTANTIATE(Int128)
CONTACTCERT_FARKAS_ROUNDING_INSTANTIATE(Z)
#undef CONTACTCERT_FARKAS_ROUNDING_INSTANTIATE

}  // namespace contactcert::solvers::ucp
