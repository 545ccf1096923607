// Strict feasibility of { x : A x = b, x_j >= 0 (j not free), x_j > 0 (j in S) }, decided by one LP
// (maximise t subject to x_j >= t on S, t <= 1), with Motzkin's transposition theorem as the proof of
// a "no": a vector y with
//     (y^T A)_j >= 0 on non-free columns, (y^T A)_j = 0 on free columns, y^T b <= 0, and
//     y^T b < 0  or  (y^T A)_j > 0 for some j in S.
// (If x were feasible, y^T b = y^T A x >= 0, and > 0 in the second case: a contradiction.)
#pragma once

#include <optional>
#include <type_traits>
#include <vector>

#include "exact/arith.h"
#include "exact/lp_problem.h"
#include "exact/number.h"
#include "exact/rounded_certificate.h"

namespace contactcert::exact {

/// The system A x = b with sign constraints: is_free[j] (no sign), strict[j] (x_j > 0), else x_j >= 0.
template <class T>
struct StrictSystem {
  Mat<T> A;
  Vec<T> b;
  std::vector<bool> is_free;  ///< empty = none free
  std::vector<bool> strict;   ///< empty = none strict; strict columns must not be free
};

enum class StrictStatus { kFeasible, kInfeasible };

template <class T>
struct StrictFeasibility {
  StrictStatus status = StrictStatus::kInfeasible;
  Vec<T> x;        ///< kFeasible: a point of the system
  Vec<T> motzkin;  ///< kInfeasible: the certificate y described above
  long lps = 0;    ///< LPs solved (1)
  DecidedBy decided_by = DecidedBy::kExact;  ///< kFloat for T = double; else how the exact answer was reached
  /// T = Q: the float LP's point or certificate, rounded to fractions, verified exactly (no rational LP).
  bool rounded_float_checked = false;
};

/// One system matrix with many right-hand sides: the LP above is set up once, and each solve(b) is one LP.
/// For T = Q with the verified arithmetic (every Arith but kExact), solve(b) first solves the LP in doubles
/// on the rows of A scaled to 64-bit integers, rounds its point x or its certificate y to fractions and
/// checks A x = b and the signs, or the Motzkin conditions on y, exactly in 128-bit integers; only if that
/// check fails (or an integer overflows) is the LP solved again by the verified LP. Answers are exact.
template <class T>
class StrictSolver {
 public:
  /// Prepares the LP of `system` (its b is not used).
  explicit StrictSolver(const StrictSystem<T>& system, Arith arith = Arith::kVerified);
  /// Strict feasibility of the system with right-hand side b.
  StrictFeasibility<T> solve(const Vec<T>& b) const;
  const StrictSystem<T>& system() const { return system_; }

 private:
  StrictSystem<T> system_;
  Arith arith_;
  std::vector<Eigen::Index> strict_columns_;
  std::optional<IntegerLp> integer_;  ///< T = Q, verified: row i of A times integer_->row_scale[i], in 64 bits
  /// The LP in doubles (of the integer rows) if T = Q, else in T; b set per solve.
  LpProblem<std::conditional_t<NumberTraits<T>::is_exact, double, T>> hint_;
};

/// Decides strict feasibility with one LP: StrictSolver(system, arith).solve(system.b). For T = Q, `arith`
/// chooses the exact or the verified route (kFloat is treated as kVerified); for T = double the float simplex.
template <class T>
StrictFeasibility<T> strict_feasibility(const StrictSystem<T>& system, Arith arith = Arith::kVerified);

/// Exact check of a Motzkin certificate for the system (trusts nothing but the numbers).
bool verify_motzkin(const StrictSystem<Q>& system, const Vec<Q>& y);
/// Exact check that x satisfies the system.
bool verify_strict_point(const StrictSystem<Q>& system, const Vec<Q>& x);

extern template class StrictSolver<double>;
extern template class StrictSolver<Q>;
extern template StrictFeasibility<double> strict_feasibility<double>(const StrictSystem<double>&, Arith);
extern template StrictFeasibility<Q> strict_feasibility<Q>(const StrictSystem<Q>&, Arith);

}  // namespace contactcert::exact
