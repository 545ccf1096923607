#include "exact/linalg.h"

#include <type_traits>

#include "exact/int_matrix.h"
#include "exact/interval_number.h"
#include "exact/mpfr_number.h"

namespace contactcert::exact {

namespace {

// Q: the rows of A as primitive integers (Int128, again in Z on overflow), brought to row echelon form without
// fractions (IntMatrix::echelon); row r of the reduced row echelon form is echelon row r over its pivot entry (the
// form is unique, so it is the one Gauss-Jordan elimination in Q reaches).
Rref<Q> rref_in_integers(const Mat<Q>& A) {
  return with_exact_ring<Q, Int128>([&]<class R>() {
    IntMatrix<R> E = IntMatrix<R>::primitive_rows(A.rows(), A.cols(),
                                                  [&](Eigen::Index i, Eigen::Index j) -> const Q& { return A(i, j); });
    Rref<Q> out{Mat<Q>(A.rows(), A.cols()), E.echelon()};  // (a default rational is 0)
    for (Eigen::Index r = 0; r < out.rank(); ++r) {
      const R& pivot = E(r, out.pivots[static_cast<std::size_t>(r)]);
      for (Eigen::Index j = 0; j < A.cols(); ++j)
        if (ring::sign(E(r, j)) != 0) ring::to_rational(E(r, j), pivot, out.R(r, j));
    }
    return out;
  });
}

// A float field: Gauss-Jordan elimination with the pivots of NumberTraits<T> and its sign tolerance, on a row-major
// copy (row operations run along contiguous rows) that updates, in doubles, only the pivot row's non-zero columns
// (x - f * 0 = x).
template <class T>
Rref<T> rref_in_field(const Mat<T>& A) {
  using RowMajor = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  RowMajor R = A;
  std::vector<Eigen::Index> pivots;
  const Eigen::Index m = R.rows(), n = R.cols();
  std::vector<Eigen::Index> nz;  // the non-zero columns > col of the pivot row
  Eigen::Index row = 0;
  for (Eigen::Index col = 0; col < n && row < m; ++col) {
    Eigen::Index p = -1;
    for (Eigen::Index i = row; i < m; ++i)
      if (!exact::is_zero(R(i, col)) && (p < 0 || NumberTraits<T>::better_pivot(R(i, col), R(p, col)))) p = i;
    if (p < 0) {
      for (Eigen::Index i = row; i < m; ++i) R(i, col) = T(0);  // below tolerance: treat as zero
      continue;
    }
    R.row(p).swap(R.row(row));
    const T inv = T(1) / R(row, col);
    nz.clear();
    for (Eigen::Index j = col + 1; j < n; ++j) {
      R(row, j) *= inv;
      if (!std::is_floating_point_v<T> || R(row, j) != T(0)) nz.push_back(j);  // (intervals and MPFR: all)
    }
    R(row, col) = T(1);
    for (Eigen::Index i = 0; i < m; ++i) {
      if (i == row || exact::is_negligible(R(i, col))) continue;
      const T f = R(i, col);
      for (const Eigen::Index j : nz) R(i, j) -= f * R(row, j);
      R(i, col) = T(0);
    }
    pivots.push_back(col);
    ++row;
  }
  return {Mat<T>(R), std::move(pivots)};
}

}  // namespace

template <class T>
Rref<T> rref(const Mat<T>& A) {
  if constexpr (std::is_same_v<T, Q>)
    return rref_in_integers(A);
  else
    return rref_in_field(A);
}

template <class T>
Eigen::Index rank(const Mat<T>& A) {
  return rref(A).rank();
}

template <class T>
Mat<T> null_space(const Mat<T>& A) {
  const Rref<T> E = rref(A);
  const Eigen::Index n = A.cols();
  std::vector<bool> is_pivot(static_cast<size_t>(n), false);
  for (auto p : E.pivots) is_pivot[static_cast<size_t>(p)] = true;
  Mat<T> N = Mat<T>::Zero(n, n - E.rank());
  Eigen::Index k = 0;
  // One basis vector per free column f: x_f = 1, x_pivot(r) = -R(r, f).
  for (Eigen::Index f = 0; f < n; ++f) {
    if (is_pivot[static_cast<size_t>(f)]) continue;
    N(f, k) = T(1);
    for (Eigen::Index r = 0; r < E.rank(); ++r) N(E.pivots[static_cast<size_t>(r)], k) = -E.R(r, f);
    ++k;
  }
  return N;
}

template <class T>
Mat<T> left_null_space(const Mat<T>& A) {
  return null_space<T>(A.transpose()).transpose();
}

template <class T>
std::optional<Vec<T>> solve(const Mat<T>& A, const Vec<T>& b) {
  Mat<T> Ab(A.rows(), A.cols() + 1);
  Ab << A, b;
  const Rref<T> E = rref(Ab);
  if (E.rank() > 0 && E.pivots.back() == A.cols()) return std::nullopt;  // 0 = 1 row
  Vec<T> x = Vec<T>::Zero(A.cols());
  for (Eigen::Index r = 0; r < E.rank(); ++r) x(E.pivots[static_cast<size_t>(r)]) = E.R(r, A.cols());
  return x;
}

template <class T>
std::optional<Mat<T>> inverse(const Mat<T>& A) {
  const Eigen::Index n = A.rows();
  if (A.cols() != n) return std::nullopt;
  Mat<T> AI(n, 2 * n);
  AI << A, Mat<T>::Identity(n, n);
  const Rref<T> E = rref(AI);
  if (E.rank() < n || E.pivots[static_cast<size_t>(n - 1)] != n - 1) return std::nullopt;
  return Mat<T>(E.R.rightCols(n));
}

#define CONTACTCERT_LINALG_INSTANTIATE(T)                                \
  template Rref<T> rref<T>(const Mat<T>&);                               \
  template Eigen::Index rank<T>(const Mat<T>&);                          \
  template Mat<T> null_space<T>(const Mat<T>&);                          \
  template Mat<T> left_null_space<T>(const Mat<T>&);                     \
  template std::optional<Vec<T>> solve<T>(const Mat<T>&, const Vec<T>&); \
  template std::optional<Mat<T>> inverse<T>(const Mat<T>&);
CONTACTCERT_LINALG_INSTANTIATE(double)
CONTACTCERT_LINALG_INSTANTIATE(Q)
CONTACTCERT_LINALG_INSTANTIATE(Mpfr)
CONTACTCERT_LINALG_INSTANTIATE(Interval)

}  // namespace contactcert::exact
