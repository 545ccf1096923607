// Pictures for `contactcert stability`: the sphere of wrench directions with its exact cells, coloured by verdict.
#pragma once

#include <optional>
#include <string>

#include "solvers/stability/stable_region.h"

namespace contactcert::queries {

/// The colour of a verdict in every picture (strongly stable green, weakly stable yellow, unstable red).
const char* verdict_colour(solvers::StabilityVerdict v);

/// The sphere of wrench directions unfolded as a cube net: each face of the cube max(|f_x|, |f_y|, |tau|) = 1 is a
/// gnomonic projection of its part of the sphere, which maps the arrangement's planes (great circles) to straight
/// lines, so every cell is an exact polygon (cut from the face in rational arithmetic, rounded only when written).
/// Open regions are filled with their label's colour; rays and sectors whose label differs from the region they
/// bound are drawn over it. `mark`, if given, is drawn as the queried wrench.
std::string stability_sphere_svg(const solvers::StableRegion<exact::Q>& region,
                                 const std::optional<exact::Vec<exact::Q>>& mark = std::nullopt);

}  // namespace contactcert::queries
