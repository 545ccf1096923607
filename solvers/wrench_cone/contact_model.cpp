#include "solvers/wrench_cone/contact_model.h"

namespace contactcert::solvers {

Mat<Q> jacobian(const geometry::PlanarScene& scene) {
  const Eigen::Index n = static_cast<Eigen::Index>(scene.fixels.size());
  Mat<Q> J(3, 2 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const geometry::ContactFrame& f = scene.fixels[static_cast<std::size_t>(i)].frame;
    const geometry::Point2 r = f.point - scene.workpiece.com;
    const geometry::Point2 t = f.tangent();
    J(0, i) = f.normal.x;
    J(1, i) = f.normal.y;
    J(2, i) = geometry::cross(r, f.normal);
    J(0, n + i) = t.x;
    J(1, n + i) = t.y;
    J(2, n + i) = geometry::cross(r, t);
  }
  return J;
}

template <class T>
ContactModel<T> contact_model(const geometry::PlanarScene& scene) {
  ContactModel<T> m;
  m.J = from_exact<T>(jacobian(scene));
  const Eigen::Index n2 = m.J.cols();
  const T inv_inertia = from_exact<T>(Q(1 / scene.workpiece.inertia_per_mass));
  // B = J^T M^-1 with M^-1 = diag(1, 1, m/I); A = B J (eq. 6).
  m.B.resize(n2, 3);
  for (Eigen::Index i = 0; i < n2; ++i) {
    m.B(i, 0) = m.J(0, i);
    m.B(i, 1) = m.J(1, i);
    m.B(i, 2) = m.J(2, i) * inv_inertia;
  }
  m.A.resize(n2, n2);
  for (Eigen::Index i = 0; i < n2; ++i)
    for (Eigen::Index j = 0; j < n2; ++j) m.A(i, j) = m.B(i, 0) * m.J(0, j) + m.B(i, 1) * m.J(1, j) + m.B(i, 2) * m.J(2, j);
  // C = [I  -A] (eq. 8).
  m.C = Mat<T>::Zero(n2, 2 * n2);
  for (Eigen::Index i = 0; i < n2; ++i) {
    m.C(i, i) = T(1);
    for (Eigen::Index j = 0; j < n2; ++j) m.C(i, n2 + j) = -m.A(i, j);
  }
  return m;
}

template ContactModel<double> contact_model<double>(const geometry::PlanarScene&);
template ContactModel<Q> contact_model<Q>(const geometry::PlanarScene&);

}  // namespace contactcert::solvers
