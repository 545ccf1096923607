// cddlib's exact (GMP) LP solver as an independent reference for tests and benchmarks.
#pragma once

#include "exact/lp_problem.h"

namespace contactcert::reference {

struct CddLpResult {
  exact::LpStatus status = exact::LpStatus::kInfeasible;
  exact::Q value = 0;  ///< optimal value (kOptimal only)
};

/// Solves min c^T x, A x = b, x >= 0 (free columns allowed) with cddlib's GMP dd_LPSolve (dual simplex).
/// Feasibility is decided first (objective 0), so an infeasible and dual infeasible LP is kInfeasible.
CddLpResult cdd_solve_lp(const exact::LpProblem<exact::Q>& problem);

/// One dd_LPSolve of the LP as given (no separate feasibility solve): the benchmark peer.
CddLpResult cdd_solve_lp_once(const exact::LpProblem<exact::Q>& problem);

}  // namespace contactcert::reference
