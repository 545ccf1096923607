// The rigid-body model of the wrench cone paper from rest (eqs. 3-6, Table 2), written directly in the
// workpiece acceleration vdot and the contact forces c, for one contact mode of the touching fixels:
//     M vdot - J c = g                         (eq. 4: vdot = M^-1 (J c + g))
//     a = J^T vdot with Table 2's signs         (s: a_n > 0; l: a_n = 0, a_t > 0; r: a_n = 0, a_t < 0; n: a = 0)
//     c by Table 2                              (s: c = 0; l/r: c_t = -/+ mu_k c_n; n: |c_t| <= mu_s c_n)
// Answering "is g consistent with this mode?" is one strict-feasibility LP on this system, with no cone
// conversion (ARCHITECTURE principle 4); the cone of the mode is the projection of the same set on g.
#pragma once

#include <vector>

#include "exact/strict_feasibility.h"
#include "geometry/planar_scene.h"
#include "solvers/number_names.h"
#include "solvers/wrench_cone/mode.h"

namespace contactcert::solvers {

/// The linear system of one mode: columns vdot (3, free), then per fixel its forces and slacks; rows:
/// kinematic rows first (they do not involve g), then friction rows, then the 3 dynamics rows.
template <class T>
struct MotionSystem {
  exact::SparseStrictSystem<T> system;               ///< A by its non-zero entries; b = rhs(g)
  Eigen::Index kinematic_rows = 0;                   ///< rows [0, kinematic_rows) constrain vdot only
  std::vector<Eigen::Index> c_n_column, c_t_column;  ///< per fixel: column of c_n / c_t (-1 if none)
  std::vector<T> c_t_per_c_n;                        ///< per fixel: c_t = this * c_n when sliding (else 0)
  std::vector<Eigen::Index> slack_column;            ///< per kinematic or friction row: its slack column (-1 if none)
  bool zero_acceleration = false;                    ///< vdot fixed to 0 (no vdot columns, no kinematic rows)
  /// The right-hand side b for wrench g: zero but for the 3 dynamics rows, which are g.
  Vec<T> rhs(const Vec<T>& g) const;
  /// The system for wrench g (b = rhs(g)), dense.
  exact::StrictSystem<T> with_wrench(const Vec<T>& g) const { return system.dense(rhs(g)); }
  /// Contact forces (c_1n..c_kn, c_1t..c_kt) and vdot read off a point of the system.
  Vec<T> forces(const Vec<T>& x) const;
  Vec<T> acceleration(const Vec<T>& x) const { return x.head(3); }
  /// The point of the system for acceleration vdot (not read if zero_acceleration) and forces c, the inverse
  /// of acceleration() and forces(): each slack follows from its row, rho+- = mu_s c_n -+ c_t and
  /// sigma = a_n or +-a_t (Table 2). The entries of c that the mode fixes (c_t of a sliding fixel, c of a
  /// separating one) are not read.
  Vec<T> point(const Vec<T>& vdot, const Vec<T>& c) const;
};

/// What the system of every mode reads from a scene whose fixels all touch: the Jacobian J of eq. (4)
/// (contact_model.h: exact frames scaled to integers), I/m, and mu_s, mu_k per fixel.
template <class T>
struct MotionModel {
  Mat<T> J;
  T inertia_per_mass;
  std::vector<T> mu_s, mu_k;
};

template <class T>
MotionModel<T> motion_model(const geometry::PlanarScene& scene);

/// The system of `mode` (letters s l r n, one per fixel; every fixel must touch) for the model's scene.
/// With `zero_acceleration`, vdot is fixed to 0 and the kinematic rows are dropped: then the system
/// says J c + g = 0 with every force in its static friction cone (the weakly stable test).
template <class T>
MotionSystem<T> motion_system(const MotionModel<T>& model, const ModeString& mode, bool zero_acceleration = false);

/// How Table 2's kinematic rows read at each fixel of a mode.
struct KinematicRules {
  std::vector<bool> touching;       ///< per fixel; empty: every fixel touches
  bool printed_separation = false;  ///< Table 2 as printed: `s` is a_n >= 0 also at a touching fixel
  bool touches(std::size_t i) const { return touching.empty() || touching[i]; }
};

/// The kinematic rows of `mode` (any Table 2 letters) or of a prefix of it (letters for the first fixels only),
/// on the only columns they involve: vdot, then the slack sigma of each fixel whose letter signs a row (s a l r;
/// strict but for `s` at a gap or printed), in fixel order. Per fixel: s a m one row (a_n - sigma, a_n + sigma,
/// a_n), l r n two (a_n; a_t - sigma, a_t + sigma, a_t), u none. Feasible iff some vdot realises the letters; for
/// a mode over s l r n of a scene whose fixels all touch, these are the leading rows of motion_system(model,
/// mode), so a Motzkin certificate of them is one for the whole system (the other columns are zero there). Does
/// not depend on g.
template <class T>
exact::SparseStrictSystem<T> kinematic_system(const MotionModel<T>& model, const ModeString& mode,
                                              const KinematicRules& rules = {});

/// The number of rows of motion_system(model, mode): per fixel 1 kinematic row if it separates, else 2, plus 2
/// friction rows if it rolls; then the 3 dynamics rows.
Eigen::Index motion_system_rows(const ModeString& mode);

#define CONTACTCERT_MOTION_SYSTEM_EXTERN(T)                                                                  \
  extern template MotionModel<T> motion_model<T>(const geometry::PlanarScene&);                              \
  extern template exact::SparseStrictSystem<T> kinematic_system<T>(const MotionModel<T>&, const ModeString&, \
                                                                   const KinematicRules&);                   \
  extern template MotionSystem<T> motion_system<T>(const MotionModel<T>&, const ModeString&, bool);
CONTACTCERT_MOTION_SYSTEM_EXTERN(double)
CONTACTCERT_MOTION_SYSTEM_EXTERN(Q)
#undef CONTACTCERT_MOTION_SYSTEM_EXTERN

}  // namespace contactcert::solvers
