// Two-phase primal simplex for  min c^T x  s.t.  A x = b, x >= 0 (free variables allowed), written once over
// T (double or Q). Anti-cycling by Bland's rule (after a run of degenerate pivots, or always), so it
// terminates on degenerate problems. Returns the optimal basis, a certificate (Farkas vector or ray) and, on
// request (LpOptions::duals), the optimal duals.
#pragma once

#include "exact/input_error.h"
#include "exact/lp_problem.h"
#include "exact/simplex_tableau.h"

namespace contactcert::exact {

/// Solves the LP by the two-phase simplex in T; see LpResult for the meaning and sign conventions of the
/// result. decided_by = kFloat for double, kExact for Q. Throws BudgetExceeded after options.max_pivots
/// (check_pivot_budget); returns status kTimeLimit once options.deadline has passed (only a caller that sets a
/// deadline meets it, and it reports the time limit its own way).
template <class T>
LpResult<T> solve_lp(const LpProblem<T>& problem, const LpOptions& options = {});

/// The tableau of `basis` (columns of problem.A) if it is a primal feasible basis (x_B >= 0 on the non-free
/// basic columns); nullopt if the columns are singular, do not span, or x_B is infeasible.
template <class T>
std::optional<SimplexTableau<T>> feasible_tableau(const LpProblem<T>& problem, const std::vector<Eigen::Index>& basis);

/// Phase 2 of the simplex from a primal feasible tableau of problem.A x = problem.b (for example
/// feasible_tableau of a basis): a warm start. The pivots done are counted in the result; status
/// kPivotLimit if options.max_pivots pivots end without a verdict, kTimeLimit once options.deadline passed.
template <class T>
LpResult<T> solve_lp_from_tableau(const LpProblem<T>& problem, SimplexTableau<T> tableau,
                                  const LpOptions& options = {});

/// True if the tableau's basis is optimal for its objective row (set_objective): no non-basic column prices
/// out, i.e. d_j >= 0 on every non-basic column and d_j = 0 on free ones.
template <class T>
bool is_optimal_basis(const SimplexTableau<T>& tableau, const std::vector<bool>& is_free);

/// The verdict a primal feasible tableau's basis gives without a pivot, for problem's objective: kOptimal if
/// is_optimal_basis; kUnbounded (with the ray) if the column options.rule's pricing enters has no blocking
/// row; nullopt if a pivot is needed. The result is that of solve_lp_from_tableau with max_pivots = 0 whenever
/// that one is a verdict (pivots = 0).
template <class T>
std::optional<LpResult<T>> decide_at_basis(const LpProblem<T>& problem, SimplexTableau<T> tableau,
                                           const LpOptions& options = {});

/// The duals an optimal result carries when options.duals asks for them: some y with B^T y = c_B for the basis
/// columns B of problem.A (a dense solve), for a caller that needs them only after reading the verdict.
template <class T>
Vec<T> optimal_duals(const LpProblem<T>& problem, const std::vector<Eigen::Index>& basis);

/// Throws BudgetExceeded (the commands' budget, exit 3) if `status` is the pivot limit of `options`.
void check_pivot_budget(LpStatus status, const LpOptions& options);

/// Exact check of a Farkas certificate: (y^T A)_j >= 0 on non-free columns, == 0 on free ones, y^T b < 0.
bool verify_farkas(const LpProblem<Q>& problem, const Vec<Q>& y);
/// Exact check of an unbounded ray: A d = 0, d_j >= 0 on non-free columns, c^T d < 0.
bool verify_ray(const LpProblem<Q>& problem, const Vec<Q>& d);
/// Exact check of optimality: x primal feasible, y dual feasible (A^T y <= c, == on free), c^T x = b^T y.
bool verify_optimal(const LpProblem<Q>& problem, const Vec<Q>& x, const Vec<Q>& y);

extern template Vec<double> optimal_duals<double>(const LpProblem<double>&, const std::vector<Eigen::Index>&);
extern template Vec<Q> optimal_duals<Q>(const LpProblem<Q>&, const std::vector<Eigen::Index>&);
extern template LpResult<double> solve_lp<double>(const LpProblem<double>&, const LpOptions&);
extern template LpResult<Q> solve_lp<Q>(const LpProblem<Q>&, const LpOptions&);
extern template LpResult<double> solve_lp_from_tableau<double>(const LpProblem<double>&, SimplexTableau<double>,
                                                               const LpOptions&);
extern template LpResult<Q> solve_lp_from_tableau<Q>(const LpProblem<Q>&, SimplexTableau<Q>, const LpOptions&);
extern template std::optional<SimplexTableau<double>> feasible_tableau<double>(const LpProblem<double>&,
                                                                               const std::vector<Eigen::Index>&);
extern template std::optional<SimplexTableau<Q>> feasible_tableau<Q>(const LpProblem<Q>&,
                                                                     const std::vector<Eigen::Index>&);
extern template bool is_optimal_basis<double>(const SimplexTableau<double>&, const std::vector<bool>&);
extern template bool is_optimal_basis<Q>(const SimplexTableau<Q>&, const std::vector<bool>&);
extern template std::optional<LpResult<double>> decide_at_basis<double>(const LpProblem<double>&,
                                                                        SimplexTableau<double>, const LpOptions&);
extern template std::optional<LpResult<Q>> decide_at_basis<Q>(const LpProblem<Q>&, SimplexTableau<Q>, const LpOptions&);

}  // namespace contactcert::exact
