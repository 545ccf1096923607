#include "queries/boundary_fraction.h"

#include <cmath>

namespace contactcert::queries {
namespace {

using exact::Q;

double angle(const exact::Vec<Q>& u) { return std::atan2(u(1).get_d(), u(0).get_d()); }

}  // namespace

double boundary_fraction(const geometry::PlanarScene& scene, const solvers::BoundaryPieces<Q, bool>& p) {
  double in = 0, total = 0;
  if (const auto* poly = std::get_if<geometry::PolygonShape>(&scene.workpiece.shape)) {
    const auto& V = poly->vertices;
    std::vector<double> len(V.size());
    for (std::size_t e = 0; e < V.size(); ++e) {
      const auto& a = V[e];
      const auto& b = V[(e + 1) % V.size()];
      len[e] = std::hypot(Q(b.x - a.x).get_d(), Q(b.y - a.y).get_d());
      total += len[e];
    }
    for (const auto& piece : p.edges)
      if (piece.label) in += Q(piece.to - piece.from).get_d() * len[piece.edge];
  } else {
    total = 2 * M_PI;
    for (const auto& piece : p.arcs) {
      if (!piece.label) continue;
      double d = angle(piece.to) - angle(piece.from);
      if (d < 0 || (d == 0 && !(piece.from_closed && piece.to_closed))) d += 2 * M_PI;
      in += d;
    }
  }
  return total > 0 ? in / total : 0;
}

}  // namespace contactcert::queries
