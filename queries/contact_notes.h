// Notes for the readable reports about a scene's contacts that a reader could misread.
#pragma once

#include <string>

#include "geometry/planar_scene.h"

namespace contactcert::queries {

/// One line per fixel whose gap is positive but tiny next to the workpiece (gap < 1e-30 of its size): such a
/// fixel does not touch (a fixel touches only at a gap of exactly zero, SPEC section 3), which a reader who
/// rounded the input could not tell. Empty when there is none.
std::string tiny_gap_notes(const geometry::PlanarScene& scene, const std::string& indent);

}  // namespace contactcert::queries
