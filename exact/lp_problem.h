// The linear program of contactcert and its result:  min c^T x  s.t.  A x = b,  x_j >= 0 unless is_free[j].
// Shared by the simplex (simplex.h), the verified LP (verified_lp.h) and adjacency (adjacent_vertices.h).
#pragma once

#include <optional>
#include <vector>

#include "exact/arith.h"
#include "exact/deadline.h"
#include "exact/number.h"

namespace contactcert::exact {

/// min c^T x  s.t.  A x = b,  x_j >= 0 for every j with !is_free[j] (is_free empty = no free variable).
template <class T>
struct LpProblem {
  Mat<T> A;
  Vec<T> b;
  Vec<T> c;                   ///< may be empty: feasibility problem (c = 0)
  std::vector<bool> is_free;  ///< empty or size A.cols()

  /// Number of equality rows m.
  Eigen::Index rows() const { return A.rows(); }
  /// Number of variables n.
  Eigen::Index cols() const { return A.cols(); }
  /// True if x_j has no sign constraint.
  bool free(Eigen::Index j) const { return !is_free.empty() && is_free[static_cast<size_t>(j)]; }
  /// The objective (zero vector if c is empty).
  Vec<T> objective() const { return c.size() == 0 ? Vec<T>(Vec<T>::Zero(A.cols())) : c; }
};

/// How an LP run ended: a verdict with its certificate, or a budget of LpOptions used up before one: the pivot
/// limit (max_pivots) or the deadline. These are outcomes, as HiGHS's kIterationLimit and kTimeLimit: the
/// caller decides whether that is a budget to report (solve_lp reports the pivot limit as BudgetExceeded).
enum class LpStatus { kOptimal, kInfeasible, kUnbounded, kPivotLimit, kTimeLimit };

/// Which path decided the result (verified_lp.h): the float simplex alone, the exact simplex from scratch,
/// the float basis checked exactly (no exact pivot), or exact pivots continued from the float basis.
enum class DecidedBy { kFloat, kExact, kFloatBasisCheckedExactly, kExactContinuedFromFloatBasis };

/// Pricing rule. Both terminate on degenerate problems: kDantzigThenBland prices by the most negative
/// reduced cost and switches to Bland's rule after a run of degenerate pivots until the objective moves.
enum class PivotRule { kDantzigThenBland, kBland };

struct LpOptions {
  /// Warm start: a basis of A (columns, |basis| = rank A) that is primal feasible. If it is singular or not
  /// primal feasible the solver starts from scratch (phase 1) instead.
  std::optional<std::vector<Eigen::Index>> warm_basis;
  /// Pivot budget (phase 1 + phase 2): the run ends with LpStatus::kPivotLimit when it is used up (solve_lp
  /// reports that as BudgetExceeded).
  long max_pivots = 1000000;
  PivotRule rule = PivotRule::kDantzigThenBland;
  /// Wall clock (a command's --time-limit), tested before each pivot: the run ends with LpStatus::kTimeLimit
  /// once it has passed.
  Deadline deadline;
  /// Compute the optimal duals y (LpResult::duals): a solve of B^T y = c_B after the last pivot. Off, an
  /// optimal result carries no duals (the UCP's face LPs read only x and the basis).
  bool duals = false;
};

/// Result with evidence. Sign conventions (checked exactly by verify_* in simplex.h):
/// - kOptimal:    x optimal, A x = b, x >= 0 on non-free columns; duals y (if options.duals, else empty) with
///                (A^T y)_j <= c_j on non-free columns, == c_j on free columns, and b^T y = c^T x = value. basis = the
///                optimal basis (columns of A, |basis| = rank A, basis[r] is basic in tableau row r).
/// - kInfeasible: farkas y with (y^T A)_j >= 0 on non-free columns, == 0 on free columns, and y^T b < 0
///                (so no x >= 0 has A x = b). basis = the final phase-1 basis of [A | S] with S = diag(sign b)
///                (sign 0 counts as +1): column index A.cols() + i is the artificial of row i.
/// - kUnbounded:  x a feasible vertex with its basis; ray d with A d = 0, d_j >= 0 on non-free columns and
///                c^T d < 0; unbounded_column = the non-basic column whose pivot found the ray (d of it is 1).
/// - kPivotLimit: no verdict after options.max_pivots pivots; basis and x are those of the last tableau.
/// - kTimeLimit:  no verdict when options.deadline passed; basis and x as for kPivotLimit.
template <class T>
struct LpResult {
  LpStatus status = LpStatus::kInfeasible;
  T value = T(0);
  Vec<T> x;
  std::vector<Eigen::Index> basis;
  Vec<T> duals;
  Vec<T> farkas;
  Vec<T> ray;
  Eigen::Index unbounded_column = -1;
  DecidedBy decided_by = DecidedBy::kExact;
  Rung proposed_by;  ///< the float rung whose basis was checked or continued from (solve_lp_ladder; else double)
  long pivots = 0;   ///< simplex pivots done in this number type (0 if a float basis checked out)
};

/// The problem in doubles (for the float path).
LpProblem<double> to_double(const LpProblem<Q>& problem);

/// The problem with every number mapped by f : Q -> T (the interval and MPFR paths).
template <class T, class F>
LpProblem<T> convert_lp(const LpProblem<Q>& problem, F f) {
  return {problem.A.unaryExpr(f), problem.b.unaryExpr(f), problem.c.unaryExpr(f), problem.is_free};
}

}  // namespace contactcert::exact
