#include "tests/reference/cdd_lp.h"

#include <mutex>
#include <stdexcept>

#include <cddlib/setoper.h>
#include <cddlib/cdd.h>

namespace contactcert::reference {
namespace {

using exact::LpProblem;
using exact::LpStatus;
using exact::Q;
using Index = Eigen::Index;

void init_cdd_lp() {
  static std::once_flag once;
  std::call_once(once, [] { dd_set_global_constants(); });
}

/// H-representation: rows [b | -A] in the linearity set (b - A x = 0), rows [0 | e_j] for x_j >= 0.
CddLpResult solve(const LpProblem<Q>& problem, bool with_objective) {
  init_cdd_lp();
  const Index m = problem.rows(), n = problem.cols();
  Index nonneg = 0;
  for (Index j = 0; j < n; ++j) nonneg += problem.free(j) ? 0 : 1;
  dd_MatrixPtr M = dd_CreateMatrix(m + nonneg, n + 1);
  M->representation = dd_Inequality;
  M->numbtype = dd_Rational;
  for (Index i = 0; i < m; ++i) {
    dd_set(M->matrix[i][0], problem.b(i).get_mpq_t());
    for (Index j = 0; j < n; ++j) {
      const Q v = -problem.A(i, j);
      dd_set(M->matrix[i][j + 1], v.get_mpq_t());
    }
    set_addelem(M->linset, i + 1);
  }
  Index row = m;
  for (Index j = 0; j < n; ++j) {
    if (problem.free(j)) continue;
    for (Index k = 0; k <= n; ++k) dd_set_si(M->matrix[row][k], k == j + 1 ? 1 : 0);
    ++row;
  }
  M->objective = dd_LPmin;
  const exact::Vec<Q> c = problem.objective();
  dd_set_si(M->rowvec[0], 0);
  for (Index j = 0; j < n; ++j) {
    if (with_objective)
      dd_set(M->rowvec[j + 1], c(j).get_mpq_t());
    else
      dd_set_si(M->rowvec[j + 1], 0);
  }
  dd_ErrorType err = dd_NoError;
  dd_LPPtr lp = dd_Matrix2LP(M, &err);
  if (err != dd_NoError || lp == nullptr) {
    dd_FreeMatrix(M);
    throw std::runtime_error("cddlib: dd_Matrix2LP failed");
  }
  dd_LPSolve(lp, dd_DualSimplex, &err);
  CddLpResult res;
  const dd_LPStatusType status = err == dd_NoError ? lp->LPS : dd_LPSundecided;
  switch (status) {
    case dd_Optimal:
      res.status = LpStatus::kOptimal;
      res.value = Q(lp->optvalue);
      break;
    case dd_Inconsistent:
    case dd_StrucInconsistent:
      res.status = LpStatus::kInfeasible;
      break;
    case dd_DualInconsistent:
    case dd_StrucDualInconsistent:
    case dd_Unbounded:
      res.status = LpStatus::kUnbounded;
      break;
    default:
      dd_FreeLPData(lp);
      dd_FreeMatrix(M);
      throw std::runtime_error("cddlib: LP undecided");
  }
  dd_FreeLPData(lp);
  dd_FreeMatrix(M);
  return res;
}

}  // namespace

CddLpResult cdd_solve_lp(const LpProblem<Q>& problem) {
  const CddLpResult feasibility = solve(problem, false);
  if (feasibility.status == LpStatus::kInfeasible) return feasibility;
  return solve(problem, true);
}

CddLpResult cdd_solve_lp_once(const LpProblem<Q>& problem) { return solve(problem, true); }

}  // namespace contactcert::reference
