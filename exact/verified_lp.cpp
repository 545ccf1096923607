#include "exact/verified_lp.h"

#include "exact/linalg.h"
#include "exact/rounded_certificate.h"
#include "exact/simplex.h"

namespace contactcert::exact {

namespace {

using Index = Eigen::Index;

/// Column v of [A | S], S = diag(sign b) (sign 0 counts as +1): the phase-1 matrix of solve_lp.
Vec<Q> phase1_column(const LpProblem<Q>& problem, Index v) {
  if (v < problem.cols()) return problem.A.col(v);
  Vec<Q> e = Vec<Q>::Zero(problem.rows());
  e(v - problem.cols()) = sgn(problem.b(v - problem.cols())) < 0 ? Q(-1) : Q(1);
  return e;
}

Mat<Q> basis_matrix(const LpProblem<Q>& problem, const std::vector<Index>& basis) {
  Mat<Q> B(problem.rows(), static_cast<Index>(basis.size()));
  for (size_t k = 0; k < basis.size(); ++k) B.col(static_cast<Index>(k)) = phase1_column(problem, basis[k]);
  return B;
}

bool valid_indices(const std::vector<Index>& basis, Index limit) {
  for (Index v : basis)
    if (v < 0 || v >= limit) return false;
  return true;
}

/// Some y with B^T y = c_B, or nullopt.
std::optional<Vec<Q>> basis_duals(const LpProblem<Q>& problem, const std::vector<Index>& basis, const Vec<Q>& cB) {
  return solve<Q>(Mat<Q>(basis_matrix(problem, basis).transpose()), cB);
}

LpResult<Q> from_scratch(const LpProblem<Q>& problem, const LpOptions& options) {
  LpOptions cold = options;
  cold.warm_basis.reset();
  return solve_lp<Q>(problem, cold);
}

/// Exact pivoting from the float basis: its tableau in Q, then phase 2 (no pivot if the basis is optimal in Q
/// too). From scratch if the basis is singular or not primal feasible in Q.
LpResult<Q> continue_exact(const LpProblem<Q>& problem, const std::vector<Index>& basis, const LpOptions& options) {
  std::optional<SimplexTableau<Q>> tab = SimplexTableau<Q>::from_basis(problem.A, problem.b, basis);
  bool feasible = tab.has_value();
  for (Index r = 0; feasible && r < tab->rows(); ++r)
    feasible = sgn(tab->rhs(r)) >= 0 || problem.free(tab->basis()[static_cast<size_t>(r)]);
  if (!feasible) return from_scratch(problem, options);
  LpResult<Q> res = solve_lp_from_tableau(problem, std::move(*tab), options);
  res.decided_by = res.pivots == 0 ? DecidedBy::kFloatBasisCheckedExactly : DecidedBy::kExactContinuedFromFloatBasis;
  return res;
}

}  // namespace

LpResult<Q> solve_lp_verified(const LpProblem<Q>& problem, const LpOptions& options) {
  const Index n = problem.cols();
  // The float simplex solves the integer-scaled LP when it fits in 64 bits (cheap to convert, and the
  // rounded certificate is then checked in integers).
  const std::optional<IntegerLp> ilp = integer_lp(problem);
  const LpResult<double> fl = solve_lp<double>(ilp ? ilp->to_double(problem.is_free) : to_double(problem), options);

  if (fl.status == LpStatus::kInfeasible) {
    // Farkas vector of the float phase-1 basis, recomputed exactly: y with B1^T y = 1 on artificials.
    if (!valid_indices(fl.basis, n + problem.rows())) return from_scratch(problem, options);
    Vec<Q> cB(static_cast<Index>(fl.basis.size()));
    for (size_t k = 0; k < fl.basis.size(); ++k) cB(static_cast<Index>(k)) = fl.basis[k] >= n ? Q(1) : Q(0);
    std::optional<Vec<Q>> y = basis_duals(problem, fl.basis, cB);
    if (y) {
      Vec<Q> farkas = -*y;
      if (verify_farkas(problem, farkas)) {
        LpResult<Q> res;
        res.status = LpStatus::kInfeasible;
        res.basis = fl.basis;
        res.farkas = std::move(farkas);
        res.decided_by = DecidedBy::kFloatBasisCheckedExactly;
        return res;
      }
    }
    return from_scratch(problem, options);
  }

  if (!valid_indices(fl.basis, n)) return from_scratch(problem, options);
  if (fl.status == LpStatus::kOptimal && ilp) {
    // Fast path: round the float optimum and check it exactly in integers.
    std::optional<OptimalCertificate> cert = round_and_check_optimal(problem, *ilp, fl.basis, fl.x, fl.duals);
    if (cert) {
      LpResult<Q> res;
      res.status = LpStatus::kOptimal;
      res.x = std::move(cert->x);
      res.duals = std::move(cert->y);
      res.value = cert->value;
      res.basis = fl.basis;
      res.decided_by = DecidedBy::kFloatBasisCheckedExactly;
      return res;
    }
  }
  return continue_exact(problem, fl.basis, options);
}

}  // namespace contactcert::exact
