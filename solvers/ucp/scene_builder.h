// A geometric front end for the quasistatic problem of Pang, Trinkle and Lo (section 2): a workpiece, contacts
// with fixed obstacles or point fingers (each velocity- or force-controlled), gravity and mu per contact, from
// which P = [W^T  J_abar], Jn, Jt, theta_dot, alpha and d are built exactly (docs/formats.md, section 2).
#pragma once

#include <string>
#include <vector>

#include "exact/json_input.h"
#include "geometry/contact_frame.h"
#include "solvers/ucp/problem.h"

namespace contactcert::solvers::ucp {

/// One contact of a quasistatic scene: its frame (point r on the workpiece boundary, inward normal n), mu and, for a
/// finger, its control.
struct SceneContact {
  geometry::Point2 r, n;
  Q mu;
  bool finger = false, world_axes = false, force_controlled = false;
  geometry::Point2 given;  ///< the velocity (velocity control) or the force (force control), in the finger's axes
};

/// The problem of a workpiece with centre of mass `com` under `gravity` held by `contacts`, as
/// build_quasistatic_scene below builds it from a file (`file` names the problem in a refusal: exact::InputError).
QuasistaticProblem quasistatic_of_contacts(const geometry::Point2& com, const geometry::Point2& gravity,
                                           const std::vector<SceneContact>& contacts, const std::string& file);

/// The problem of a `"kind": "quasistatic_scene"` file. Per contact i (point r_i on the workpiece boundary,
/// inward normal n_i as written, t_i = (-n_iy, n_ix)): the wrench columns w_in = (n_i, r_i x n_i) and
/// w_it = (t_i, r_i x t_i) of eq. (1), torques about the world origin. Each finger adds two joints, in contact
/// order: along n_i and t_i ("axes": "frame", the paper's Data Sets) or along x and y ("axes": "world"), so
/// J_n and J_t of eqs. (3)-(5) are selection rows or n_i^T, t_i^T; an obstacle adds none (zero rows). A
/// velocity-controlled finger's joints are in alpha with theta_dot its velocity; a force-controlled finger's
/// are in abar with tau its force (g_man = 0). g_obj = (gravity, com x gravity). Throws exact::InputError
/// naming the field. The frames are `frames`' (the solvers' geometry::frame_of, or a certificate checker's own).
QuasistaticProblem build_quasistatic_scene(const exact::JsonInput& root,
                                           geometry::FrameRule frames = geometry::frame_of);

/// The contact frames of a `"kind": "quasistatic_scene"` file, in contact order, as build_quasistatic_scene
/// uses them: point r_i, inward normal n_i as written (gap 0), t_i = tangent(). Throws exact::InputError.
std::vector<geometry::ContactFrame> quasistatic_scene_frames(const exact::JsonInput& root);

}  // namespace contactcert::solvers::ucp
