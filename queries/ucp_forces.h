// The contact forces of a quasistatic solution as a person reads them. For a `"kind": "quasistatic_scene"` file
// each contact i has point r_i and frame (n_i as written, t_i = (-n_iy, n_ix)) (solvers/ucp/scene_builder.h), so
// its world force f_i = c_n,i n_i + c_t,i t_i and torque r_i x f_i about the world origin are printed beside c_n,
// c_t; the workpiece's equilibrium (Pang, Trinkle, Lo, eq. 1) reads sum_i (f_i, r_i x f_i) + g_obj = 0. A problem
// given by its matrices states no geometry: its c_n, c_t are against its own frames only.
#pragma once

#include <string>
#include <vector>

#include "geometry/contact_frame.h"
#include "queries/json_out.h"
#include "solvers/stability/world_forces.h"

namespace contactcert::queries {

/// Per contact i (its index in `fixel`): r_i, n_i, t_i, c_n, c_t, f_i = c_n n_i + c_t t_i, torque r_i x f_i.
std::vector<solvers::WorldForce<exact::Q>> scene_world_forces(const std::vector<geometry::ContactFrame>& frames,
                                                              const exact::Vec<exact::Q>& c_n,
                                                              const exact::Vec<exact::Q>& c_t);

/// The world forces of a scene as JSON: per contact {"contact", "point", "normal", "tangent", "c_n", "c_t",
/// "force", "torque"} (exact strings).
json ucp_forces_json(const std::vector<geometry::ContactFrame>& frames, const exact::Vec<exact::Q>& c_n,
                     const exact::Vec<exact::Q>& c_t);

/// The text lines (two-space indent) on the frames of the contact forces c_n, c_t: the world forces of a scene,
/// or (no frames) one sentence that they are against the problem's own frames.
std::string ucp_forces_text(const std::vector<geometry::ContactFrame>& frames, const exact::Vec<exact::Q>& c_n,
                            const exact::Vec<exact::Q>& c_t);

}  // namespace contactcert::queries
