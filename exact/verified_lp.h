// The verified LP (SoPlex-style): a float simplex proposes a basis, exact arithmetic checks it, and the
// exact simplex continues from it only if the check fails. The answer is always exact. The proposer can be
// any rung of the precision ladder (doubles, intervals, MPFR floats; docs/precision.md).
#pragma once

#include <vector>

#include "exact/lp_problem.h"

namespace contactcert::exact {

/// Solves the LP exactly: solve_lp_ladder with the ladder {double, exact}. solve_lp<double> solves the LP
/// with rows scaled to 64-bit integers (integer_lp) and proposes a basis. Optimal: its x and duals are rounded
/// to fractions and checked exactly in integer arithmetic (round_and_check_optimal); otherwise the tableau of
/// the float basis is built in Q and checked (primal feasibility, then reduced costs or the ray). Infeasible:
/// the Farkas vector B^-T c_B of the float phase-1 basis is computed in Q and checked. If a check passes,
/// decided_by = kFloatBasisCheckedExactly (pivots = 0); if not, the exact simplex continues from the float
/// basis (kExactContinuedFromFloatBasis) or, if that basis is singular or primal infeasible in Q, starts from
/// scratch (kExact). The result satisfies the conventions of LpResult exactly. (On the integer fast path the
/// basis is known to be non-singular in floating point only; x, value and duals (with options.duals) are exact and
/// certified by A x = b, x >= 0, A^T y <= c, c^T x = b^T y.) Once options.deadline has passed, in a float rung or in
/// the exact simplex, the result is status kTimeLimit (no verdict); options.max_pivots throws BudgetExceeded.
LpResult<Q> solve_lp_verified(const LpProblem<Q>& problem, const LpOptions& options = {});

/// Solves the LP exactly by climbing `ladder` (its last rung must be kExact). Each float rung solves the
/// (integer-scaled) LP in its number type and proposes its final basis, which is checked exactly as in
/// solve_lp_verified; the first rung whose proposal checks out with no exact pivot decides (decided_by =
/// kFloatBasisCheckedExactly, proposed_by = that rung). An interval run that meets an uncertain sign proposes
/// nothing. The last float rung's basis is not rejected: the exact simplex continues from it as in
/// solve_lp_verified. adaptive_ladder() is the ladder of --arith adaptive.
LpResult<Q> solve_lp_ladder(const LpProblem<Q>& problem, const std::vector<Rung>& ladder,
                            const LpOptions& options = {});

}  // namespace contactcert::exact
