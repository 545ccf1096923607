#include "solvers/wrench_cone/contact_model.h"

#include <cmath>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/ladder_numbers.h"

namespace contactcert::solvers {
namespace {

namespace rg = exact::ring;

// J of eq. (4) in an exact ring R, 3 x 2n row-major (see jacobian()). Per fixel: n = the primitive
// integer multiple of the frame's normal, t = (-n_y, n_x); D r = (R_x, R_y) integer for
// r = p - com; the torques D cross(r, n) = T_n and D cross(r, t) = T_t; the frame scale
// lcm(den(T_n / D), den(T_t / D)) is D / g with g = gcd(T_n, T_t, D).
template <class R>
std::vector<R> jacobian_ring(const geometry::PlanarScene& scene) {
  const std::size_t n = scene.fixels.size(), w = 2 * n;
  std::vector<R> J(3 * w);
  auto lcm = [](const R& a, const R& b) { return rg::mul(rg::divexact(a, rg::gcd(a, b)), b); };
  R a, b, c, d, pn, pd, cn, cd, qn, qd, en, ed;
  for (std::size_t i = 0; i < n; ++i) {
    const geometry::ContactFrame& f = scene.fixels[i].frame;
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
    J[i] = rg::mul(nx, s);
    J[w + i] = rg::mul(ny, s);
    J[2 * w + i] = rg::divexact(tn, g);
    J[n + i] = -rg::mul(ny, s);
    J[w + n + i] = rg::mul(nx, s);
    J[2 * w + n + i] = rg::divexact(tt, g);
  }
  return J;
}

// B = J^T M^-1 and A = B J (eq. 6) with M^-1 = diag(lin, lin, rot), in the ring R; J is 3 x 2n
// row-major, B and A come out row-major (A is symmetric).
template <class R>
void products(const std::vector<R>& J, const R& lin, const R& rot, std::vector<R>& B, std::vector<R>& A) {
  const std::size_t w = J.size() / 3;
  const R m[3] = {lin, lin, rot};
  std::vector<R> Jt(3 * w);  // rows of J^T
  B.resize(3 * w);
  for (std::size_t i = 0; i < w; ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      Jt[3 * i + k] = J[k * w + i];
      rg::mul(Jt[3 * i + k], m[k], B[3 * i + k]);
    }
  A.resize(w * w);
  for (std::size_t i = 0; i < w; ++i)
    for (std::size_t j = i; j < w; ++j) {
      rg::dot(&B[3 * i], &Jt[3 * j], 3, A[i * w + j]);
      if (j != i) A[j * w + i] = A[i * w + j];
    }
}

}  // namespace

Mat<Q> jacobian(const geometry::PlanarScene& scene) {
  const auto w = static_cast<Eigen::Index>(2 * scene.fixels.size());
  return exact::with_exact_ring<Q>(
      [&]<class R>() { return rg::IntegerMatrix(3, w, jacobian_ring<R>(scene)).to_field(); });
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
      std::vector<R> J = jacobian_ring<R>(scene), B, A;
      products<R>(J, lin, rot, B, A);
      ContactModel<T> out;
      out.J = rg::IntegerMatrix(3, w, std::move(J));
      out.B = rg::IntegerMatrix(w, 3, std::move(B));
      out.A = rg::IntegerMatrix(w, w, std::move(A));
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
    std::vector<T> J(static_cast<std::size_t>(3 * w)), B, A;
    for (Eigen::Index k = 0; k < 3; ++k)
      for (Eigen::Index i = 0; i < w; ++i) J[static_cast<std::size_t>(k * w + i)] = Jf(k, i);
    products<T>(J, T(1), rot, B, A);
    using RowMajor = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    m.J = std::move(Jf);
    m.B = Eigen::Map<const RowMajor>(B.data(), w, 3);
    m.A = Eigen::Map<const RowMajor>(A.data(), w, w);
  }
  return m;
}

template ContactModel<double> contact_model<double>(const geometry::PlanarScene&);
template ContactModel<Q> contact_model<Q>(const geometry::PlanarScene&);
template ContactModel<exact::Mpfr> contact_model<exact::Mpfr>(const geometry::PlanarScene&);
template ContactModel<exact::Interval> contact_model<exact::Interval>(const geometry::PlanarScene&);

}  // namespace contactcert::solvers
