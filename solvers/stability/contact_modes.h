// `contactcert modes`: every kinematically feasible augmented contact mode of a planar scene (touching and gap
// fixels), from rest, found by the prefix tree of mode_tree.h, and the "modes" certificate that the list is
// complete. The wrench cone of a mode (Table 2) is non-empty exactly when the mode is kinematically feasible:
// every letter allows c = 0, so g = M vdot lies in the cone of any feasible mode (eq. 4 with c = 0), and a mode
// with no vdot has no point at all. The dynamic list is therefore the kinematic one, each mode with the
// witness wrench M vdot.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "exact/json_input.h"
#include "geometry/planar_scene.h"
#include "solvers/stability/mode_tree.h"

namespace contactcert::solvers {

/// How the modes of a scene are enumerated.
struct ContactModeOptions {
  bool printed_separation = false;  ///< Table 2 as printed: `s` is a_n >= 0 at a touching fixel too
  bool unions = false;              ///< also the letters m and u (overlapping modes)
  ModeTreeOptions tree;
};

/// The feasible modes of a scene with a witness each, and the tree that proves the list complete.
struct ContactModes {
  ModeAlphabet alphabet;
  MotionModel<Q> model;  ///< every fixel of the scene, exact frames scaled to integers (contact_model.h)
  ModeTree<Q> tree;      ///< modes, accelerations and the dead prefixes
  /// The witness wrench of mode i: M vdot (forces zero), in the scene's wrench coordinates.
  Vec<Q> wrench(std::size_t i) const;
};

ContactModes contact_modes(const geometry::PlanarScene& scene, const ContactModeOptions& options = {});

/// Which kind of motion a mode describes at the touching fixels: every one separates, every one slides, every one
/// rolls (n: at rest unless the workpiece pivots), or a mix; gap letters do not count.
const char* mode_group(const ModeString& mode, const std::vector<bool>& touching);

/// The "modes" certificate: the scene text, the alphabet, every mode with its acceleration, every dead prefix
/// with its Motzkin certificate (sparse, sparse_motzkin.h).
std::string modes_certificate(const std::string& scene_text, const ContactModes& modes);

/// The tree's part of a modes certificate, as `modes` and `dead` members of `certificate` (a JSON object): every
/// mode with its acceleration, every dead prefix with its Motzkin certificate (sparse, sparse_motzkin.h).
void add_mode_tree(nlohmann::ordered_json& certificate, const ModeTree<Q>& tree);

}  // namespace contactcert::solvers
