// Certificates that a wrench lies in G_goal (wrench cone paper, eq. 21 for two fixels, Table 5 for three):
// G_goal is the complement of the union of the wrench cones G_M of the sets (contact state, mode M) of eq. (21) /
// Table 5, each G_M = { g : K z = P g, z >= 0, z_j > 0 on Table 2's strict components } (eqs. 13-17) in the
// scene with contact at the state's fixels only. A wrench g is outside G_M exactly when Motzkin's transposition
// theorem gives a y with y^T K >= 0, y^T P g <= 0, and y^T P g < 0 or (y^T K)_j > 0 on a strict component j
// (a z would give 0 <= y^T K z = y^T P g). Strict inequalities are kept exactly, as everywhere else.
//
// "goal_nonempty" (kind), written by `contactcert design` for each reported insertable placement:
//   "scene" (the goal scene's text, every fixel touching; its digest under "problem_sha256"), "wrench" g,
//   optionally "push": a boundary point p whose frictionless push (n, (p - com) x n), n the inward normal,
//   is a positive multiple of g, and "outside": for each set in the order of eq. (21) / Table 5, its
//   {"state", "mode", "motzkin"}, the Motzkin vector sparse and primitive (solvers/stability/sparse_motzkin.h).
// The checker (checker/goal_check.cpp) states eq. (21) and Table 5 itself, rebuilds each set's scene from the
// embedded goal scene and its K and P with the checkers' own Table 2 (checker/table2_rows.h), recomputes the push
// from the point, and checks every Motzkin vector.
#pragma once

#include <optional>
#include <string>

#include "exact/json_input.h"
#include "exact/strict_feasibility.h"
#include "geometry/planar_scene.h"
#include "solvers/wrench_cone/mode.h"

namespace contactcert::solvers {

/// g in G_M exactly when this system in z is strictly feasible: K z = P g, z >= 0, z_j > 0 on the strict
/// components, K and P of eqs. (15), (17) for `mode` in `scene` (a valid mode of the scene).
exact::StrictSystem<exact::Q> wrench_cone_membership(const geometry::PlanarScene& scene, const ModeString& mode,
                                                     const exact::Vec<exact::Q>& g);

/// The "goal_nonempty" certificate that g is in G_goal of the goal scene (read from `scene_text`), with the push
/// point when g is that point's push. Throws std::logic_error if g lies in some set's cone (a wrong witness).
std::string goal_certificate(const std::string& scene_text, const geometry::PlanarScene& scene,
                             const exact::Vec<exact::Q>& g, const std::optional<geometry::Point2>& push);

}  // namespace contactcert::solvers
