#include "solvers/stability/motion_system.h"

#include <stdexcept>

#include "exact/ladder_numbers.h"
#include "solvers/wrench_cone/contact_model.h"

namespace contactcert::solvers {

using Index = Eigen::Index;

template <class T>
Vec<T> MotionSystem<T>::rhs(const Vec<T>& g) const {
  Vec<T> b = Vec<T>::Zero(system.A.rows());
  b.tail(3) = g;
  return b;
}

template <class T>
exact::StrictSystem<T> MotionSystem<T>::with_wrench(const Vec<T>& g) const {
  exact::StrictSystem<T> s = system;
  s.b = rhs(g);
  return s;
}

template <class T>
exact::StrictSystem<T> MotionSystem<T>::kinematic() const {
  return {system.A.topRows(kinematic_rows), Vec<T>::Zero(kinematic_rows), system.is_free, system.strict};
}

template <class T>
Vec<T> MotionSystem<T>::forces(const Vec<T>& x) const {
  const Index k = static_cast<Index>(c_n_column.size());
  Vec<T> c = Vec<T>::Zero(2 * k);
  for (Index i = 0; i < k; ++i) {
    const Index cn = c_n_column[static_cast<size_t>(i)], ct = c_t_column[static_cast<size_t>(i)];
    if (cn >= 0) c(i) = x(cn);
    if (ct >= 0)
      c(k + i) = x(ct);
    else if (cn >= 0)
      c(k + i) = c_t_per_c_n[static_cast<size_t>(i)] * x(cn);
  }
  return c;
}

template <class T>
Vec<T> MotionSystem<T>::point(const Vec<T>& vdot, const Vec<T>& c) const {
  const Index k = static_cast<Index>(c_n_column.size());
  Vec<T> x = Vec<T>::Zero(system.A.cols());
  if (!zero_acceleration) x.head(3) = vdot;
  for (Index i = 0; i < k; ++i) {
    const Index cn = c_n_column[static_cast<size_t>(i)], ct = c_t_column[static_cast<size_t>(i)];
    if (cn >= 0) x(cn) = c(i);
    if (ct >= 0) x(ct) = c(k + i);
  }
  // Each slack appears in its own row only, with coefficient -+1: slack = -(row . x without it) / coefficient.
  for (Index r = 0; r < static_cast<Index>(slack_column.size()); ++r) {
    const Index j = slack_column[static_cast<size_t>(r)];
    if (j >= 0) x(j) = T(-system.A.row(r).dot(x) / system.A(r, j));
  }
  return x;
}

template <class T>
MotionSystem<T> motion_system(const geometry::PlanarScene& scene, const ModeString& mode, bool zero_acceleration) {
  const Index k = static_cast<Index>(scene.fixels.size());
  if (static_cast<Index>(mode.letters.size()) != k) throw std::invalid_argument("motion_system: mode length");
  const Mat<T> J = from_exact<T>(jacobian(scene));  // 3 x 2k: normals, then tangents
  const T inertia = from_exact<T>(scene.workpiece.inertia_per_mass);

  // Column layout: vdot (3) | per fixel: [sigma (strict kinematic slack)] [c_n] [c_t, rho+, rho-].
  MotionSystem<T> ms;
  ms.c_n_column.assign(static_cast<size_t>(k), -1);
  ms.c_t_column.assign(static_cast<size_t>(k), -1);
  ms.c_t_per_c_n.assign(static_cast<size_t>(k), T(0));
  std::vector<Index> sigma(static_cast<size_t>(k), -1), rho(static_cast<size_t>(k), -1);
  Index cols = zero_acceleration ? 0 : 3;
  Index kin_rows = 0, fric_rows = 0;
  for (Index i = 0; i < k; ++i) {
    const auto u = static_cast<size_t>(i);
    const Interaction L = zero_acceleration ? Interaction::kRoll : mode.letters[u];
    if (L != Interaction::kSeparate && L != Interaction::kSlideLeft && L != Interaction::kSlideRight &&
        L != Interaction::kRoll)
      throw std::invalid_argument("motion_system: only s, l, r, n describe motion from rest");
    if (!zero_acceleration) {
      if (L != Interaction::kRoll) sigma[u] = cols++;
      kin_rows += (L == Interaction::kSeparate) ? 1 : 2;
    }
    if (L == Interaction::kSeparate) continue;
    ms.c_n_column[u] = cols++;
    if (L == Interaction::kRoll) {
      ms.c_t_column[u] = cols++;
      rho[u] = cols;
      cols += 2;
      fric_rows += 2;
    } else {
      // Table 2: l has c_t = -mu_k c_n, r has c_t = +mu_k c_n (friction opposes the sliding).
      const T mu_k = from_exact<T>(scene.fixels[u].mu_k);
      ms.c_t_per_c_n[u] = L == Interaction::kSlideLeft ? T(-mu_k) : mu_k;
    }
  }
  const Index rows = kin_rows + fric_rows + 3;
  exact::StrictSystem<T>& s = ms.system;
  s.A = Mat<T>::Zero(rows, cols);
  s.b = Vec<T>::Zero(rows);
  s.is_free.assign(static_cast<size_t>(cols), false);
  s.strict.assign(static_cast<size_t>(cols), false);
  if (!zero_acceleration)
    for (Index j = 0; j < 3; ++j) s.is_free[static_cast<size_t>(j)] = true;

  Index r = 0, f = kin_rows;
  const Index dyn = kin_rows + fric_rows;
  ms.slack_column.assign(static_cast<size_t>(dyn), -1);
  ms.zero_acceleration = zero_acceleration;
  for (Index i = 0; i < k; ++i) {
    const auto u = static_cast<size_t>(i);
    const Interaction L = zero_acceleration ? Interaction::kRoll : mode.letters[u];
    if (!zero_acceleration) {
      // a_n = J_n^T vdot and a_t = J_t^T vdot (eq. 6 from rest, velocity products neglected).
      if (L == Interaction::kSeparate) {  // a_n - sigma = 0, sigma > 0
        s.A.block(r, 0, 1, 3) = J.col(i).transpose();
        s.A(r, sigma[u]) = T(-1);
        ms.slack_column[static_cast<size_t>(r++)] = sigma[u];
      } else {
        s.A.block(r++, 0, 1, 3) = J.col(i).transpose();  // a_n = 0
        s.A.block(r, 0, 1, 3) = J.col(k + i).transpose();
        if (L == Interaction::kSlideLeft) s.A(r, sigma[u]) = T(-1);  // a_t = sigma > 0
        if (L == Interaction::kSlideRight) s.A(r, sigma[u]) = T(1);  // a_t = -sigma < 0
        ms.slack_column[static_cast<size_t>(r++)] = sigma[u];
      }
      if (sigma[u] >= 0) s.strict[static_cast<size_t>(sigma[u])] = true;
    }
    const Index cn = ms.c_n_column[u];
    if (cn < 0) continue;
    // Dynamics: M vdot - J c = g, the contact force entering through its columns of J.
    const Index ct = ms.c_t_column[u];
    for (Index d = 0; d < 3; ++d) {
      s.A(dyn + d, cn) = -J(d, i);
      if (ct >= 0)
        s.A(dyn + d, ct) = -J(d, k + i);
      else
        s.A(dyn + d, cn) -= ms.c_t_per_c_n[u] * J(d, k + i);
    }
    if (ct >= 0) {
      // |c_t| <= mu_s c_n:  mu_s c_n - c_t - rho+ = 0,  mu_s c_n + c_t - rho- = 0.
      const T mu_s = from_exact<T>(scene.fixels[u].mu_s);
      s.is_free[static_cast<size_t>(ct)] = true;
      for (Index side = 0; side < 2; ++side, ++f) {
        s.A(f, cn) = mu_s;
        s.A(f, ct) = T(side ? 1 : -1);
        s.A(f, rho[u] + side) = T(-1);
        ms.slack_column[static_cast<size_t>(f)] = rho[u] + side;
      }
    }
  }
  if (!zero_acceleration) {
    s.A(dyn, 0) = T(1);
    s.A(dyn + 1, 1) = T(1);
    s.A(dyn + 2, 2) = inertia;  // M = diag(1, 1, I/m) per unit mass
  }
  ms.kinematic_rows = kin_rows;
  return ms;
}

template struct MotionSystem<double>;
template struct MotionSystem<Q>;
template MotionSystem<double> motion_system<double>(const geometry::PlanarScene&, const ModeString&, bool);
template MotionSystem<Q> motion_system<Q>(const geometry::PlanarScene&, const ModeString&, bool);
template struct MotionSystem<exact::Mpfr>;
template struct MotionSystem<exact::Interval>;
template MotionSystem<exact::Mpfr> motion_system<exact::Mpfr>(const geometry::PlanarScene&, const ModeString&, bool);
template MotionSystem<exact::Interval> motion_system<exact::Interval>(const geometry::PlanarScene&, const ModeString&,
                                                                      bool);

}  // namespace contactcert::solvers
