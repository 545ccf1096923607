// The rigid-body model of the wrench cone paper mapped into the contact frames (section 2.2):
// the Jacobian J (eq. 4), A = J^T M^-1 J and B = J^T M^-1 (eq. 6), C = [I  -A] (eqs. 7-8).
#pragma once

#include <type_traits>

#include "exact/number.h"
#include "geometry/planar_scene.h"

namespace contactcert::solvers {

using exact::Mat;
using exact::Q;
using exact::Vec;

/// The matrices of eqs. (4)-(8) for one scene with n fixels, over T.
template <class T>
struct ContactModel {
  Mat<T> J;  ///< 3 x 2n: columns n_1..n_n then t_1..t_n, as wrenches (f_x, f_y, torque about the com)
  Mat<T> A;  ///< 2n x 2n, A = J^T M^-1 J (eq. 6)
  Mat<T> B;  ///< 2n x 3,  B = J^T M^-1 (eq. 6)
  Mat<T> C;  ///< 2n x 4n, C = [I  -A] (eq. 8)
  Eigen::Index fixels() const { return J.cols() / 2; }
};

/// The Jacobian J of eq. (4), exactly: column i is the wrench of a unit-length-of-n_i force along
/// n_i applied at p_i, column n + i the same for t_i; torques about the centre of mass.
Mat<Q> jacobian(const geometry::PlanarScene& scene);

/// J, A, B, C for the scene, with M = diag(1, 1, I/m) (only I/m matters: the cones are invariant
/// under scaling M).
template <class T>
ContactModel<T> contact_model(const geometry::PlanarScene& scene);

/// An exact number in T (identity for Q, rounding to nearest for double).
template <class T>
T from_exact(const Q& x) {
  if constexpr (std::is_same_v<T, Q>) {
    return x;
  } else {
    return x.get_d();
  }
}

/// An exact matrix in T (identity for Q, rounding to nearest for double).
template <class T>
Mat<T> from_exact(const Mat<Q>& M) {
  if constexpr (std::is_same_v<T, Q>) {
    return M;
  } else {
    return exact::to_double(M);
  }
}

extern template ContactModel<double> contact_model<double>(const geometry::PlanarScene&);
extern template ContactModel<Q> contact_model<Q>(const geometry::PlanarScene&);

}  // namespace contactcert::solvers
