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
  for (Index i = 0; i < s.rows(); ++i)
    acc = add(acc, mul(s.b[static_cast<std::size_t>(i)], Y[static_cast<std::size_t>(i)]));
  if (sign(acc) >= 0) return std::nullopt;
  FarkasVector f;
  const std::vector<R> yA = exact::left_product(s, Y);
  for (Index j = 0; j < s.cols(); ++j) {
    if (sign(yA[static_cast<std::size_t>(j)]) >= 0) continue;
    if (!zero[static_cast<std::size_t>(j)]) return std::nullopt;
    f.negative.push_back(j);
  }
  f.y = Vec<Q>(s.rows());
  for (Index i = 0; i < s.rows(); ++i)
    f.y(i) = exact::ring::to_field<Q>(mul(s.row_scale[static_cast<std::size_t>(i)], Y[static_cast<std::size_t>(i)]));
  return f;
}

}  // namespace

template <class R>
std::optional<FarkasVector> basis_farkas(const exact::IntegerSystem<R>& s, const Vec<double>& y_approx,
                                         const std::vector<Index>& basis, const std::vector<bool>& zero) {
  // Phase 1 ends with duals y, B^T y = c_B (cost 1 on artificials), and reports f = -y: f^T A_v = 0 for every
  // structural v of the basis, and f_i = -sign(b_i) w_i for the artificial n + i of row i, where w_i = 1, or
  // the power of two the float simplex scaled row i by. Those entries are taken from y_approx, rounded to
  // signed powers of two; in the rows of s (row i times L_i) they read L_i f'_i = f_i. The system is sparse (X's
  // columns come from the sparse rows of P's left null space, an artificial's equation has one unknown): the
  // sparse solve fixes most unknowns without elimination.
  const Index m = s.rows(), n = s.cols();
  if (y_approx.size() != m) return std::nullopt;
  if (static_cast<Index>(basis.size()) != m) return std::nullopt;
  std::vector<exact::SparseEquation<R>> eqs(static_cast<std::size_t>(m));  // one per basis column, unknowns f'
  for (Index r = 0; r < m; ++r) {
    exact::SparseEquation<R>& eq = eqs[static_cast<std::size_t>(r)];
    const Index v = basis[static_cast<std::size_t>(r)];
    if (v < 0 || v >= n + m) return std::nullopt;
    if (v < n) {
      for (Index i = 0; i < m; ++i)
        if (sign(s.A(i, v)) != 0) eq.terms.push_back({i, s.A(i, v)});
      eq.rhs = R(0);
    } else {
      const Index i = v - n;
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
  R D;
  if (exact::solve_sparse_square(eqs, m, F, D) != exact::SolutionKind::kUnique) return std::nullopt;
  return checked_farkas(s, F, zero);  // F = D f', a positive multiple
}

template <class R>
std::optional<FarkasVector> rounded_farkas(const exact::IntegerSystem<R>& s, const Vec<double>& y_approx,
                                           const std::vector<bool>& zero) {
  // A positive multiple of a Farkas vector is one: scaled to max-norm 1 before rounding, so that a float
  // vector of tiny entries (rows equilibrated by the float simplex) does not round to 0.
  std::vector<double> ys(static_cast<std::size_t>(s.rows()));
  double norm = 0;
  for (Index i = 0; i < s.rows(); ++i) {
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
