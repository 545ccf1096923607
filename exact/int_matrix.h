// The one integer matrix: a dense matrix over a ring R of exact/fraction_free.h, eliminated without fractions (the
// model is Normaliz's Matrix<Integer>): row echelon form with primitive rows, rank, kernel, make-primitive, and the
// unique solution of a system by Bareiss's elimination (with a sparse front end for square systems). R = std::int64_t,
// Int128 (overflow-checked: throw RingOverflow so that with_exact_ring restarts in Z) or Z; the echelon form also runs
// in the float rings (double, MPFR floats, intervals). Row-major, on the stack up to 64 entries (the UCP's systems are
// that small and solved by the thousand). Its sparse form, SparseIntMatrix (compressed rows), holds the rows that are
// mostly zero (the UCP's X and Y, the contact Jacobians). Rational rows are held as integer rows with one scale per row
// (row i = integer row i / scale_i: IntegerSystem, RationalRows). The rows of field matrices become ring rows by
// to_ring_rows and field rows again by to_field_rows: the rows and rays of the double description are IntMatrix
// rows (double_description.h). Instantiated in int_matrix.cpp.
#pragma once

#include <algorithm>
#include <boost/container/small_vector.hpp>
#include <cassert>
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
  bool operator==(const IntMatrix&) const = default;
  /// Keeps the first `rows` rows if there are more, appends zero rows if there are fewer.
  void resize_rows(Index rows) {
    rows_ = rows;
    entries_.resize(static_cast<std::size_t>(rows * cols_), R(0));
  }
  /// Appends the row v[0..cols).
  void append_row(const R* v) {
    entries_.insert(entries_.end(), v, v + cols_);
    ++rows_;
  }
  /// Removes row i; the rows below it move up by one.
  void erase_row(Index i) {
    std::move(row(i + 1), row(rows_), row(i));
    resize_rows(rows_ - 1);
  }
  /// Exchanges rows i and j.
  void swap_rows(Index i, Index j) { std::swap_ranges(row(i), row(i) + cols_, row(j)); }
  /// The rows which[0], which[1], ... in that order.
  IntMatrix select_rows(const std::vector<Index>& which) const {
    IntMatrix out(0, cols_);
    out.entries_.reserve(which.size() * static_cast<std::size_t>(cols_));
    for (Index i : which) out.append_row(row(i));
    return out;
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

/// A sparse matrix over an exact ring R in compressed rows: the non-zero entries of row i are value(t) in column
/// col(t) for t in [begin(i), end(i)), columns ascending. Built row by row: add_row(), then push() its entries.
template <class R>
class SparseIntMatrix {
 public:
  using Index = Eigen::Index;

  SparseIntMatrix() = default;
  /// No rows, `cols` columns.
  explicit SparseIntMatrix(Index cols) : cols_(cols) {}
  /// The non-zero entries of a dense matrix, each mapped by to(entry) (e.g. Int128 -> Z).
  template <class S, class To>
  static SparseIntMatrix nonzeros(const IntMatrix<S>& M, To to) {
    SparseIntMatrix out(M.cols());
    for (Index i = 0; i < M.rows(); ++i) {
      out.add_row();
      for (Index j = 0; j < M.cols(); ++j)
        if (ring::sign(M(i, j)) != 0) out.push(j, to(M(i, j)));
    }
    return out;
  }

  Index rows() const { return static_cast<Index>(start_.size()) - 1; }
  Index cols() const { return cols_; }
  Index begin(Index i) const { return start_[static_cast<std::size_t>(i)]; }
  Index end(Index i) const { return start_[static_cast<std::size_t>(i + 1)]; }
  Index col(Index t) const { return col_[static_cast<std::size_t>(t)]; }
  const R& value(Index t) const { return value_[static_cast<std::size_t>(t)]; }
  R& value(Index t) { return value_[static_cast<std::size_t>(t)]; }
  /// The values of row i, contiguous.
  R* values(Index i) { return value_.data() + begin(i); }

  /// Appends an empty row.
  void add_row() { start_.push_back(start_.back()); }
  /// Appends the entry v in column c to the last row (c after its columns so far).
  void push(Index c, R v) {
    col_.push_back(c);
    value_.push_back(std::move(v));
    ++start_.back();
  }
  /// The same matrix, dense.
  IntMatrix<R> dense() const {
    IntMatrix<R> M(rows(), cols_);
    for (Index i = 0; i < rows(); ++i)
      for (Index t = begin(i); t < end(i); ++t) M(i, col(t)) = value(t);
    return M;
  }

 private:
  Index cols_ = 0;
  boost::container::small_vector<Index, 64> start_{0}, col_;
  boost::container::small_vector<R, 64> value_;
};

/// An integer matrix in the narrowest exact ring that holds it (the exact model matrices of the wrench cone paper):
/// an IntMatrix<std::int64_t> when every entry fits, an IntMatrix<Z> otherwise, as with_exact_ring made it. Reading a
/// Z-held matrix in std::int64_t throws RingOverflow, so that with_exact_ring restarts in Z.
class FittedIntMatrix {
 public:
  using Index = Eigen::Index;

  FittedIntMatrix() = default;
  explicit FittedIntMatrix(IntMatrix<std::int64_t> M) : fixed_(std::move(M)) {}
  explicit FittedIntMatrix(IntMatrix<Z> M) : wide_(std::move(M)), is_wide_(true) {}

  Index rows() const { return is_wide_ ? wide_.rows() : fixed_.rows(); }
  Index cols() const { return is_wide_ ? wide_.cols() : fixed_.cols(); }
  bool is_wide() const { return is_wide_; }
  void get(Index i, Index j, std::int64_t& out) const {
    if (is_wide_) throw RingOverflow{};
    out = fixed_(i, j);
  }
  void get(Index i, Index j, Z& out) const {
    if (is_wide_)
      out = wide_(i, j);
    else
      out = static_cast<long>(fixed_(i, j));
  }
  /// The same matrix over Q.
  Mat<Q> to_field() const {
    Mat<Q> M(rows(), cols());
    Z x;
    for (Index i = 0; i < rows(); ++i)
      for (Index j = 0; j < cols(); ++j) {
        get(i, j, x);
        M(i, j) = Q(x);
      }
    return M;
  }

 private:
  IntMatrix<std::int64_t> fixed_;
  IntMatrix<Z> wide_;
  bool is_wide_ = false;
};

namespace ring {
/// Entry (i, j) of a matrix over the ring: a FittedIntMatrix (exact rings; a float matrix: float_ring.h).
template <class R>
void get(const FittedIntMatrix& M, Eigen::Index i, Eigen::Index j, R& out) {
  M.get(i, j, out);
}

/// The rows [A_1 | A_2 | ...] of field matrices with equal row counts (Eigen expressions over the same
/// field T, e.g. [P | K]) as ring rows: row i is the positive multiple of the field row that to_ring gives
/// (primitive integers for Q, unit max-norm rows for a float T; a zero row stays zero).
template <class R, class D0, class... Ds>
IntMatrix<R> to_ring_rows(const Eigen::MatrixBase<D0>& A0, const Eigen::MatrixBase<Ds>&... more) {
  using T = typename D0::Scalar;
  static_assert((std::is_same_v<T, typename Ds::Scalar> && ...), "to_ring_rows: blocks over different fields");
  const Eigen::Index m = A0.rows(), w = (A0.cols() + ... + more.cols());
  assert(((more.rows() == m) && ...));
  IntMatrix<R> rows(m, w);
  std::vector<T> buf(static_cast<std::size_t>(w));
  for (Eigen::Index i = 0; i < m; ++i) {
    std::size_t at = 0;
    auto append = [&](const auto& B) {
      for (Eigen::Index j = 0; j < B.cols(); ++j) buf[at++] = B(i, j);
    };
    append(A0);
    (append(more), ...);
    to_ring(buf.data(), w, rows.row(i));
  }
  return rows;
}

/// Columns [first, first + cols) of ring rows as a matrix over the field T, entry by entry (to_field): the
/// inverse of to_ring_rows up to the positive factor of each row. No rows give a 0 x cols matrix.
template <class T, class R>
Mat<T> to_field_rows(const IntMatrix<R>& rows, Eigen::Index cols, Eigen::Index first = 0) {
  Mat<T> M(rows.rows(), cols);
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    const R* row = rows.row(i);
    for (Eigen::Index j = 0; j < cols; ++j) to_field(row[first + j], M(i, j));
  }
  return M;
}

}  // namespace ring

/// One equation of a sparse system: sum over terms (j, a) of a u_j = rhs.
template <class R>
struct SparseEquation {
  std::vector<std::pair<Eigen::Index, R>> terms;
  R rhs;
};

/// How solve_sparse_square solves its core: fraction-free elimination (IntMatrix::solve), or for R = Z and a core of
/// at least kLiftedCoreFrom unknowns Dixon's p-adic lifting (padic_solve.h: k^3 word operations, not k^3 on growing
/// integers), elimination deciding where it gives up. Both give the same u; U and D may differ by a common factor.
enum class CoreSolve { kFractionFree, kLifted };
inline constexpr Eigen::Index kLiftedCoreFrom = 16;

/// The unique solution u = U / D (D > 0) of the square system `eqs` in m unknowns (m equations, each a list of terms
/// with non-zero coefficients, at most one per unknown); kRankDeficient if it is singular (U, D unspecified). The
/// equations with one open unknown fix it first, over a common denominator, and it is substituted into the rest,
/// repeatedly; what is left, a core, goes to IntMatrix::solve. The matrix is block-triangular in that order, so it is
/// singular exactly when the core is. Exact rings only.
template <class R>
SolutionKind solve_sparse_square(const std::vector<SparseEquation<R>>& eqs, Eigen::Index m, std::vector<R>& U, R& D,
                                 CoreSolve core = CoreSolve::kFractionFree);

extern template class IntMatrix<std::int64_t>;
extern template class IntMatrix<Int128>;
extern template class IntMatrix<Z>;
extern template class SparseIntMatrix<std::int64_t>;
extern template class SparseIntMatrix<Int128>;
extern template class SparseIntMatrix<Z>;
extern template SolutionKind solve_sparse_square<std::int64_t>(const std::vector<SparseEquation<std::int64_t>>&,
                                                               Eigen::Index, std::vector<std::int64_t>&, std::int64_t&,
                                                               CoreSolve);
extern template SolutionKind solve_sparse_square<Int128>(const std::vector<SparseEquation<Int128>>&, Eigen::Index,
                                                         std::vector<Int128>&, Int128&, CoreSolve);
extern template SolutionKind solve_sparse_square<Z>(const std::vector<SparseEquation<Z>>&, Eigen::Index,
                                                    std::vector<Z>&, Z&, CoreSolve);
extern template void IntMatrix<double>::make_primitive();
extern template std::vector<Eigen::Index> IntMatrix<double>::echelon(Eigen::Index, Eigen::Index, Eigen::Index);

}  // namespace contactcert::exact
