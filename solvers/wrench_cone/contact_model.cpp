#include "solvers/wrench_cone/contact_model.h"

#include <cmath>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/ladder_numbers.h"
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
      using std::sqrt;  // and CGAL's sqrt for MPFR floats and intervals (found by ADL)
      const T len = sqrt(T(m.J(0, i) * m.J(0, i) + m.J(1, i) * m.J(1, i)));
      m.J.col(i) /= len;
      m.J.col(n + i) /= len;
    }
    rot = rot / lin;
    lin = T(1);
  }
  // B = J^T M^-1, A = B J (eq. 6), in the ring of T: integer matrices in the exact path (integer J,
  // lin and rot), so the products run on machine integers (restarted in Z if they outgrow them).
  exact::with_exact_ring<T>([&]<class R>() {
    namespace rg = exact::ring;
    const auto u2 = static_cast<std::size_t>(n2);
    std::vector<R> w(3), Jt(3 * u2), Bt(3 * u2);  // diag(M^-1), rows of J^T and of B
    rg::from_integer(lin, w[0]);
    w[1] = w[0];
    rg::from_integer(rot, w[2]);
    m.B.resize(n2, 3);
    for (std::size_t i = 0; i < u2; ++i)
      for (std::size_t k = 0; k < 3; ++k) {
        rg::from_integer(m.J(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(i)), Jt[3 * i + k]);
        rg::mul(Jt[3 * i + k], w[k], Bt[3 * i + k]);
        m.B(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = rg::to_field<T>(Bt[3 * i + k]);
      }
    // A is symmetric.
    m.A.resize(n2, n2);
    R a;
    for (std::size_t i = 0; i < u2; ++i)
      for (std::size_t j = i; j < u2; ++j) {
        rg::dot(&Bt[3 * i], &Jt[3 * j], 3, a);
        const auto ei = static_cast<Eigen::Index>(i), ej = static_cast<Eigen::Index>(j);
        m.A(ei, ej) = rg::to_field<T>(a);
        if (j != i) m.A(ej, ei) = m.A(ei, ej);
      }
  });
  return m;
}

template ContactModel<double> contact_model<double>(const geometry::PlanarScene&);
template ContactModel<Q> contact_model<Q>(const geometry::PlanarScene&);
template ContactModel<exact::Mpfr> contact_model<exact::Mpfr>(const geometry::PlanarScene&);
template ContactModel<exact::Interval> contact_model<exact::Interval>(const geometry::PlanarScene&);

}  // namespace contactcert::solvers
