// Fraction-free Gauss-Jordan elimination (Bareiss) of an integer system A_S x_S = b: its unique solution as
// N / d with d a minor of A_S, every intermediate a minor (no fractions, no growth beyond products of two
// minors). Runs in Int128 (overflow-checked, throws RingOverflow) or Z: with_exact_ring<Q, Int128>.
#pragma once

#include <optional>
#include <vector>

#include "exact/integer_system.h"

namespace contactcert::exact {

/// How A_S x_S = b stands: one solution, or A_S without full column rank, or (full rank) no solution.
enum class SolutionKind { kUnique, kRankDeficient, kInconsistent };

/// The unique solution in integers, in place: M = [A_S | b] row-major m x (k + 1), overwritten by the
/// elimination. For kUnique, x_S = N / d with N = N[0..k-1] and d > 0 (a k x k minor of A_S up to sign and the
/// columns' contents); N and d are unspecified otherwise.
template <class R>
SolutionKind unique_solution(R* M, Eigen::Index m, Eigen::Index k, R* N, R& d);

/// The unique solution x_S of A_S x_S = b (A_S: the given columns of s, in order) as rationals; nullopt if A_S
/// does not have full column rank or the system is inconsistent.
template <class R>
std::optional<Vec<Q>> unique_solution(const IntegerSystem<R>& s, const std::vector<Eigen::Index>& columns);
/// The same over all columns of s.
template <class R>
std::optional<Vec<Q>> unique_solution(const IntegerSystem<R>& s);

#define CONTACTCERT_BAREISS_EXTERN(R)                                                                                  \
  extern template SolutionKind unique_solution<R>(R*, Eigen::Index, Eigen::Index, R*, R&);                             \
  extern template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&, const std::vector<Eigen::Index>&); \
  extern template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&);
CONTACTCERT_BAREISS_EXTERN(Int128)
CONTACTCERT_BAREISS_EXTERN(Z)
#undef CONTACTCERT_BAREISS_EXTERN

}  // namespace contactcert::exact
