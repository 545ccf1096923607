// Pictures for `contactcert stability`: the sphere of wrench directions coloured by verdict.
#pragma once

#include <string>

#include "solvers/stability/stable_region.h"

namespace contactcert::cli {

/// Two discs (torque >= 0 and torque <= 0; each the projection on (f_x, f_y) of a half sphere), each pixel of the
/// sampled direction coloured strongly stable / weakly stable / unstable from the exact cones' rows (in
/// doubles: a picture, not a verdict).
std::string stability_sphere_svg(const solvers::StableRegion<exact::Q>& region, int resolution = 64);

/// The colour of a label (shared by all stability pictures).
const char* verdict_colour(solvers::StabilityVerdict v);

}  // namespace contactcert::cli
