// The world forces that `check` shows a person for a checked witness, from the checker's own Jacobian: the column
// pair (w_in, w_it) of each touching fixel is table2_rows.h's (eq. 4, rebuilt from the checker's frames and scaled
// as the certificates' raw force vectors are), so the raw forces c = (c_1n..c_kn, c_1t..c_kt) that the checker
// verified apply the world force f_i = c_in (w_in)_xy + c_it (w_it)_xy with torque about the com
// tau_i = c_in (w_in)_tau + c_it (w_it)_tau. No solver code (contact_model.h's Jacobian) is used. The components
// c_n, c_t are then stated against the frame the scene writes (solvers::reported_normal, docs/formats.md section 3):
// c_n = f_i . n / |n|^2, c_t = f_i . t / |n|^2.
#pragma once

#include <vector>

#include "geometry/planar_scene.h"
#include "solvers/stability/world_forces.h"

namespace contactcert::checker {

/// The world forces of the verified raw forces `c` of the touching fixels `touching` (indices into the scene read
/// with the checker's frames, in order), in the shape the writers print (queries/contact_forces.h).
std::vector<solvers::WorldForce<exact::Q>> checked_world_forces(const geometry::PlanarScene& scene,
                                                                const std::vector<Eigen::Index>& touching,
                                                                const exact::Vec<exact::Q>& c);

}  // namespace contactcert::checker
