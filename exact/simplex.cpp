#include "exact/simplex.h"

#include <string>

#include "exact/input_error.h"
#include "exact/interval_number.h"
#include "exact/linalg.h"
#include "exact/mpfr_number.h"

namespace contactcert::exact {

LpProblem<double> to_double(const LpProblem<Q>& problem) {
  return {to_double(problem.A), to_double(problem.b), to_double(problem.c), problem.is_free};
}

namespace {

using Index = Eigen::Index;

/// After this many consecutive degenerate pivots, Dantzig's rule gives way to Bland's rule until the
/// objective moves again (Bland's rule cannot cycle, so every degenerate run ends).
constexpr long kDegenerateRunBeforeBland = 50;
/// The same in floating point, where Bland's rule is only the fallback for a cycle: its smallest-index ties take
/// pivots just above the sign tolerance, which wreck a float tableau (on a wall of 16 boxes, phase 1 then wanders for
/// 10^5 pivots), while Dantzig's rule with the largest tied pivot ends its degenerate runs in practice. The float
/// answer is checked exactly afterwards, and options.max_pivots bounds a cycle.
constexpr long kFloatDegenerateRunBeforeBland = 1000;

enum class LoopEnd { kOptimal, kUnbounded, kPivotLimit, kTimeLimit };

struct LoopOutcome {
  LoopEnd end = LoopEnd::kOptimal;
  Index column = -1;  // entering column of the unbounded edge
  int direction = 1;  // +1: the column increases along the ray, -1: a free column decreases
};

bool column_is_free(const std::vector<bool>& is_free, Index j) {
  return !is_free.empty() && is_free[static_cast<size_t>(j)];
}

bool row_is_free(const std::vector<bool>& is_free, Index basic, Index n) {
  return basic < n && column_is_free(is_free, basic);
}

/// A column that prices out: reduced cost d_j < 0 (it increases), or d_j > 0 on a free column (it decreases).
struct Entering {
  Index column = -1;  // -1: none, the basis is optimal
  int direction = 1;
};

/// Pricing: Bland's rule takes the first column that prices out, Dantzig's the largest |d_j|.
template <class T>
Entering entering_column(const SimplexTableau<T>& tab, const std::vector<bool>& is_free, bool bland) {
  Entering e;
  T best_score = T(0);
  for (Index j = 0; j < tab.cols(); ++j) {
    if (tab.is_basic(j)) continue;
    const T& dj = tab.reduced_cost(j);
    const int sg = exact::sign(dj);
    if (sg == 0 || (sg > 0 && !column_is_free(is_free, j))) continue;
    if (bland) return {j, sg > 0 ? -1 : 1};
    const T score = sg > 0 ? dj : T(-dj);
    if (e.column < 0 || score > best_score) {
      e = {j, sg > 0 ? -1 : 1};
      best_score = score;
    }
  }
  return e;
}

/// Ratio test: the row whose basic variable blocks the entering column first (ties: the smallest basic index
/// under Bland's rule, else the better pivot); -1 if none blocks (an unbounded edge). Free basic variables never
/// leave.
template <class T>
Index blocking_row(const SimplexTableau<T>& tab, const std::vector<bool>& is_free, const Entering& e, bool bland) {
  Index r = -1;
  T best_ratio = T(0), best_entry = T(0);
  for (Index i = 0; i < tab.rows(); ++i) {
    const Index v = tab.basis()[static_cast<size_t>(i)];
    if (row_is_free(is_free, v, tab.cols())) continue;
    const T a = e.direction > 0 ? tab.entry(i, e.column) : T(-tab.entry(i, e.column));
    if (!exact::is_positive(a)) continue;
    const T ratio = tab.rhs(i) / a;
    bool take = r < 0;
    if (!take) {
      const int cmp = exact::sign(T(ratio - best_ratio));
      take = cmp < 0 || (cmp == 0 && (bland ? v < tab.basis()[static_cast<size_t>(r)]
                                            : NumberTraits<T>::better_pivot(a, best_entry)));
    }
    if (take) {
      r = i;
      best_ratio = ratio;
      best_entry = a;
    }
  }
  return r;
}

/// The primal simplex loop on the tableau's current objective: pivots until no column prices out
/// (optimal), an improving column has no blocking row (unbounded), options.max_pivots pivots are done
/// (counted in `pivots` over both phases) or options.deadline has passed (tested before each pivot).
template <class T>
LoopOutcome simplex_loop(SimplexTableau<T>& tab, const std::vector<bool>& is_free, const LpOptions& options,
                         long& pivots) {
  long degenerate_run = 0;
  for (;;) {
    const bool bland =
        options.rule == PivotRule::kBland ||
        degenerate_run >= (NumberTraits<T>::is_exact ? kDegenerateRunBeforeBland : kFloatDegenerateRunBeforeBland);
    const Entering e = entering_column(tab, is_free, bland);
    if (e.column < 0) return {LoopEnd::kOptimal, -1, 1};
    const Index r = blocking_row(tab, is_free, e, bland);
    if (r < 0) return {LoopEnd::kUnbounded, e.column, e.direction};
    if (pivots >= options.max_pivots) return {LoopEnd::kPivotLimit, -1, 1};
    if (options.deadline.expired()) return {LoopEnd::kTimeLimit, -1, 1};
    const bool degenerate = exact::is_zero(tab.rhs(r));
    tab.pivot(r, e.column);
    ++pivots;
    degenerate_run = degenerate ? degenerate_run + 1 : 0;
  }
}

/// Some y with B^T y = c_B for the basis columns of [A | S] (S = diag(sign b), artificial i = index n + i).
template <class T>
Vec<T> basis_duals(const Mat<T>& A, const Vec<T>& b, const std::vector<Index>& basis, const Vec<T>& cB) {
  const Index m = A.rows(), n = A.cols(), k = static_cast<Index>(basis.size());
  Mat<T> Bt = Mat<T>::Zero(k, m);
  for (Index r = 0; r < k; ++r) {
    const Index v = basis[static_cast<size_t>(r)];
    if (v < n)
      Bt.row(r) = A.col(v).transpose();
    else
      Bt(r, v - n) = exact::sign(b(v - n)) < 0 ? T(-1) : T(1);
  }
  std::optional<Vec<T>> y = solve<T>(Bt, cB);
  return y ? *y : Vec<T>(Vec<T>::Zero(m));
}

/// The result of a run that ended with `out`; an optimal one carries duals if options.duals asks for them.
template <class T>
LpResult<T> finish(const LpProblem<T>& problem, const SimplexTableau<T>& tab, const LoopOutcome& out, long pivots,
                   const LpOptions& options) {
  LpResult<T> res;
  res.decided_by = NumberTraits<T>::is_exact ? DecidedBy::kExact : DecidedBy::kFloat;
  res.pivots = pivots;
  res.basis = tab.basis();
  res.x = tab.primal();
  if (out.end == LoopEnd::kPivotLimit || out.end == LoopEnd::kTimeLimit) {
    res.status = out.end == LoopEnd::kPivotLimit ? LpStatus::kPivotLimit : LpStatus::kTimeLimit;
    return res;
  }
  if (out.end == LoopEnd::kUnbounded) {
    res.status = LpStatus::kUnbounded;
    res.unbounded_column = out.column;
    res.ray = Vec<T>::Zero(problem.cols());
    res.ray(out.column) = T(out.direction);
    for (Index r = 0; r < tab.rows(); ++r)
      res.ray(tab.basis()[static_cast<size_t>(r)]) = T(-out.direction) * tab.entry(r, out.column);
    res.value = tab.objective_value();
    return res;
  }
  res.status = LpStatus::kOptimal;
  res.value = tab.objective_value();
  if (!options.duals) return res;
  res.duals = optimal_duals(problem, res.basis);
  return res;
}

}  // namespace

template <class T>
Vec<T> optimal_duals(const LpProblem<T>& problem, const std::vector<Index>& basis) {
  const Vec<T> c = problem.objective();
  Vec<T> cB(static_cast<Index>(basis.size()));
  for (size_t r = 0; r < basis.size(); ++r) cB(static_cast<Index>(r)) = c(basis[r]);
  return basis_duals(problem.A, problem.b, basis, cB);
}

template <class T>
std::optional<SimplexTableau<T>> feasible_tableau(const LpProblem<T>& problem, const std::vector<Index>& basis) {
  std::optional<SimplexTableau<T>> tab = SimplexTableau<T>::from_basis(problem.A, problem.b, basis);
  for (Index r = 0; tab && r < tab->rows(); ++r)
    if (exact::is_negative(tab->rhs(r)) && !problem.free(tab->basis()[static_cast<size_t>(r)])) tab.reset();
  return tab;
}

template <class T>
LpResult<T> solve_lp_from_tableau(const LpProblem<T>& problem, SimplexTableau<T> tab, const LpOptions& options) {
  long pivots = 0;
  tab.set_objective(problem.objective());
  const LoopOutcome out = simplex_loop(tab, problem.is_free, options, pivots);
  return finish(problem, tab, out, pivots, options);
}

template <class T>
bool is_optimal_basis(const SimplexTableau<T>& tableau, const std::vector<bool>& is_free) {
  return entering_column(tableau, is_free, true).column < 0;
}

template <class T>
std::optional<LpResult<T>> decide_at_basis(const LpProblem<T>& problem, SimplexTableau<T> tab,
                                           const LpOptions& options) {
  tab.set_objective(problem.objective());
  // Every pricing rule enters a column exactly when one has an improving reduced cost: none means optimal.
  const bool bland = options.rule == PivotRule::kBland;
  const Entering e = entering_column(tab, problem.is_free, bland);
  if (e.column < 0) return finish(problem, tab, {LoopEnd::kOptimal, -1, 1}, 0, options);
  // Not optimal, yet decided if the entering column has no blocking row: its edge is an unbounded ray (the outcome
  // of phase 2 before its first pivot).
  if (blocking_row(tab, problem.is_free, e, bland) >= 0) return std::nullopt;
  return finish(problem, tab, {LoopEnd::kUnbounded, e.column, e.direction}, 0, options);
}

namespace {

/// The two-phase simplex; a pivot limit is the status kPivotLimit.
template <class T>
LpResult<T> run_simplex(const LpProblem<T>& problem, const LpOptions& options) {
  const Index n = problem.cols();
  if (options.warm_basis)
    if (std::optional<SimplexTableau<T>> tab = feasible_tableau(problem, *options.warm_basis))
      return solve_lp_from_tableau(problem, std::move(*tab), options);

  // Phase 1: min sum of artificials of A x + S a = b from the artificial basis.
  SimplexTableau<T> tab = SimplexTableau<T>::artificial_start(problem.A, problem.b);
  tab.set_objective(Vec<T>::Zero(n), T(1));
  long pivots = 0;
  const LoopOutcome phase1 = simplex_loop(tab, problem.is_free, options, pivots);
  if (phase1.end == LoopEnd::kPivotLimit || phase1.end == LoopEnd::kTimeLimit)
    return finish(problem, tab, phase1, pivots, options);
  if (exact::is_positive(tab.objective_value())) {
    LpResult<T> res;
    res.status = LpStatus::kInfeasible;
    res.decided_by = NumberTraits<T>::is_exact ? DecidedBy::kExact : DecidedBy::kFloat;
    res.pivots = pivots;
    res.basis = tab.basis();
    Vec<T> cB(tab.rows());
    for (Index r = 0; r < tab.rows(); ++r) cB(r) = tab.basis()[static_cast<size_t>(r)] >= n ? T(1) : T(0);
    res.farkas = -basis_duals(problem.A, problem.b, res.basis, cB);
    return res;
  }
  // Drive the artificials (all at level 0) out of the basis; rows where that is impossible are redundant (a pivot
  // on another row leaves their zeros zero: they are dropped together at the end).
  std::vector<Index> redundant;
  for (Index r = tab.rows() - 1; r >= 0; --r) {
    if (tab.basis()[static_cast<size_t>(r)] < n) continue;
    Index s = -1;
    for (Index j = 0; j < n && s < 0; ++j)
      if (!tab.is_basic(j) && !exact::is_zero(tab.entry(r, j))) s = j;
    if (s >= 0) {
      tab.pivot(r, s);
      ++pivots;
    } else {
      redundant.push_back(r);
    }
  }
  tab.remove_rows(redundant);
  // Phase 2.
  tab.set_objective(problem.objective());
  const LoopOutcome out = simplex_loop(tab, problem.is_free, options, pivots);
  return finish(problem, tab, out, pivots, options);
}

}  // namespace

template <class T>
LpResult<T> solve_lp(const LpProblem<T>& problem, const LpOptions& options) {
  LpResult<T> res = run_simplex(problem, options);
  check_pivot_budget(res.status, options);
  return res;
}

void check_pivot_budget(LpStatus status, const LpOptions& options) {
  if (status == LpStatus::kPivotLimit)
    throw BudgetExceeded("simplex pivot budget exceeded", std::to_string(options.max_pivots) + " pivots");
}

bool verify_farkas(const LpProblem<Q>& problem, const Vec<Q>& y) {
  if (y.size() != problem.rows()) return false;
  const Vec<Q> yA = problem.A.transpose() * y;
  for (Index j = 0; j < problem.cols(); ++j) {
    const int s = sgn(yA(j));
    if (problem.free(j) ? s != 0 : s < 0) return false;
  }
  return sgn(Q(problem.b.dot(y))) < 0;
}

bool verify_ray(const LpProblem<Q>& problem, const Vec<Q>& d) {
  if (d.size() != problem.cols()) return false;
  const Vec<Q> Ad = problem.A * d;
  for (Index i = 0; i < problem.rows(); ++i)
    if (sgn(Ad(i)) != 0) return false;
  for (Index j = 0; j < problem.cols(); ++j)
    if (!problem.free(j) && sgn(d(j)) < 0) return false;
  return sgn(Q(problem.objective().dot(d))) < 0;
}

bool verify_optimal(const LpProblem<Q>& problem, const Vec<Q>& x, const Vec<Q>& y) {
  if (x.size() != problem.cols() || y.size() != problem.rows()) return false;
  const Vec<Q> Ax = problem.A * x;
  for (Index i = 0; i < problem.rows(); ++i)
    if (Ax(i) != problem.b(i)) return false;
  const Vec<Q> c = problem.objective();
  const Vec<Q> yA = problem.A.transpose() * y;
  for (Index j = 0; j < problem.cols(); ++j) {
    if (problem.free(j) ? yA(j) != c(j) : (sgn(x(j)) < 0 || yA(j) > c(j))) return false;
  }
  return Q(c.dot(x)) == Q(problem.b.dot(y));
}

template LpResult<double> solve_lp<double>(const LpProblem<double>&, const LpOptions&);
template LpResult<Q> solve_lp<Q>(const LpProblem<Q>&, const LpOptions&);
template LpResult<double> solve_lp_from_tableau<double>(const LpProblem<double>&, SimplexTableau<double>,
                                                        const LpOptions&);
template LpResult<Q> solve_lp_from_tableau<Q>(const LpProblem<Q>&, SimplexTableau<Q>, const LpOptions&);
template std::optional<SimplexTableau<double>> feasible_tableau<double>(const LpProblem<double>&,
                                                                        const std::vector<Index>&);
template std::optional<SimplexTableau<Q>> feasible_tableau<Q>(const LpProblem<Q>&, const std::vector<Index>&);
template bool is_optimal_basis<double>(const SimplexTableau<double>&, const std::vector<bool>&);
template bool is_optimal_basis<Q>(const SimplexTableau<Q>&, const std::vector<bool>&);
template std::optional<LpResult<double>> decide_at_basis<double>(const LpProblem<double>&, SimplexTableau<double>,
                                                                 const LpOptions&);
template std::optional<LpResult<Q>> decide_at_basis<Q>(const LpProblem<Q>&, SimplexTableau<Q>, const LpOptions&);
template Vec<double> optimal_duals<double>(const LpProblem<double>&, const std::vector<Index>&);
template Vec<Q> optimal_duals<Q>(const LpProblem<Q>&, const std::vector<Index>&);
template Vec<Mpfr> optimal_duals<Mpfr>(const LpProblem<Mpfr>&, const std::vector<Index>&);
template Vec<Interval> optimal_duals<Interval>(const LpProblem<Interval>&, const std::vector<Index>&);
template LpResult<Mpfr> solve_lp<Mpfr>(const LpProblem<Mpfr>&, const LpOptions&);
template LpResult<Mpfr> solve_lp_from_tableau<Mpfr>(const LpProblem<Mpfr>&, SimplexTableau<Mpfr>, const LpOptions&);
template LpResult<Interval> solve_lp<Interval>(const LpProblem<Interval>&, const LpOptions&);
template LpResult<Interval> solve_lp_from_tableau<Interval>(const LpProblem<Interval>&, SimplexTableau<Interval>,
                                                            const LpOptions&);

}  // namespace contactcert::exact
