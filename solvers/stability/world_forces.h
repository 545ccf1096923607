// Contact forces of the rigid-body model in world coordinates (wrench cone paper, eq. 4). The model's force
// vector c = (c_1n..c_kn, c_1t..c_kt) is measured against frames (n_i, t_i) that the exact model scales by a
// positive factor (contact_model.h, jacobian); the world force f_i = c_n,i n_i + c_t,i t_i and its torque
// about the centre of mass p_i x f_i do not depend on that scale, so they are what a user reads, with the
// components against the frame the user wrote (reported_normal): the internal scaling stays internal.
#pragma once

#include <optional>
#include <vector>

#include "exact/number.h"
#include "geometry/planar_scene.h"

namespace contactcert::solvers {

using exact::Vec;

/// One touching fixel's contact force: the frame it is measured against, its components and the world vector.
template <class T>
struct WorldForce {
  Eigen::Index fixel = 0;  ///< index of the fixel in the scene (0-based, the scene's order)
  Vec<T> point;            ///< p_i, the contact point (x, y)
  Vec<T> normal;           ///< n_i (x, y), pointing into the workpiece: reported_normal of the fixel
  Vec<T> tangent;          ///< t_i = (-n_iy, n_ix)
  T c_n, c_t;              ///< the components against (n_i, t_i)
  Vec<T> force;            ///< f_i = c_n n_i + c_t t_i, world coordinates (x, y)
  T torque;                ///< f_i's torque: (p_i - com) x f_i here; about the world origin for a quasistatic scene
};

/// The normal a report measures a fixel's force against: an explicit contact's normal as written; for a frame
/// found from a `position`, the unit inward normal when its length is rational, else its primitive integer
/// direction (docs/formats.md section 3).
geometry::Point2 reported_normal(const geometry::Fixel& f);

/// The part of world_forces that depends on the scene only, exact: per fixel its two columns of J (eq. 4; column i of
/// J depends on fixel i and the centre of mass alone), its point and its reported frame. Prepared once, it serves
/// every answer of a batch.
class ForceFrames {
 public:
  /// The frames of the fixels `fixels` of the scene.
  ForceFrames(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& fixels);
  /// world_forces(scene, touching, c); every fixel of `touching` must be one of the constructor's.
  template <class T>
  std::vector<WorldForce<T>> forces(const std::vector<Eigen::Index>& touching, const Vec<T>& c) const;

 private:
  struct Frame {
    Vec<exact::Q> point, normal, normal_wrench, tangent_wrench;  // p_i, the reported n_i, J's columns i and k + i
    exact::Q normal_squared;                                     // |n_i|^2
  };
  std::vector<std::optional<Frame>> by_fixel_;
};

/// The world forces of `c` (the layout of StabilityResult: normals then tangents of the touching fixels
/// `touching`, in that order). Then sum_i (f_i, torque_i) = J c, so a resting solution has
/// sum_i f_i + (g_x, g_y) = 0 and sum_i torque_i + g_tau = 0 (eq. 4 with zero acceleration).
template <class T>
std::vector<WorldForce<T>> world_forces(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                                        const Vec<T>& c);

extern template std::vector<WorldForce<double>> ForceFrames::forces<double>(const std::vector<Eigen::Index>&,
                                                                            const Vec<double>&) const;
extern template std::vector<WorldForce<exact::Q>> ForceFrames::forces<exact::Q>(const std::vector<Eigen::Index>&,
                                                                                const Vec<exact::Q>&) const;

extern template std::vector<WorldForce<double>> world_forces<double>(const geometry::PlanarScene&,
                                                                     const std::vector<Eigen::Index>&,
                                                                     const Vec<double>&);
extern template std::vector<WorldForce<exact::Q>> world_forces<exact::Q>(const geometry::PlanarScene&,
                                                                         const std::vector<Eigen::Index>&,
                                                                         const Vec<exact::Q>&);

}  // namespace contactcert::solvers
