// Rational data scaled to integers: each row of [A | b] times the lcm of its denominators (row_scale), the
// same solutions in integer arithmetic: the integer matrix exact::IntMatrix with one scale per row. Rational rows are
// held as RationalRows (sparse integer rows of exact::SparseIntMatrix over a denominator each, b as rationals: the
// UCP's X and Y), and integer_system is the one builder of the scaled system from them, for the verified LP
// (IntegerLp, 64 bits) and the exact integer checks (IntegerSystem<R>, R = Int128 or Z as with_exact_ring<Q, Int128>
// chooses).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "exact/int_matrix.h"
#include "exact/lp_problem.h"

namespace contactcert::exact {

/// The rows of [A | b] in integers: row i of A is the integer row A[i] over den[i] (den[i] > 0), b as rationals (one
/// per row).
struct RationalRows {
  SparseIntMatrix<Z> A;
  std::vector<Z> den;
  Vec<Q> b;
  Eigen::Index rows() const { return A.rows(); }
  Eigen::Index cols() const { return A.cols(); }
};

/// The rows of [A | b] as given in rationals: each row of A over its least common denominator (its non-zero
/// entries), b as it is.
RationalRows rational_rows(const Mat<Q>& A, const Vec<Q>& b);

/// The rows of A x = b, row i of [A | b] times row_scale[i] (the lcm of its denominators), as integers of R.
template <class R>
struct IntegerSystem {
  IntMatrix<R> A;
  std::vector<R> b, row_scale;
  Eigen::Index rows() const { return A.rows(); }
  Eigen::Index cols() const { return A.cols(); }
};

/// An LP as an IntegerSystem<std::int64_t> of its rows, with c scaled to integers (times objective_scale):
/// same feasible set, same optimal x.
struct IntegerLp : IntegerSystem<std::int64_t> {
  std::vector<std::int64_t> c;
  std::int64_t objective_scale = 1;
  /// The scaled LP in doubles (what the float simplex of the verified path solves); is_free as given.
  LpProblem<double> to_double(const std::vector<bool>& is_free) const;
  /// The scaled LP in T, each integer mapped by from_int : int64 -> T (the other rungs of the ladder).
  template <class T, class F>
  LpProblem<T> convert(const std::vector<bool>& is_free, F from_int) const {
    const Eigen::Index m = rows(), n = cols();
    LpProblem<T> p;
    p.A = Mat<T>(m, n);
    p.b = Vec<T>(m);
    p.c = Vec<T>(n);
    for (Eigen::Index j = 0; j < n; ++j)  // down the columns of p.A (column-major)
      for (Eigen::Index i = 0; i < m; ++i) p.A(i, j) = from_int(A(i, j));
    for (Eigen::Index i = 0; i < m; ++i) p.b(i) = from_int(b[static_cast<size_t>(i)]);
    for (Eigen::Index j = 0; j < n; ++j) p.c(j) = from_int(c[static_cast<size_t>(j)]);
    p.is_free = is_free;
    return p;
  }
};

/// The integer-scaled LP, or nullopt if a scaled entry does not fit in 64 bits.
std::optional<IntegerLp> integer_lp(const LpProblem<Q>& problem);

/// The rows of A x = b over R, each row of [A | b] times the lcm of its denominators (std::int64_t, Int128: throws
/// RingOverflow if a number does not fit).
template <class R>
IntegerSystem<R> integer_system(const RationalRows& P);

/// The unique solution x_S of A_S x_S = b (A_S: the given columns of s, in order) as rationals, by
/// IntMatrix::solve; nullopt if A_S does not have full column rank or the system is inconsistent.
template <class R>
std::optional<Vec<Q>> unique_solution(const IntegerSystem<R>& s, const std::vector<Eigen::Index>& columns);
/// The same over all columns of s.
template <class R>
std::optional<Vec<Q>> unique_solution(const IntegerSystem<R>& s);

#define CONTACTCERT_INTEGER_SYSTEM_EXTERN(R)                                                                           \
  extern template IntegerSystem<R> integer_system<R>(const RationalRows&);                                             \
  extern template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&, const std::vector<Eigen::Index>&); \
  extern template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&);
extern template IntegerSystem<std::int64_t> integer_system<std::int64_t>(const RationalRows&);
CONTACTCERT_INTEGER_SYSTEM_EXTERN(Int128)
CONTACTCERT_INTEGER_SYSTEM_EXTERN(Z)
#undef CONTACTCERT_INTEGER_SYSTEM_EXTERN

}  // namespace contactcert::exact
