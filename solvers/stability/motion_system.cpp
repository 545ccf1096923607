#include "solvers/stability/motion_system.h"

#include <stdexcept>

#include "exact/ladder_numbers.h"
#include "solvers/wrench_cone/contact_model.h"

namespace contactcert::solvers {

using Index = Eigen::Index;

template <class T>
Vec<T> MotionSystem<T>::rhs(const Vec<T>& g) const {
  Vec<T> b = Vec<T>::Zero(system.rows);
  b.tail(3) = g;
  return b;
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
  Vec<T> x = Vec<T>::Zero(system.cols);
  if (!zero_acceleration) x.head(3) = vdot;
  for (Index i = 0; i < k; ++i) {
    const Index cn = c_n_column[static_cast<size_t>(i)], ct = c_t_column[static_cast<size_t>(i)];
    if (cn >= 0) x(cn) = c(i);
    if (ct >= 0) x(ct) = c(k + i);
  }
  // Each slack appears in its own row only, with coefficient -+1: slack = -(row . x without it) / coefficient.
  const Index rows = static_cast<Index>(slack_column.size());
  Vec<T> rest = Vec<T>::Zero(rows), coefficient = Vec<T>::Zero(rows);
  for (const exact::Entry<T>& e : system.entries) {
    if (e.row >= rows || slack_column[static_cast<size_t>(e.row)] < 0) continue;
    if (e.col == slack_column[static_cast<size_t>(e.row)])
      coefficient(e.row) = e.value;
    else
      rest(e.row) += e.value * x(e.col);
  }
  for (Index r = 0; r < rows; ++r) {
    const Index j = slack_column[static_cast<size_t>(r)];
    if (j >= 0) x(j) = T(-rest(r) / coefficient(r));
  }
  return x;
}

template <class T>
MotionModel<T> motion_model(const geometry::PlanarScene& scene) {
  MotionModel<T> m{from_exact<T>(jacobian(scene)), from_exact<T>(scene.workpiece.inertia_per_mass), {}, {}};
  for (const geometry::Fixel& f : scene.fixels) {
    m.mu_s.push_back(from_exact<T>(f.mu_s));
    m.mu_k.push_back(from_exact<T>(f.mu_k));
  }
  return m;
}

namespace {

void check_letters(const ModeString& mode, Index k) {
  if (static_cast<Index>(mode.letters.size()) != k) throw std::invalid_argument("motion_system: mode length");
  for (Interaction L : mode.letters)
    if (L != Interaction::kSeparate && L != Interaction::kSlideLeft && L != Interaction::kSlideRight &&
        L != Interaction::kRoll)
      throw std::invalid_argument("motion_system: only s, l, r, n describe motion from rest");
}

}  // namespace

Index motion_system_rows(const ModeString& mode) {
  Index rows = 3;
  for (Interaction L : mode.letters) rows += L == Interaction::kSeparate ? 1 : L == Interaction::kRoll ? 4 : 2;
  return rows;
}

template <class T>
exact::SparseStrictSystem<T> kinematic_system(const MotionModel<T>& model, const ModeString& mode,
                                              const KinematicRules& rules) {
  const Index k = model.J.cols() / 2;
  if (static_cast<Index>(mode.letters.size()) > k) throw std::invalid_argument("kinematic_system: mode length");
  const Index D = model.J.rows();  // 3, or 3N for an assembly's bodies (solvers/assembly/assembly_modes.h)
  const auto dims = static_cast<std::size_t>(D);
  exact::SparseStrictSystem<T> s{0, D, {}, std::vector<bool>(dims, true), std::vector<bool>(dims, false)};
  s.entries.reserve(8 * mode.letters.size());
  const T zero(0);
  auto add = [&s, &zero](Index col, const T& value) {
    if (value != zero) s.entries.push_back({s.rows, col, value});
  };
  // a_n = J_n^T vdot and a_t = J_t^T vdot (eq. 6 from rest, velocity products neglected).
  auto a_n = [&](Index i) {
    for (Index d = 0; d < D; ++d) add(d, model.J(d, i));
  };
  auto a_t = [&](Index i) {
    for (Index d = 0; d < D; ++d) add(d, model.J(d, k + i));
  };
  for (std::size_t u = 0; u < mode.letters.size(); ++u) {
    const auto i = static_cast<Index>(u);
    const Interaction L = mode.letters[u];
    Index sigma = -1;  // the slack of the row with a sign (Table 2): a_n - sigma = 0, +-a_t - sigma = 0, ...
    const bool separates = L == Interaction::kSeparate || L == Interaction::kSeparatePrinted;
    if (separates || L == Interaction::kApproach || L == Interaction::kSlideLeft || L == Interaction::kSlideRight) {
      sigma = s.cols++;
      s.is_free.push_back(false);
      // s is strict at a touching fixel (docs/papers.md), a_n >= 0 at a gap or as Table 2 prints it (S).
      s.strict.push_back(!separates || (L == Interaction::kSeparate && rules.touches(u) && !rules.printed_separation));
    }
    switch (L) {
      case Interaction::kUnconstrained:
        continue;
      case Interaction::kSeparate:  // a_n - sigma = 0
      case Interaction::kSeparatePrinted:
      case Interaction::kApproach:  // a_n + sigma = 0, sigma > 0
        a_n(i);
        add(sigma, T(separates ? -1 : 1));
        ++s.rows;
        continue;
      default:
        break;
    }
    a_n(i);  // a_n = 0
    ++s.rows;
    if (L == Interaction::kMaintain) continue;
    a_t(i);
    if (L == Interaction::kSlideLeft) add(sigma, T(-1));  // a_t = sigma > 0
    if (L == Interaction::kSlideRight) add(sigma, T(1));  // a_t = -sigma < 0
    ++s.rows;
  }
  return s;
}

template <class T>
MotionSystem<T> motion_system(const MotionModel<T>& model, const ModeString& mode, bool zero_acceleration) {
  const Index k = model.J.cols() / 2;
  if (!zero_acceleration) check_letters(mode, k);
  const Mat<T>& J = model.J;  // 3 x 2k: normals, then tangents
  const T& inertia = model.inertia_per_mass;

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
      const T& mu_k = model.mu_k[u];
      ms.c_t_per_c_n[u] = L == Interaction::kSlideLeft ? T(-mu_k) : mu_k;
    }
  }
  exact::SparseStrictSystem<T>& s = ms.system;
  ms.slack_column.assign(static_cast<size_t>(kin_rows + fric_rows), -1);
  s.rows = kin_rows + fric_rows + 3;
  s.cols = cols;
  s.is_free.assign(static_cast<size_t>(cols), false);
  s.strict.assign(static_cast<size_t>(cols), false);
  if (!zero_acceleration)
    for (Index j = 0; j < 3; ++j) s.is_free[static_cast<size_t>(j)] = true;
  s.entries.reserve(static_cast<size_t>(4 * kin_rows + 3 * fric_rows + 3 * (1 + 2 * k)));
  const T zero(0);
  auto add = [&s, &zero](Index row, Index col, T value) {
    if (value != zero) s.entries.push_back({row, col, std::move(value)});
  };
  if (!zero_acceleration) {
    // The kinematic rows first, their sigma columns (compact 3, 4, ...) moved to the fixels' sigma columns.
    exact::SparseStrictSystem<T> kin = kinematic_system(model, mode, {});
    std::vector<Index> column{0, 1, 2};
    for (Index i = 0; i < k; ++i)
      if (sigma[static_cast<size_t>(i)] >= 0) column.push_back(sigma[static_cast<size_t>(i)]);
    for (exact::Entry<T>& e : kin.entries) {
      const Index j = column[static_cast<size_t>(e.col)];
      if (e.col >= 3) {  // the row's slack, strict
        ms.slack_column[static_cast<size_t>(e.row)] = j;
        s.strict[static_cast<size_t>(j)] = true;
      }
      s.entries.push_back({e.row, j, std::move(e.value)});
    }
  }

  Index f = kin_rows;
  const Index dyn = kin_rows + fric_rows;
  ms.zero_acceleration = zero_acceleration;
  for (Index i = 0; i < k; ++i) {
    const auto u = static_cast<size_t>(i);
    const Index cn = ms.c_n_column[u];
    if (cn < 0) continue;
    // Dynamics: M vdot - J c = g, the contact force entering through its columns of J.
    const Index ct = ms.c_t_column[u];
    for (Index d = 0; d < 3; ++d) {
      if (ct >= 0) {
        add(dyn + d, cn, T(-J(d, i)));
        add(dyn + d, ct, T(-J(d, k + i)));
      } else {
        add(dyn + d, cn, T(-J(d, i) - ms.c_t_per_c_n[u] * J(d, k + i)));
      }
    }
    if (ct >= 0) {
      // |c_t| <= mu_s c_n:  mu_s c_n - c_t - rho+ = 0,  mu_s c_n + c_t - rho- = 0.
      const T& mu_s = model.mu_s[u];
      s.is_free[static_cast<size_t>(ct)] = true;
      for (Index side = 0; side < 2; ++side, ++f) {
        add(f, cn, mu_s);
        add(f, ct, T(side ? 1 : -1));
        add(f, rho[u] + side, T(-1));
        ms.slack_column[static_cast<size_t>(f)] = rho[u] + side;
      }
    }
  }
  if (!zero_acceleration) {
    add(dyn, 0, T(1));
    add(dyn + 1, 1, T(1));
    add(dyn + 2, 2, inertia);  // M = diag(1, 1, I/m) per unit mass
  }
  ms.kinematic_rows = kin_rows;
  return ms;
}

template struct MotionSystem<double>;
template struct MotionSystem<Q>;
template struct MotionSystem<exact::Mpfr>;
template struct MotionSystem<exact::Interval>;
#define CONTACTCERT_MOTION_SYSTEM_INSTANTIATE(T)                                                      \
  template MotionModel<T> motion_model<T>(const geometry::PlanarScene&);                              \
  template exact::SparseStrictSystem<T> kinematic_system<T>(const MotionModel<T>&, const ModeString&, \
                                                            const KinematicRules&);                   \
  template MotionSystem<T> motion_system<T>(const MotionModel<T>&, const ModeString&, bool);
CONTACTCERT_MOTION_SYSTEM_INSTANTIATE(double)
CONTACTCERT_MOTION_SYSTEM_INSTANTIATE(Q)
CONTACTCERT_MOTION_SYSTEM_INSTANTIATE(exact::Mpfr)
CONTACTCERT_MOTION_SYSTEM_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_MOTION_SYSTEM_INSTANTIATE

}  // namespace contactcert::solvers
