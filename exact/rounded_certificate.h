// The fast exact check of the verified LP: round a float optimum (x, y) to rationals of small denominator
// and check primal feasibility, dual feasibility and complementary slackness exactly in 64/128-bit integer
// arithmetic (every operation overflow-checked). Rational LPs from contact geometry have small basis
// determinants, so this usually succeeds; when it does not, the caller falls back to exact pivoting.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

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

/// A point of {x : A x = b, x >= 0 on non-free columns, x_j = 0 where zero[j]} (problem.c unused) near
/// x_approx: its entries rounded to fractions and checked exactly in 64/128-bit integers; nullopt if the
/// rounding, an integer overflow or a check fails.
std::optional<Vec<Q>> round_and_check_point(const LpProblem<Q>& problem, const Vec<double>& x_approx,
                                            const std::vector<bool>& zero);

/// Rounds x_approx (on the basis columns; zero elsewhere) and y_approx to nearby rationals and returns them if
/// they form an exact optimality certificate of `problem`; nullopt if rounding fails, an integer overflows or
/// a check fails. x_approx and y_approx are a float optimum of the scaled LP `ilp` (its duals, not problem's).
std::optional<OptimalCertificate> round_and_check_optimal(const LpProblem<Q>& problem, const IntegerLp& ilp,
                                                          const std::vector<Eigen::Index>& basis,
                                                          const Vec<double>& x_approx,
                                                          const Vec<double>& y_approx);

}  // namespace contactcert::exact
