// Pieces of the workpiece boundary (finger pushes, insertion pushes) in words for the readable reports: an
// edge piece by its parameter s and its end points in coordinates, a disk arc by its directions and angles.
// Numbering (docs/formats.md): fixels, vertices and edges count from 0 in the scene's order; edge k runs from
// vertex k to vertex k + 1 (mod the vertex count) and s in [0, 1] is the fraction of the way along it.
#pragma once

#include <string>

#include "geometry/planar_scene.h"
#include "solvers/stability/finger_push.h"

namespace contactcert::queries {

/// "edge 2 runs from vertex 2 (x, y) to vertex 3 (x, y); s is the fraction of the way along it:".
std::string edge_header_text(const geometry::PlanarScene& scene, std::size_t edge);

/// "edge 2, s in (1/2, 31/52): from (x, y) to (x, y)", or "edge 2 at s = 1/2: the point (x, y)".
std::string edge_piece_text(const geometry::PlanarScene& scene, std::size_t edge, const exact::Q& from,
                            const exact::Q& to, bool from_closed, bool to_closed);

/// "arc of 90.0 deg counter-clockwise from 0.0 deg (direction (1, 0), excluded) to 90.0 deg (direction (0, 1),
/// included)", "the whole circle" or "the single direction (1, 0) (0.0 deg)"; angles are rounded (a view of the
/// exact directions).
std::string arc_piece_text(const exact::Vec<exact::Q>& from, const exact::Vec<exact::Q>& to, bool from_closed,
                           bool to_closed);

/// The text of every piece whose label passes `keep`, one per line with `indent`; "none" when there is none.
template <class Label, class Keep, class Suffix>
std::string pieces_text(const geometry::PlanarScene& scene, const solvers::BoundaryPieces<exact::Q, Label>& p,
                        const std::string& indent, Keep keep, Suffix suffix) {
  std::string out;
  std::size_t header = p.edges.empty() ? 0 : p.edges.size();
  for (const auto& e : p.edges)
    if (keep(e.label)) {
      if (e.edge != header) out += indent + edge_header_text(scene, header = e.edge) + "\n";
      out += indent + "  " + edge_piece_text(scene, e.edge, e.from, e.to, e.from_closed, e.to_closed) +
             suffix(e.label) + "\n";
    }
  for (const auto& a : p.arcs)
    if (keep(a.label))
      out += indent + arc_piece_text(a.from, a.to, a.from_closed, a.to_closed) + suffix(a.label) + "\n";
  return out.empty() ? indent + "none\n" : out;
}

}  // namespace contactcert::queries
