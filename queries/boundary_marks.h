// Pictures of labelled boundary pieces (finger pushes, insertion pushes) as marks on the scene drawing.
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "queries/cone_svg.h"
#include "solvers/stability/finger_push.h"

namespace contactcert::queries {

/// One mark per piece whose style(label) has a colour: edge pieces as segments, disk arcs sampled
/// counter-clockwise, single points as dots.
template <class Label>
std::vector<BoundaryMark> boundary_marks(const geometry::PlanarScene& scene,
                                         const solvers::BoundaryPieces<exact::Q, Label>& pieces,
                                         const std::function<MarkStyle(Label)>& style) {
  std::vector<BoundaryMark> marks;
  if (const auto* poly = std::get_if<geometry::PolygonShape>(&scene.workpiece.shape)) {
    const auto& V = poly->vertices;
    for (const auto& p : pieces.edges) {
      const MarkStyle c = style(p.label);
      if (c.colour.empty()) continue;
      const auto& a = V[p.edge];
      const auto& b = V[(p.edge + 1) % V.size()];
      auto at = [&](const exact::Q& s) {
        return std::make_pair(exact::Q(a.x + s * (b.x - a.x)).get_d(), exact::Q(a.y + s * (b.y - a.y)).get_d());
      };
      BoundaryMark m{{at(p.from)}, c};
      if (p.to != p.from) m.points.push_back(at(p.to));
      marks.push_back(m);
    }
  } else {
    const auto& d = std::get<geometry::DiskShape>(scene.workpiece.shape);
    const double cx = d.center.x.get_d(), cy = d.center.y.get_d(), r = d.radius.get_d();
    for (const auto& p : pieces.arcs) {
      const MarkStyle c = style(p.label);
      if (c.colour.empty()) continue;
      const double a0 = std::atan2(p.from(1).get_d(), p.from(0).get_d());
      double a1 = std::atan2(p.to(1).get_d(), p.to(0).get_d());
      const bool point = p.from == p.to && p.from_closed && p.to_closed;
      if (!point && a1 <= a0) a1 += 2 * M_PI;
      BoundaryMark m{{}, c};
      const int n = point ? 1 : 48;
      for (int i = 0; i < n; ++i) {
        const double t = point ? a0 : a0 + (a1 - a0) * i / (n - 1);
        m.points.emplace_back(cx + r * std::cos(t), cy + r * std::sin(t));
      }
      marks.push_back(m);
    }
  }
  return marks;
}

/// The finger pushes by verdict: green strongly stable, yellow only weakly, red unstable (verdict_colour).
std::vector<BoundaryMark> verdict_marks(const geometry::PlanarScene& scene,
                                        const solvers::BoundaryPieces<exact::Q, solvers::StabilityVerdict>& pushes);

/// The frictionless pushes that seat the workpiece from any contact state (G_goal), in green.
std::vector<BoundaryMark> seating_marks(const geometry::PlanarScene& scene,
                                        const solvers::BoundaryPieces<exact::Q, bool>& pushes);

}  // namespace contactcert::queries
