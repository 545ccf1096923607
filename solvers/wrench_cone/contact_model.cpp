#include "solvers/wrench_cone/contact_model.h"

#include <cmath>
#include <vector>

#include "exact/rational_text.h"

namespace contactcert::solvers {

Mat<Q> jacobian(const geometry::PlanarScene& scene) {
  const Eigen::Index n = static_cast<Eigen::Index>(scene.fixels.size());
  Mat<Q> J(3, 2 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const geometry::ContactFrame& f = scene.fixels[static_cast<std::size_t>(i)].frame;
    const geometry::Point2 r = f.point - scene.workpiece.com;
    const std::vector<exact::Z> np = exact::primitive(std::vector<Q>{f.normal.x, f.normal.y});
    const geometry::Point2 nrm{Q(np[0]), Q(np[1])};
    const geometry::Point2 t = geometry::perp(nrm);
    const Q torque_n = geometry::cross(r, nrm), torque_t = geometry::cross(r, t);
    // A positive frame scale that also makes both torques integers.
    exact::Z scale;
    mpz_lcm(scale.get_mpz_t(), torque_n.get_den_mpz_t(), torque_t.get_den_mpz_t());
    J(0, i) = nrm.x * scale;
    J(1, i) = nrm.y * scale;
    J(2, i) = torque_n * scale;
    J(0, n + i) = t.x * scale;
    J(1, n + i) = t.y * scale;
    J(2, n + i) = torque_t * scale;
  }
  return J;
}

template <class T>
ContactModel<T> contact_model(const geometry::PlanarScene& scene) {
  ContactModel<T> m;
  m.J = from_exact<T>(jacobian(scene));
  const Eigen::Index n2 = m.J.cols();
  // Exact path: M^-1 = diag(1, 1, m/I) up to the positive factor num(I/m), i.e. diag(num, num, den),
  // so that integer J gives integer A and B. Float path: unit normals and M^-1 = diag(1, 1, m/I), so
  // that entries stay of order one for the tolerance of the sign test.
  T lin = from_exact<T>(Q(scene.workpiece.inertia_per_mass.get_num()));
  T rot = from_exact<T>(Q(scene.workpiece.inertia_per_mass.get_den()));
  if constexpr (!exact::NumberTraits<T>::is_exact) {
    const Eigen::Index n = n2 / 2;
    for (Eigen::Index i = 0; i < n; ++i) {
      const T len = std::hypot(m.J(0, i), m.J(1, i));
      m.J.col(i) /= len;
      m.J.col(n + i) /= len;
    }
    rot = rot / lin;
    lin = T(1);
  }
  // B = J^T M^-1, A = B J (eq. 6).
  m.B.resize(n2, 3);
  for (Eigen::Index i = 0; i < n2; ++i) {
    m.B(i, 0) = m.J(0, i) * lin;
    m.B(i, 1) = m.J(1, i) * lin;
    m.B(i, 2) = m.J(2, i) * rot;
  }
  // A is symmetric; products go through one scratch number (no temporaries in the exact path).
  m.A.resize(n2, n2);
  T product;
  for (Eigen::Index i = 0; i < n2; ++i)
    for (Eigen::Index j = i; j < n2; ++j) {
      T& a = m.A(i, j);
      a = m.B(i, 0) * m.J(0, j);
      for (Eigen::Index k = 1; k < 3; ++k) {
        product = m.B(i, k) * m.J(k, j);
        a += product;
      }
      if (j != i) m.A(j, i) = a;
    }
  return m;
}

template ContactModel<double> contact_model<double>(const geometry::PlanarScene&);
template ContactModel<Q> contact_model<Q>(const geometry::PlanarScene&);

}  // namespace contactcert::solvers
