#include "solvers/wrench_cone/contact_model.h"

#include <cmath>
#include <vector>

#include "exact/int_matrix.h"
#include "exact/ladder_numbers.h"

// GCC 12 warns falsely that moving a boost::container::small_vector<std::int64_t, 64> (an IntMatrix's entries) out of
// its inline storage reads past it (-Wstringop-overread, inlined from boost's memmove). Clang has no such warning.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-overread"
#endif

namespace contactcert::solvers {
namespace {

namespace rg = exact::ring;

// J of eq. (4) in an exact ring R, 3 x 2n row-major (see jacobian()). Per fixel: n = the primitive
// integer multiple of the frame's normal, t = (-n_y, n_x); D r = (R_x, R_y) integer for
// r = p - com; the torques D cross(r, n) = T_n and D cross(r, t) = T_t; the frame scale
// lcm(den(T_n / D), den(T_t / D)) is D / g with g = gcd(T_n, T_t, D).
template <class R>
exact::IntMatrix<R> jacobian_ring(const geometry::PlanarScene& scene) {
  const auto n = static_cast<Eigen::Index>(scene.fixels.size());
  exact::IntMatrix<R> J(3, 2 * n);
  auto lcm = [](const R& a, const R& b) { return rg::mul(rg::divexact(a, rg::gcd(a, b)), b); };
  R a, b, c, d, pn, pd, cn, cd, qn, qd, en, ed;
  for (Eigen::Index i = 0; i < n; ++i) {
    const geometry::ContactFrame& f = scene.fixels[static_cast<std::size_t>(i)].frame;
    rg::from_rational(f.normal.x, a, b);
    rg::from_rational(f.normal.y, c, d);
    const R l = lcm(b, d);
    R nx = rg::mul(a, rg::divexact(l, b)), ny = rg::mul(c, rg::divexact(l, d));
    const R gn = rg::gcd(nx, ny);
    nx = rg::divexact(nx, gn);
    ny = rg::divexact(ny, gn);
    rg::from_rational(f.point.x, pn, pd);
    rg::from_rational(scene.workpiece.com.x, cn, cd);
    rg::from_rational(f.point.y, qn, qd);
    rg::from_rational(scene.workpiece.com.y, en, ed);
    const R D = lcm(lcm(pd, cd), lcm(qd, ed));
    const R rx = rg::sub(rg::mul(pn, rg::divexact(D, pd)), rg::mul(cn, rg::divexact(D, cd)));
    const R ry = rg::sub(rg::mul(qn, rg::divexact(D, qd)), rg::mul(en, rg::divexact(D, ed)));
    const R tn = rg::sub(rg::mul(rx, ny), rg::mul(ry, nx)), tt = rg::add(rg::mul(rx, nx), rg::mul(ry, ny));
    const R g = rg::gcd(rg::gcd(tn, tt), D), s = rg::divexact(D, g);
    J(0, i) = rg::mul(nx, s);
    J(1, i) = rg::mul(ny, s);
    J(2, i) = rg::divexact(tn, g);
    J(0, n + i) = -rg::mul(ny, s);
    J(1, n + i) = rg::mul(nx, s);
    J(2, n + i) = rg::divexact(tt, g);
  }
  return J;
}

// B = J^T M^-1 (w x 3) and A = B J (w x w, symmetric; eq. 6) with M^-1 = diag(lin, lin, rot), in the ring R (an
// exact ring, or a float type for the float model), for J 3 x w.
template <class R>
void products(const exact::IntMatrix<R>& J, const R& lin, const R& rot, exact::IntMatrix<R>& B,
              exact::IntMatrix<R>& A) {
  const Eigen::Index w = J.cols();
  const R m[3] = {lin, lin, rot};
  exact::IntMatrix<R> Jt(w, 3);
  B = exact::IntMatrix<R>(w, 3);
  for (Eigen::Index i = 0; i < w; ++i)
    for (Eigen::Index k = 0; k < 3; ++k) {
      Jt(i, k) = J(k, i);
      rg::mul(Jt(i, k), m[k], B(i, k));
    }
  A = exact::IntMatrix<R>(w, w);
  for (Eigen::Index i = 0; i < w; ++i)
    for (Eigen::Index j = i; j < w; ++j) {
      rg::dot(B.row(i), Jt.row(j), 3, A(i, j));
      if (j != i) A(j, i) = A(i, j);
    }
}

}  // namespace

Mat<Q> jacobian(const geometry::PlanarScene& scene) {
  return exact::with_exact_ring<Q>(
      [&]<class R>() { return exact::FittedIntMatrix(jacobian_ring<R>(scene)).to_field(); });
}

template <class T>
ContactModel<T> contact_model(const geometry::PlanarScene& scene) {
  ContactModel<T> m;
  const auto w = static_cast<Eigen::Index>(2 * scene.fixels.size());
  const Q& inertia = scene.workpiece.inertia_per_mass;
  if constexpr (exact::NumberTraits<T>::is_exact) {
    // M^-1 = diag(1, 1, m/I) up to the positive factor num(I/m), i.e. diag(num, num, den), so that
    // the integer J gives integer A and B; all three in machine integers, or in Z if they outgrow them.
    m = exact::with_exact_ring<Q>([&]<class R>() {
      R lin, rot;
      rg::from_integer(inertia.get_num(), lin);
      rg::from_integer(inertia.get_den(), rot);
      exact::IntMatrix<R> J = jacobian_ring<R>(scene), B, A;
      products<R>(J, lin, rot, B, A);
      ContactModel<T> out;
      out.J = exact::FittedIntMatrix(std::move(J));
      out.B = exact::FittedIntMatrix(std::move(B));
      out.A = exact::FittedIntMatrix(std::move(A));
      return out;
    });
  } else {
    // Float path (double, MPFR, intervals): unit normals and M^-1 = diag(1, 1, m/I), so that entries stay of
    // order one for the tolerance of the sign test.
    Mat<T> Jf = from_exact<T>(jacobian(scene));
    const Eigen::Index n = w / 2;
    for (Eigen::Index i = 0; i < n; ++i) {
      using std::sqrt;  // and CGAL's sqrt for MPFR floats and intervals (found by ADL)
      const T len = sqrt(T(Jf(0, i) * Jf(0, i) + Jf(1, i) * Jf(1, i)));
      Jf.col(i) /= len;
      Jf.col(n + i) /= len;
    }
    const T rot = from_exact<T>(Q(inertia.get_den(), inertia.get_num()));
    exact::IntMatrix<T> J(3, w), B, A;
    for (Eigen::Index k = 0; k < 3; ++k)
      for (Eigen::Index i = 0; i < w; ++i) J(k, i) = Jf(k, i);
    products<T>(J, T(1), rot, B, A);
    using RowMajor = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    m.J = std::move(Jf);
    m.B = Eigen::Map<const RowMajor>(B.row(0), w, 3);
    m.A = Eigen::Map<const RowMajor>(A.row(0), w, w);
  }
  return m;
}

template ContactModel<double> contact_model<double>(const geometry::PlanarScene&);
template ContactModel<Q> contact_model<Q>(const geometry::PlanarScene&);
template ContactModel<exact::Mpfr> contact_model<exact::Mpfr>(const geometry::PlanarScene&);
template ContactModel<exact::Interval> contact_model<exact::Interval>(const geometry::PlanarScene&);

}  // namespace contactcert::solvers

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
