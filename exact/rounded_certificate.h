// The fast exact check of the verified LP: round a float optimum (x, y) to rationals of small denominator
// and check primal feasibility, dual feasibility and complementary slackness exactly in 64/128-bit integer
// arithmetic (every operation overflow-checked). Rational LPs from contact geometry have small basis
// determinants, so this usually succeeds; when it does not, the caller falls back to exact pivoting.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/lp_problem.h"

namespace contactcert::exact {

/// An exact optimality certificate: A x = b, x >= 0 on non-free columns, A^T y <= c (== on free columns
/// and on the columns of the basis, which contain the support of x), hence c^T x = b^T y = value.
struct OptimalCertificate {
  Vec<Q> x;
  Vec<Q> y;
  Q value;
};

/// The LP with each row of [A | b] scaled to integers (row i times row_scale[i]) and c scaled to integers
/// (times objective_scale): same feasible set, same optimal x; row-major 64-bit data.
struct IntegerLp {
  Eigen::Index m = 0, n = 0;
  std::vector<std::int64_t> A, b, c;
  std::vector<std::int64_t> row_scale;
  std::int64_t objective_scale = 1;
  /// The scaled LP in doubles (what the float simplex of the verified path solves); is_free as given.
  LpProblem<double> to_double(const std::vector<bool>& is_free) const;
  /// The scaled LP in T, each integer mapped by from_int : int64 -> T (the other rungs of the ladder).
  template <class T, class F>
  LpProblem<T> convert(const std::vector<bool>& is_free, F from_int) const {
    LpProblem<T> p;
    p.A = Mat<T>(m, n);
    p.b = Vec<T>(m);
    p.c = Vec<T>(n);
    for (Eigen::Index i = 0; i < m; ++i) {
      for (Eigen::Index j = 0; j < n; ++j) p.A(i, j) = from_int(A[static_cast<size_t>(i * n + j)]);
      p.b(i) = from_int(b[static_cast<size_t>(i)]);
    }
    for (Eigen::Index j = 0; j < n; ++j) p.c(j) = from_int(c[static_cast<size_t>(j)]);
    p.is_free = is_free;
    return p;
  }
};

/// Rounds each entry of v to a nearby fraction (a continued-fraction convergent, denominator <= 2^30) and
/// writes them over their common denominator: v ~ out / scale. False if a rounding or a product overflows.
bool round_vector(const std::vector<double>& v, std::vector<std::int64_t>& out, std::int64_t& scale);

/// num / den in lowest terms (den > 0).
Q make_q(std::int64_t num, std::int64_t den);

/// The integer-scaled LP, or nullopt if a scaled entry does not fit in 64 bits.
std::optional<IntegerLp> integer_lp(const LpProblem<Q>& problem);

/// The rows of A x = b, each row of [A | b] multiplied by the lcm of its denominators (row_scale), as integers
/// of the ring R (Int128 or Z, see with_exact_ring<Q, Int128>).
template <class R>
struct IntegerSystem {
  Eigen::Index m = 0, n = 0;
  std::vector<R> A, b, row_scale;  ///< A row-major, m x n
};

template <class R>
IntegerSystem<R> integer_system(const Mat<Q>& A, const Vec<Q>& b);
/// The rows of A_S x_S = b for the given columns S of A (in order; row scales from those entries only).
template <class R>
IntegerSystem<R> integer_system(const Mat<Q>& A, const Vec<Q>& b, const std::vector<Eigen::Index>& columns);

/// The unique solution x_S of A_S x_S = b (A_S: the given columns of A, in order), by fraction-free
/// Gauss-Jordan (Bareiss) elimination in R after dividing out column and row contents: x_S = N / d with d a
/// minor of A_S. nullopt if A_S does not have full column rank or the system is inconsistent.
template <class R>
std::optional<Vec<Q>> unique_solution(const IntegerSystem<R>& s, const std::vector<Eigen::Index>& columns);
/// The same over all columns of s.
template <class R>
std::optional<Vec<Q>> unique_solution(const IntegerSystem<R>& s);

/// How A_S x_S = b stands: one solution, or A_S without full column rank, or (full rank) no solution.
enum class SolutionKind { kUnique, kRankDeficient, kInconsistent };

/// unique_solution in integers, in place: M = [A_S | b] row-major m x (k + 1), overwritten by the elimination.
/// For kUnique, x_S = N / d with N = N[0..k-1] and d > 0 (a k x k minor of A_S up to sign and the columns'
/// contents); N and d are unspecified otherwise.
template <class R>
SolutionKind unique_solution(R* M, Eigen::Index m, Eigen::Index k, R* N, R& d);

/// A point of the face {x >= 0 : A x = b, x_j = 0 where zero[j]} near x_approx: the entries off `zero`
/// rounded to fractions (continued-fraction convergents, denominators <= 2^30) over their common denominator
/// D, then A X = D b and X >= 0 checked in R. nullopt if a rounding or the check fails.
template <class R>
std::optional<Vec<Q>> rounded_point(const IntegerSystem<R>& s, const Vec<double>& x_approx,
                                    const std::vector<bool>& zero);

/// A Farkas vector y for the rows of A x = b, with the columns j where y^T A_j < 0.
struct FarkasVector {
  Vec<Q> y;
  std::vector<Eigen::Index> negative;
};

/// A Farkas vector y proving that face empty, near y_approx (a float one for the rows of A x = b):
/// y^T A_j >= 0 for every j off `zero` and y^T b < 0 (then no x >= 0 of the face has A x = b). The entries
/// y_approx_i / row_scale_i, scaled to max-norm 1, are rounded to fractions Y_i / E and checked against the
/// integer rows; the
/// result is y_i = row_scale_i Y_i, a positive multiple of the rounded vector, with its negative columns
/// (all in `zero`). nullopt if a rounding or the check fails.
template <class R>
std::optional<FarkasVector> rounded_farkas(const IntegerSystem<R>& s, const Vec<double>& y_approx,
                                           const std::vector<bool>& zero);

/// The Farkas vector y_approx of a float phase-1 basis (columns of A, and n + i for the artificial of row i),
/// recomputed exactly: f with f^T A_v = 0 on the basis' structural columns and, on its artificial rows, the
/// entries of y_approx rounded to signed powers of two (the artificials' costs on rows the float simplex
/// scaled by powers of two), solved by fraction-free elimination in R and checked as rounded_farkas checks.
/// nullopt if the basis is singular or f is not a Farkas vector for `zero`.
template <class R>
std::optional<FarkasVector> basis_farkas(const IntegerSystem<R>& s, const Vec<double>& y_approx,
                                         const std::vector<Eigen::Index>& basis, const std::vector<bool>& zero);

#define CONTACTCERT_INTEGER_SYSTEM_EXTERN(R)                                                                           \
  extern template IntegerSystem<R> integer_system<R>(const Mat<Q>&, const Vec<Q>&);                                    \
  extern template IntegerSystem<R> integer_system<R>(const Mat<Q>&, const Vec<Q>&, const std::vector<Eigen::Index>&);  \
  extern template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&);                                   \
  extern template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&, const std::vector<Eigen::Index>&); \
  extern template SolutionKind unique_solution<R>(R*, Eigen::Index, Eigen::Index, R*, R&);                             \
  extern template std::optional<Vec<Q>> rounded_point<R>(const IntegerSystem<R>&, const Vec<double>&,                  \
                                                         const std::vector<bool>&);                                    \
  extern template std::optional<FarkasVector> basis_farkas<R>(                                                         \
      const IntegerSystem<R>&, const Vec<double>&, const std::vector<Eigen::Index>&, const std::vector<bool>&);        \
  extern template std::optional<FarkasVector> rounded_farkas<R>(const IntegerSystem<R>&, const Vec<double>&,           \
                                                                const std::vector<bool>&);
CONTACTCERT_INTEGER_SYSTEM_EXTERN(Int128)
CONTACTCERT_INTEGER_SYSTEM_EXTERN(Z)
#undef CONTACTCERT_INTEGER_SYSTEM_EXTERN

/// Rounds x_approx (on the basis columns; zero elsewhere) and y_approx to nearby rationals and returns them if
/// they form an exact optimality certificate of `problem`; nullopt if rounding fails, an integer overflows or
/// a check fails. x_approx and y_approx are a float optimum of the scaled LP `ilp` (its duals, not problem's).
std::optional<OptimalCertificate> round_and_check_optimal(const LpProblem<Q>& problem, const IntegerLp& ilp,
                                                          const std::vector<Eigen::Index>& basis,
                                                          const Vec<double>& x_approx, const Vec<double>& y_approx);

}  // namespace contactcert::exact
