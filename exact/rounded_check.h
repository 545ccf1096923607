// Round a float answer to fractions (rational reconstruction), then check it exactly in integers: the fast
// exact path of the verified LP and of strict feasibility. Rational LPs from contact geometry have small basis
// determinants, so this usually succeeds; when it does not, the caller falls back to exact pivoting.
#pragma once

#include <optional>
#include <vector>

#include "exact/integer_system.h"
#include "exact/rational_reconstruction.h"

namespace contactcert::exact {

/// A float vector reconstructed over its common denominator: x ~ X / D, D > 0.
template <class R>
struct RoundedVector {
  std::vector<R> X;
  R D;
};

/// The values x_S (for the columns S of s, in order) reconstructed, X / D, if A_S X = D rhs holds exactly in
/// the rows of s; nullopt if an entry has no reconstruction or an equation fails. Computed in R (Int128 throws
/// RingOverflow).
template <class R, class S>
std::optional<RoundedVector<R>> rounded_solution(const IntegerSystem<S>& s, const std::vector<S>& rhs,
                                                 const std::vector<Eigen::Index>& columns,
                                                 const std::vector<double>& values);

/// Y^T A for the rows A of s, in R: entry j is sum_i A_ij Y_i.
template <class R, class S>
std::vector<R> left_product(const IntegerSystem<S>& s, const std::vector<R>& Y);

#define CONTACTCERT_ROUNDED_CHECK_EXTERN(R, S)                                                                       \
  extern template std::optional<RoundedVector<R>> rounded_solution<R, S>(                                            \
      const IntegerSystem<S>&, const std::vector<S>&, const std::vector<Eigen::Index>&, const std::vector<double>&); \
  extern template std::vector<R> left_product<R, S>(const IntegerSystem<S>&, const std::vector<R>&);
CONTACTCERT_ROUNDED_CHECK_EXTERN(Int128, std::int64_t)
CONTACTCERT_ROUNDED_CHECK_EXTERN(Int128, Int128)
CONTACTCERT_ROUNDED_CHECK_EXTERN(Z, Z)
CONTACTCERT_ROUNDED_CHECK_EXTERN(Z, std::int64_t)
#undef CONTACTCERT_ROUNDED_CHECK_EXTERN

/// An exact optimality certificate: A x = b, x >= 0 on non-free columns, A^T y <= c (== on free columns
/// and on the columns of the basis, which contain the support of x), hence c^T x = b^T y = value.
struct OptimalCertificate {
  Vec<Q> x;
  Vec<Q> y;
  Q value;
};

/// Rounds x_approx (on the basis columns; zero elsewhere) and y_approx to nearby rationals and returns them if
/// they form an exact optimality certificate of `problem`; nullopt if rounding fails, a number outgrows 128
/// bits or a check fails. x_approx and y_approx are a float optimum of the scaled LP `ilp` (its duals, not
/// problem's).
std::optional<OptimalCertificate> round_and_check_optimal(const LpProblem<Q>& problem, const IntegerLp& ilp,
                                                          const std::vector<Eigen::Index>& basis,
                                                          const Vec<double>& x_approx, const Vec<double>& y_approx);

/// The Farkas vector y of a float phase-1 basis (columns of [A | S], S = diag(sign b)), computed from the basis
/// itself rather than rounded (its determinants may outgrow rational reconstruction): B^T y = 1 on artificial
/// columns, 0 on the others, solved fraction-free in the integer rows of `ilp` (solve_sparse_square, Int128 then Z),
/// returned if y^T A >= 0 (== 0 on free columns) and y^T b < 0; nullopt if the basis is singular, not square, or y is
/// no proof.
std::optional<Vec<Q>> basis_farkas_certificate(const LpProblem<Q>& problem, const IntegerLp& ilp,
                                               const std::vector<Eigen::Index>& basis);
/// The same for the LP of `ilp` itself (is_free: its free columns, empty = none). y_approx (empty or one entry per
/// row): the float LP's Farkas vector; y is then first solved on the rows where y_approx is not zero (the basis
/// equations there, chosen in doubles and solved exactly), far smaller than B when the contradiction is local, and
/// kept only if it meets every basis equation (then it is B^-T c_B: the same y).
std::optional<Vec<Q>> basis_farkas_certificate(const IntegerLp& ilp, const std::vector<bool>& is_free,
                                               const std::vector<Eigen::Index>& basis, const Vec<double>& y_approx);

/// A point of the face {x >= 0 : A x = b, x_j = 0 where zero[j]} near x_approx: the entries off `zero`
/// reconstructed over their common denominator D, then A X = D b and X >= 0 checked in R. nullopt if a
/// reconstruction or the check fails.
template <class R>
std::optional<Vec<Q>> rounded_point(const IntegerSystem<R>& s, const Vec<double>& x_approx,
                                    const std::vector<bool>& zero);

extern template std::optional<Vec<Q>> rounded_point<Int128>(const IntegerSystem<Int128>&, const Vec<double>&,
                                                            const std::vector<bool>&);
extern template std::optional<Vec<Q>> rounded_point<Z>(const IntegerSystem<Z>&, const Vec<double>&,
                                                       const std::vector<bool>&);

}  // namespace contactcert::exact
