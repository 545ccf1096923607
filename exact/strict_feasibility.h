// Strict feasibility of { x : A x = b, x_j >= 0 (j not free), x_j > 0 (j in S) }, decided by one LP
// (maximise t subject to x_j >= t on S, t <= 1), with Motzkin's transposition theorem as the proof of
// a "no": a vector y with
//     (y^T A)_j >= 0 on non-free columns, (y^T A)_j = 0 on free columns, y^T b <= 0, and
//     y^T b < 0  or  (y^T A)_j > 0 for some j in S.
// (If x were feasible, y^T b = y^T A x >= 0, and > 0 in the second case: a contradiction.)
#pragma once

#include <vector>

#include "exact/arith.h"
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

enum class StrictStatus { kFeasible, kInfeasible };

template <class T>
struct StrictFeasibility {
  StrictStatus status = StrictStatus::kInfeasible;
  Vec<T> x;        ///< kFeasible: a point of the system
  Vec<T> motzkin;  ///< kInfeasible: the certificate y described above
  long lps = 0;    ///< LPs solved (1)
};

/// Decides strict feasibility with one LP. For T = Q, `arith` chooses the exact or the verified LP
/// (kFloat is treated as kVerified); for T = double the float simplex is used.
template <class T>
StrictFeasibility<T> strict_feasibility(const StrictSystem<T>& system, Arith arith = Arith::kVerified);

/// Exact check of a Motzkin certificate for the system (trusts nothing but the numbers).
bool verify_motzkin(const StrictSystem<Q>& system, const Vec<Q>& y);
/// Exact check that x satisfies the system.
bool verify_strict_point(const StrictSystem<Q>& system, const Vec<Q>& x);

extern template StrictFeasibility<double> strict_feasibility<double>(const StrictSystem<double>&, Arith);
extern template StrictFeasibility<Q> strict_feasibility<Q>(const StrictSystem<Q>&, Arith);

}  // namespace contactcert::exact
