// The rigid-body model of the wrench cone paper mapped into the contact frames (section 2.2):
// the Jacobian J (eq. 4), A = J^T M^-1 J and B = J^T M^-1 (eq. 6), C = [I  -A] (eqs. 7-8).
#pragma once

#include <type_traits>

#include "exact/int_matrix.h"
#include "exact/number.h"
#include "geometry/planar_scene.h"
#include "solvers/number_names.h"

namespace contactcert::solvers {

/// A matrix of the model over the ring of T: integers for the exact path (held in machine integers
/// when they fit, exact::FittedIntMatrix), T itself for the float types (double, MPFR, intervals).
template <class T>
using ModelMatrix = std::conditional_t<exact::NumberTraits<T>::is_exact, exact::FittedIntMatrix, Mat<T>>;

/// A model matrix as a matrix over T.
template <class T>
Mat<T> to_field(const ModelMatrix<T>& M) {
  if constexpr (exact::NumberTraits<T>::is_exact) {
    return M.to_field();
  } else {
    return M;
  }
}

/// The matrices of eqs. (4)-(8) for one scene with n fixels, over the ring of T.
template <class T>
struct ContactModel {
  ModelMatrix<T> J;  ///< 3 x 2n: columns n_1..n_n then t_1..t_n, as wrenches (f_x, f_y, torque about the com)
  ModelMatrix<T> A;  ///< 2n x 2n, A = J^T M^-1 J (eq. 6)
  ModelMatrix<T> B;  ///< 2n x 3,  B = J^T M^-1 (eq. 6)
  Eigen::Index fixels() const { return J.cols() / 2; }
  /// C = [I  -A] (eq. 8), 2n x 4n, over T; built on demand (cone_form reads A directly).
  Mat<T> C() const {
    const Eigen::Index n2 = A.rows();
    const Mat<T> a = to_field<T>(A);
    Mat<T> out = Mat<T>::Zero(n2, 2 * n2);
    for (Eigen::Index i = 0; i < n2; ++i) {
      out(i, i) = T(1);
      for (Eigen::Index j = 0; j < n2; ++j) out(i, n2 + j) = -a(i, j);
    }
    return out;
  }
};

/// The Jacobian J of eq. (4), exactly: column i is the wrench of a force n_i applied at p_i, column
/// n + i the same for t_i; torques about the centre of mass. Each frame (n_i, t_i) is first scaled by
/// a positive factor that makes n_i a primitive integer vector and both torques integers (the cones
/// do not change, SPEC section 3, and the exact arithmetic stays on small integers).
Mat<Q> jacobian(const geometry::PlanarScene& scene);

/// J, A, B, C for the scene, with M^-1 = diag(1, 1, m/I) scaled by the positive numerator of I/m
/// (only I/m matters and the cones are invariant under scaling M; with integer J, A and B are
/// integer matrices, computed and held in std::int64_t, or in Z if they outgrow it). For M = I
/// (I/m = 1) these are literally the paper's matrices. The float model
/// (T = double) uses unit normals and M^-1 = diag(1, 1, m/I) instead, to keep entries of order one.
template <class T>
ContactModel<T> contact_model(const geometry::PlanarScene& scene);

/// An exact number in T (identity for Q, else rounded: NumberTraits<T>::from_q).
template <class T>
T from_exact(const Q& x) {
  if constexpr (std::is_same_v<T, Q>) {
    return x;
  } else {
    return exact::NumberTraits<T>::from_q(x);
  }
}

/// An exact matrix in T (identity for Q, else rounded entry by entry).
template <class T>
Mat<T> from_exact(const Mat<Q>& M) {
  if constexpr (std::is_same_v<T, Q>) {
    return M;
  } else {
    return M.unaryExpr([](const Q& x) { return exact::NumberTraits<T>::from_q(x); });
  }
}

extern template ContactModel<double> contact_model<double>(const geometry::PlanarScene&);
extern template ContactModel<Q> contact_model<Q>(const geometry::PlanarScene&);

}  // namespace contactcert::solvers
