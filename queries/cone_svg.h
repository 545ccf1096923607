// SVG pictures of wrench cones in the style of the wrench cone paper's Figures 3 and 4: the
// workpiece, the fixels (filled when touching), their friction cones, and the cone's generators as
// directed lines of force (pure moments as arcs about the centre of mass). Hand-written SVG.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "exact/number.h"
#include "geometry/planar_scene.h"

namespace contactcert::queries {

/// How a boundary mark is drawn: its colour and what it means (the legend's text; empty: no legend entry).
struct MarkStyle {
  std::string colour, meaning;
};

/// A coloured piece of the workpiece boundary, in scene coordinates (floats: a picture), drawn over the
/// workpiece: a polyline, or a dot when it has one point.
struct BoundaryMark {
  std::vector<std::pair<double, double>> points;
  MarkStyle style;
};

/// A complete <svg> element. `rays` and `lines` are the cone's generators as rows (x, y, torque);
/// lines are drawn in both directions. `title` is printed in the picture; the legend explains each mark style.
std::string wrench_cone_svg(const geometry::PlanarScene& scene, const exact::Mat<exact::Q>& rays,
                            const exact::Mat<exact::Q>& lines, const std::string& title,
                            const std::vector<BoundaryMark>& marks = {});

}  // namespace contactcert::queries
