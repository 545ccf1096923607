// The picture of a spatial scene (docs/formats.md section 3b; `modes SPATIAL --svg FILE`): an isometric view of the
// body's box, its com, and per contact the point, the inward normal and the friction pyramid.
#pragma once

#include <string>

#include "geometry/spatial_scene.h"

namespace contactcert::queries {

/// SVG text, to scale (a bar of one scene unit is drawn): the isometric projection seen from (1, 1, 1) (x to the
/// lower right, y to the lower left, z up); the box's faces translucent, its three edges at the hidden corner dashed;
/// per contact a dot, its number, the normal n as an arrow and the pyramid's edges n + d_j as rays with the polygon
/// of their tips, all scaled by one factor so that |n| draws as a fixed length (the pyramid's angles are the
/// scene's). `title` is printed above.
std::string spatial_svg(const geometry::SpatialScene& scene, const std::string& title);

}  // namespace contactcert::queries
