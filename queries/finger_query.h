// The query of `contactcert stability FILE --finger`: where on the workpiece's boundary a frictionless finger pushing
// along the inward normal leaves it strongly stable, only weakly stable or unstable (the verdict of the push's wrench
// in the stable region), as labelled edge pieces and disk arcs; with the picture of the boundary coloured by verdict.
#pragma once

#include <string>

#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "queries/scene_input.h"
#include "solvers/stability/finger_push.h"

namespace contactcert::queries {

struct FingerOptions {
  CommonOptions common;  ///< exact or verified (computed exactly); one deadline for the region and the pushes
  std::string svg;       ///< the file the picture is written to ("" = none)
};

struct FingerAnswer {
  geometry::PlanarScene scene;  ///< for the picture
  solvers::FingerPushes<exact::Q> pushes;
  std::string svg;  ///< the picture's file ("" = none)
};

/// The labelled boundary pieces under the time limit (a Limit past it), the picture written where asked.
/// InputError naming --arith on the float path.
Limited<FingerAnswer> run_finger(const SceneInput& input, const FingerOptions& options);

/// The object `stability --finger --json` prints: edge pieces and arcs with their labels.
json to_json(const FingerAnswer& answer);

/// The scene with the boundary coloured by verdict (verdict_marks, queries/boundary_marks.h).
std::string finger_svg(const FingerAnswer& answer);

}  // namespace contactcert::queries
