// Dense linear algebra over a field T (double, Q, MPFR floats or intervals), written once on reduced row echelon
// form: rank, null spaces, solving and inversion. Q's echelon form is computed in integers (exact/int_matrix.h), a
// float field's by Gauss-Jordan elimination in T. Instantiated in linalg.cpp.
#pragma once

#include <optional>
#include <vector>

#include "exact/number.h"

namespace contactcert::exact {

/// Reduced row echelon form R of A, with the pivot column of each non-zero row.
template <class T>
struct Rref {
  Mat<T> R;
  std::vector<Eigen::Index> pivots;  ///< pivots[k] = column of the leading 1 of row k
  Eigen::Index rank() const { return static_cast<Eigen::Index>(pivots.size()); }
};

/// Gauss-Jordan elimination of A to reduced row echelon form.
template <class T>
Rref<T> rref(const Mat<T>& A);

/// rank(A).
template <class T>
Eigen::Index rank(const Mat<T>& A);

/// A matrix N whose columns are a basis of {x : A x = 0} (n x (n - rank)).
template <class T>
Mat<T> null_space(const Mat<T>& A);

/// A matrix Z whose rows are a basis of {z : z A = 0} ((m - rank) x m): the left null space.
template <class T>
Mat<T> left_null_space(const Mat<T>& A);

/// Some x with A x = b, or nullopt if the system is inconsistent.
template <class T>
std::optional<Vec<T>> solve(const Mat<T>& A, const Vec<T>& b);

/// A^-1 for square non-singular A, or nullopt if A is singular.
template <class T>
std::optional<Mat<T>> inverse(const Mat<T>& A);

/// Explicit instantiation declarations for one number type (also used by exact/mpfr_number.h and
/// exact/interval_number.h).
#define CONTACTCERT_LINALG_EXTERN(T)                                            \
  extern template Rref<T> rref<T>(const Mat<T>&);                               \
  extern template Eigen::Index rank<T>(const Mat<T>&);                          \
  extern template Mat<T> null_space<T>(const Mat<T>&);                          \
  extern template Mat<T> left_null_space<T>(const Mat<T>&);                     \
  extern template std::optional<Vec<T>> solve<T>(const Mat<T>&, const Vec<T>&); \
  extern template std::optional<Mat<T>> inverse<T>(const Mat<T>&);
CONTACTCERT_LINALG_EXTERN(double)
CONTACTCERT_LINALG_EXTERN(Q)

}  // namespace contactcert::exact
