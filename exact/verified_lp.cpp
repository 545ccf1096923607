#include "exact/verified_lp.h"

#include <cassert>

#include "exact/interval_number.h"
#include "exact/linalg.h"
#include "exact/mpfr_number.h"
#include "exact/rounded_check.h"
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

/// What a float rung proposes: its verdict, final basis and (optimal) approximate x and duals of the LP it
/// solved (the integer-scaled one when there is one; no duals without it).
struct Proposal {
  Rung rung;
  LpStatus status = LpStatus::kInfeasible;
  std::vector<Index> basis;
  Vec<double> x, duals;
};

template <class T>
Vec<double> approx(const Vec<T>& v) {
  Vec<double> d(v.size());
  for (Index i = 0; i < v.size(); ++i) d(i) = NumberTraits<T>::to_double(v(i));
  return d;
}

/// Solves the LP in T: the integer-scaled LP if there is one (its integers map to T by from_int), else the
/// LP with each rational mapped by from_q.
template <class T, class FromInt, class FromQ>
Proposal propose(Rung rung, const LpProblem<Q>& problem, const std::optional<IntegerLp>& ilp, const LpOptions& options,
                 FromInt from_int, FromQ from_q) {
  const LpProblem<T> lp = ilp ? ilp->convert<T>(problem.is_free, from_int) : convert_lp<T>(problem, from_q);
  LpOptions lp_options = options;
  lp_options.duals = ilp.has_value();  // the duals are read only by the integer check of an optimum (check)
  const LpResult<T> r = solve_lp<T>(lp, lp_options);
  return {rung, r.status, r.basis, approx(r.x), approx(r.duals)};
}

/// The proposal of one float rung, or nullopt if an interval run met an uncertain sign.
std::optional<Proposal> propose(Rung rung, const LpProblem<Q>& problem, const std::optional<IntegerLp>& ilp,
                                const LpOptions& options) {
  switch (rung.kind) {
    case Rung::Kind::kDouble:
      return propose<double>(
          rung, problem, ilp, options, [](std::int64_t v) { return static_cast<double>(v); },
          [](const Q& q) { return q.get_d(); });
    case Rung::Kind::kInterval:
      try {
        return propose<Interval>(
            rung, problem, ilp, options, [](std::int64_t v) { return to_interval(Q(static_cast<long>(v))); },
            [](const Q& q) { return to_interval(q); });
      } catch (const UncertainSign&) {
        return std::nullopt;
      }
    case Rung::Kind::kMpfr:
      return propose<Mpfr>(
          rung, problem, ilp, options, [&](std::int64_t v) { return to_mpfr(Q(static_cast<long>(v)), rung.bits); },
          [&](const Q& q) { return to_mpfr(q, rung.bits); });
    case Rung::Kind::kExact:
      break;
  }
  return std::nullopt;
}

/// The Farkas vector of a float phase-1 basis, recomputed exactly (y with B1^T y = 1 on artificials) and
/// checked: in the integer rows when there are some (basis_farkas_certificate), else in Q. nullopt if it does not
/// prove the LP infeasible.
std::optional<LpResult<Q>> check_infeasible(const LpProblem<Q>& problem, const std::optional<IntegerLp>& ilp,
                                            const std::vector<Index>& basis) {
  const Index n = problem.cols();
  if (!valid_indices(basis, n + problem.rows())) return std::nullopt;
  std::optional<Vec<Q>> integer_farkas;
  if (ilp) integer_farkas = basis_farkas_certificate(problem, *ilp, basis);
  Vec<Q> farkas;
  if (integer_farkas) {
    farkas = std::move(*integer_farkas);
  } else {
    Vec<Q> cB(static_cast<Index>(basis.size()));
    for (size_t k = 0; k < basis.size(); ++k) cB(static_cast<Index>(k)) = basis[k] >= n ? Q(1) : Q(0);
    std::optional<Vec<Q>> y = basis_duals(problem, basis, cB);
    if (!y) return std::nullopt;
    farkas = -*y;
    if (!verify_farkas(problem, farkas)) return std::nullopt;
  }
  LpResult<Q> res;
  res.status = LpStatus::kInfeasible;
  res.basis = basis;
  res.farkas = std::move(farkas);
  res.decided_by = DecidedBy::kFloatBasisCheckedExactly;
  return res;
}

/// Exact pivoting from a float basis: its tableau in Q, then phase 2 (no pivot if the basis is optimal in Q
/// too; kTimeLimit once options.deadline has passed). nullopt if the basis is singular or not primal feasible
/// in Q; throws BudgetExceeded after options.max_pivots (check_pivot_budget).
std::optional<LpResult<Q>> continue_exact(const LpProblem<Q>& problem, const std::vector<Index>& basis,
                                          const LpOptions& options) {
  std::optional<SimplexTableau<Q>> tab = feasible_tableau(problem, basis);
  if (!tab) return std::nullopt;
  LpResult<Q> res = solve_lp_from_tableau(problem, std::move(*tab), options);
  check_pivot_budget(res.status, options);
  res.decided_by = res.pivots == 0 ? DecidedBy::kFloatBasisCheckedExactly : DecidedBy::kExactContinuedFromFloatBasis;
  return res;
}

/// The float basis checked as it stands: optimal in Q, or with an unbounded edge in Q (decide_at_basis).
/// nullopt if it is singular, not primal feasible, or needs a pivot in Q.
std::optional<LpResult<Q>> check_basis(const LpProblem<Q>& problem, const std::vector<Index>& basis,
                                       const LpOptions& options) {
  std::optional<SimplexTableau<Q>> tab = feasible_tableau(problem, basis);
  if (!tab) return std::nullopt;
  std::optional<LpResult<Q>> res = decide_at_basis(problem, std::move(*tab), options);
  if (res) res->decided_by = DecidedBy::kFloatBasisCheckedExactly;
  return res;
}

/// The exact check of a proposal. `last`: the exact simplex may continue from the basis (any number of
/// pivots); otherwise the basis must check out as it is. nullopt if it does not.
std::optional<LpResult<Q>> check(const LpProblem<Q>& problem, const std::optional<IntegerLp>& ilp, const Proposal& p,
                                 bool last, const LpOptions& options) {
  if (p.status == LpStatus::kInfeasible) return check_infeasible(problem, ilp, p.basis);
  if (!valid_indices(p.basis, problem.cols())) return std::nullopt;
  if (p.status == LpStatus::kOptimal && ilp) {
    // Fast path: round the float optimum and check it exactly in integers.
    if (std::optional<OptimalCertificate> cert = round_and_check_optimal(problem, *ilp, p.basis, p.x, p.duals)) {
      LpResult<Q> res;
      res.status = LpStatus::kOptimal;
      res.x = std::move(cert->x);
      if (options.duals) res.duals = std::move(cert->y);
      res.value = cert->value;
      res.basis = p.basis;
      res.decided_by = DecidedBy::kFloatBasisCheckedExactly;
      return res;
    }
  }
  return last ? continue_exact(problem, p.basis, options) : check_basis(problem, p.basis, options);
}

}  // namespace

LpResult<Q> solve_lp_verified(const LpProblem<Q>& problem, const LpOptions& options) {
  static const std::vector<Rung> ladder{{Rung::Kind::kDouble, 0}, {Rung::Kind::kExact, 0}};
  return solve_lp_ladder(problem, ladder, options);
}

LpResult<Q> solve_lp_ladder(const LpProblem<Q>& problem, const std::vector<Rung>& ladder, const LpOptions& options) {
  assert(!ladder.empty() && ladder.back().kind == Rung::Kind::kExact);
  // The float rungs solve the integer-scaled LP when it fits in 64 bits (cheap to convert, and the rounded
  // certificate is then checked in integers).
  const std::optional<IntegerLp> ilp = integer_lp(problem);
  std::optional<Proposal> best;  // the last usable proposal: the exact simplex starts from it
  for (size_t k = 0; k + 1 < ladder.size(); ++k) {
    std::optional<Proposal> p = propose(ladder[k], problem, ilp, options);
    if (!p) continue;
    if (p->status == LpStatus::kTimeLimit) {  // the deadline passed inside a float rung: no verdict
      LpResult<Q> res;
      res.status = LpStatus::kTimeLimit;
      res.proposed_by = p->rung;
      return res;
    }
    const bool last = k + 2 == ladder.size();
    if (std::optional<LpResult<Q>> res = check(problem, ilp, *p, last, options)) {
      res->proposed_by = p->rung;
      return std::move(*res);
    }
    if (p->status != LpStatus::kInfeasible && valid_indices(p->basis, problem.cols())) best = std::move(p);
  }
  if (best && best->rung != ladder[ladder.size() - 2]) {
    // The last float rung gave nothing usable: continue from an earlier rung's basis.
    if (std::optional<LpResult<Q>> res = continue_exact(problem, best->basis, options)) {
      res->proposed_by = best->rung;
      return std::move(*res);
    }
  }
  return from_scratch(problem, options);
}

}  // namespace contactcert::exact
