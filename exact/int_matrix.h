// A dense matrix over a ring R of exact/fraction_free.h, eliminated without fractions (the model is Normaliz's
// Matrix<Integer>): row echelon form with primitive rows, rank, kernel, make-primitive, and the unique solution of a
// system by Bareiss's elimination (with a sparse front end for square systems). R = std::int64_t, Int128
// (overflow-checked: throw RingOverflow so that with_exact_ring restarts in Z) or Z; the echelon form also runs in the
// float rings (double, MPFR floats, intervals). Row-major, on the stack up to 64 entries (the UCP's systems are that
// small and solved by the thousand). Instantiated in int_matrix.cpp.
#pragma once

#include <boost/container/small_vector.hpp>
#include <cstdint>
#include <utility>
#include <vector>

#include "exact/fraction_free.h"

namespace contactcert::exact {

/// How A x = b stands: one solution, or A without full column rank, or (full column rank) no solution.
enum class SolutionKind { kUnique, kRankDeficient, kInconsistent };

template <class R>
class IntMatrix {
 public:
  using Index = Eigen::Index;

  IntMatrix() = default;
  /// The zero matrix.
  IntMatrix(Index rows, Index cols) : rows_(rows), cols_(cols), entries_(static_cast<std::size_t>(rows * cols), R(0)) {}
  /// The rows of a rational matrix (entry (i, j) = q(i, j)) in R, each row over the lcm of its denominators and
  /// then primitive: a positive multiple of the rational row, the same row space (exact rings only).
  template <class Get>
  static IntMatrix primitive_rows(Index rows, Index cols, Get q) {
    IntMatrix M(rows, cols);
    for (Index i = 0; i < rows; ++i)
      ring::to_common_denominator<R>(
          cols, [&](Index j) -> const Q& { return q(i, j); }, M.row(i));
    M.make_primitive();
    return M;
  }

  Index rows() const { return rows_; }
  Index cols() const { return cols_; }
  R& operator()(Index i, Index j) { return entries_[static_cast<std::size_t>(i * cols_ + j)]; }
  const R& operator()(Index i, Index j) const { return entries_[static_cast<std::size_t>(i * cols_ + j)]; }
  R* row(Index i) { return entries_.data() + i * cols_; }
  const R* row(Index i) const { return entries_.data() + i * cols_; }
  /// Keeps the first `rows` rows.
  void keep_rows(Index rows) {
    rows_ = rows;
    entries_.resize(static_cast<std::size_t>(rows * cols_));
  }

  /// Divides every row by the gcd of its entries (a float ring: ring::normalize), so that it is primitive; zero rows
  /// stay.
  void make_primitive();

  /// Fraction-free Gauss-Jordan elimination of the rows from `top` down in columns [first, last) (last < 0: to the
  /// end): row top + r becomes the r-th pivot row, zero in every other pivot column of those rows and in the rows
  /// below it; every row stays primitive (a positive multiple of the combination of rows that reduced row echelon
  /// form reaches). The rows below the last pivot row are zero in [first, last). Returns the pivot columns.
  std::vector<Index> echelon(Index top = 0, Index first = 0, Index last = -1);

  /// The rank.
  Index rank() const;

  /// The rows of a basis of {x : A x = 0}, each primitive: one per non-pivot column f of the echelon form, x_f > 0 and
  /// zero at the other non-pivot columns, f ascending (positive multiples of the basis read off reduced row echelon
  /// form). Exact rings only.
  IntMatrix kernel() const;

  /// For this matrix = [A | b] (m x (k + 1)): the unique solution x = N / d of A x = b, with d > 0 (a k x k minor of A
  /// up to the contents of A's columns), N = N[0..k-1]; N and d are unspecified unless kUnique. Bareiss's
  /// elimination in place (every intermediate a minor: no growth beyond a product of two). Exact rings only.
  SolutionKind solve(R* N, R& d);

 private:
  Index rows_ = 0, cols_ = 0;
  boost::container::small_vector<R, 64> entries_;
};

/// One equation of a sparse system: sum over terms (j, a) of a u_j = rhs.
template <class R>
struct SparseEquation {
  std::vector<std::pair<Eigen::Index, R>> terms;
  R rhs;
};

/// The unique solution u = U / D (D > 0) of the square system `eqs` in m unknowns (m equations, each a list of terms
/// with non-zero coefficients, at most one per unknown); kRankDeficient if it is singular (U, D unspecified). The
/// equations with one open unknown fix it first, over a common denominator, and it is substituted into the rest,
/// repeatedly; what is left, a core, goes to IntMatrix::solve. The matrix is block-triangular in that order, so it is
/// singular exactly when the core is. Exact rings only.
template <class R>
SolutionKind solve_sparse_square(const std::vector<SparseEquation<R>>& eqs, Eigen::Index m, std::vector<R>& U, R& D);

extern template class IntMatrix<std::int64_t>;
extern template class IntMatrix<Int128>;
extern template class IntMatrix<Z>;
extern template SolutionKind solve_sparse_square<std::int64_t>(const std::vector<SparseEquation<std::int64_t>>&,
                                                               Eigen::Index, std::vector<std::int64_t>&, std::int64_t&);
extern template SolutionKind solve_sparse_square<Int128>(const std::vector<SparseEquation<Int128>>&, Eigen::Index,
                                                         std::vector<Int128>&, Int128&);
extern template SolutionKind solve_sparse_square<Z>(const std::vector<SparseEquation<Z>>&, Eigen::Index,
                                                    std::vector<Z>&, Z&);
extern template void IntMatrix<double>::make_primitive();
extern template std::vector<Eigen::Index> IntMatrix<double>::echelon(Eigen::Index, Eigen::Index, Eigen::Index);

}  // namespace contactcert::exact
