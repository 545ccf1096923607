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
#include "exact/integer_system.h"
#include "exact/lp_problem.h"
#include "exact/number.h"

namespace contactcert::exact {

/// The system A x = b with sign constraints: is_free[j] (no sign), strict[j] (x_j > 0), else x_j >= 0.
template <class T>
struct StrictSystem {
  Mat<T> A;
  Vec<T> b;
  std::vector<bool> is_free;  ///< empty = none free
  std::vector<bool> strict;   ///< empty = none strict; strict columns must not be free
};

/// One non-zero entry a_ij of a system matrix.
template <class T>
struct Entry {
  Eigen::Index row, col;
  T value;
};

/// The system A x = 0 with the sign constraints of StrictSystem, A given by its non-zero entries (in any
/// order, each (i, j) at most once): the verified solver scales its rows to integers straight from them.
template <class T>
struct SparseStrictSystem {
  Eigen::Index rows = 0, cols = 0;
  std::vector<Entry<T>> entries;
  std::vector<bool> is_free;  ///< empty or size cols
  std::vector<bool> strict;   ///< empty or size cols
  /// The dense system with right-hand side b (zero if b is empty).
  StrictSystem<T> dense(const Vec<T>& b = {}) const;
};

enum class StrictStatus { kFeasible, kInfeasible };

/// What StrictSolver::solve_rounded does with a float LP that finds the system infeasible while its rounded
/// certificate fails the exact check.
enum class FloatInfeasible { kVerifiedLp, kBasisCertificate };

template <class T>
struct StrictFeasibility {
  StrictStatus status = StrictStatus::kInfeasible;
  Vec<T> x;                                  ///< kFeasible: a point of the system
  Vec<T> motzkin;                            ///< kInfeasible: the certificate y described above
  long lps = 0;                              ///< LPs solved (1)
  DecidedBy decided_by = DecidedBy::kExact;  ///< kFloat for T = double; else how the exact answer was reached
  /// T = Q: the float LP's point or certificate, rounded to fractions, verified exactly (no rational LP).
  bool rounded_float_checked = false;
};

/// One system matrix with many right-hand sides: the LP above is set up once, and each solve(b) is one LP.
/// For T = Q with the verified arithmetic (every Arith but kExact), the rows of A are scaled to 64-bit integers
/// (row i times the lcm L_i of its denominators) and solve(b) first solves the LP in doubles on them, rounds
/// its point x or its certificate y to fractions and checks A x = b and the signs, or the Motzkin conditions on
/// y, exactly in 128-bit integers; only if that check fails is the LP solved again by the verified LP, on the
/// integer rows (in Q; a certificate y' of them gives y = L o y'). If a scaled entry does not fit in 64 bits,
/// the rows stay rational and every solve is the verified LP. Answers are exact.
template <class T>
class StrictSolver {
 public:
  /// Prepares the LP of `system` (its b is not used).
  explicit StrictSolver(const StrictSystem<T>& system, Arith arith = Arith::kVerified);
  /// The same from the non-zero entries of A (no dense rational matrix on the verified path).
  explicit StrictSolver(const SparseStrictSystem<T>& system, Arith arith = Arith::kVerified);
  /// Strict feasibility of the system with right-hand side b.
  StrictFeasibility<T> solve(const Vec<T>& b) const;
  /// The first step of solve(b) alone, for T = Q: the float LP's point or certificate, rounded and checked exactly;
  /// nullopt where solve(b) would go on to the verified or exact LP, and then *float_feasible tells whether the
  /// float LP found the system feasible (false if it ran out of pivots, or with no float step: kExact, or rows not
  /// in 64 bits). For a caller that needs an exact answer only when it is "infeasible". Other T: solve(b).
  /// *float_point, if given: the float LP's point of A x = b when it found one (else empty), a hint only.
  /// `infeasible`: where the float LP finds the system infeasible but its rounded certificate fails the check,
  /// kVerifiedLp gives nullopt (solve(b) solves the LP again in the verified LP), kBasisCertificate computes the
  /// certificate of the float LP's final basis exactly (Farkas, B^T y = 1 on the artificials, checked in integers)
  /// without a second LP: a valid certificate, not necessarily the one solve(b) gives (the assembly tree's choice).
  std::optional<StrictFeasibility<T>> solve_rounded(const Vec<T>& b, bool* float_feasible,
                                                    Vec<double>* float_point = nullptr,
                                                    FloatInfeasible infeasible = FloatInfeasible::kVerifiedLp) const;
  /// The rest of solve(b), for a caller whose solve_rounded(b) gave nullopt: the verified LP (for kExact or rows
  /// not in 64 bits, the exact or verified LP on the rows as given). Other T: solve(b).
  StrictFeasibility<T> solve_unrounded(const Vec<T>& b) const;

 private:
  template <class ForEachEntry>
  void prepare(ForEachEntry&& for_each_entry);

  Eigen::Index m_ = 0, n_ = 0;
  std::vector<bool> is_free_, strict_;
  Arith arith_;
  std::vector<Eigen::Index> strict_columns_;
  Mat<T> A_;                          ///< T = Q: the rows as given, unless integer_ holds them
  std::optional<IntegerLp> integer_;  ///< T = Q, verified: row i of A times integer_->row_scale[i], in 64 bits
  /// The LP in doubles (of the integer rows) if T = Q, else in T; b set per solve (for T = Q in place, by
  /// solve_rounded: a solver is not shared between threads).
  mutable LpProblem<std::conditional_t<NumberTraits<T>::is_exact, double, T>> hint_;
};

/// Decides strict feasibility with one LP: StrictSolver(system, arith).solve(system.b). For T = Q, `arith`
/// chooses the exact or the verified route (kFloat is treated as kVerified); for T = double the float simplex.
template <class T>
StrictFeasibility<T> strict_feasibility(const StrictSystem<T>& system, Arith arith = Arith::kVerified);
/// The same for A x = 0 given by its non-zero entries.
template <class T>
StrictFeasibility<T> strict_feasibility(const SparseStrictSystem<T>& system, Arith arith = Arith::kVerified);

/// Exact check of a Motzkin certificate for the system (trusts nothing but the numbers).
bool verify_motzkin(const StrictSystem<Q>& system, const Vec<Q>& y);
/// The same for the sparse system with right-hand side b, in time linear in its entries.
bool verify_motzkin(const SparseStrictSystem<Q>& system, const Vec<Q>& b, const Vec<Q>& y);
/// Exact check that x satisfies the system.
bool verify_strict_point(const StrictSystem<Q>& system, const Vec<Q>& x);

#define CONTACTCERT_STRICT_FEASIBILITY_EXTERN(T)                                             \
  extern template struct SparseStrictSystem<T>;                                              \
  extern template class StrictSolver<T>;                                                     \
  extern template StrictFeasibility<T> strict_feasibility<T>(const StrictSystem<T>&, Arith); \
  extern template StrictFeasibility<T> strict_feasibility<T>(const SparseStrictSystem<T>&, Arith);
CONTACTCERT_STRICT_FEASIBILITY_EXTERN(double)
CONTACTCERT_STRICT_FEASIBILITY_EXTERN(Q)
#undef CONTACTCERT_STRICT_FEASIBILITY_EXTERN

}  // namespace contactcert::exact
