#include "queries/boundary_text.h"

#include <cmath>
#include <cstdio>

#include "exact/rational_text.h"
#include "queries/json_out.h"

namespace contactcert::queries {
namespace {

using exact::Q;

/// The angle of direction u in [0, 360) degrees.
double degrees_0_360(const exact::Vec<Q>& u) {
  const double a = std::atan2(u(1).get_d(), u(0).get_d()) * 180.0 / M_PI;
  return a < 0 ? a + 360 : a;
}

std::string deg(double a) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f deg", a);
  return buf;
}

std::string direction_text(const exact::Vec<Q>& u) { return tuple_text(exact::primitive(u)); }

}  // namespace

std::string edge_header_text(const geometry::PlanarScene& scene, std::size_t edge) {
  const auto& V = std::get<geometry::PolygonShape>(scene.workpiece.shape).vertices;
  const std::size_t next = (edge + 1) % V.size();
  return "edge " + std::to_string(edge) + " runs from vertex " + std::to_string(edge) + " " + point_text(V[edge]) +
         " to vertex " + std::to_string(next) + " " + point_text(V[next]) + "; s is the fraction of the way along it:";
}

std::string edge_piece_text(const geometry::PlanarScene& scene, std::size_t edge, const Q& from, const Q& to,
                            bool from_closed, bool to_closed) {
  const auto& V = std::get<geometry::PolygonShape>(scene.workpiece.shape).vertices;
  const geometry::Point2 &a = V[edge], &b = V[(edge + 1) % V.size()];
  const auto at = [&](const Q& s) { return point_text(a + s * (b - a)); };
  if (from == to)
    return "edge " + std::to_string(edge) + " at s = " + exact::to_string(from) + ": the point " + at(from);
  return "edge " + std::to_string(edge) + ", s in " + (from_closed ? "[" : "(") + exact::to_string(from) + ", " +
         exact::to_string(to) + (to_closed ? "]" : ")") + ": from " + at(from) + " to " + at(to);
}

std::string arc_piece_text(const exact::Vec<Q>& from, const exact::Vec<Q>& to, bool from_closed, bool to_closed) {
  const bool same = exact::primitive(from) == exact::primitive(to);
  if (same && !from_closed && !to_closed) return "the whole circle";
  const double a = degrees_0_360(from);
  if (same) return "the single direction " + direction_text(from) + " (" + deg(a) + ")";
  double b = degrees_0_360(to);
  if (b <= a) b += 360;
  return "arc of " + deg(b - a) + " counter-clockwise from " + deg(a) + " (direction " + direction_text(from) +
         (from_closed ? ", included" : ", excluded") + ") to " + deg(b >= 360 ? b - 360 : b) + " (direction " +
         direction_text(to) + (to_closed ? ", included" : ", excluded") + ")";
}

}  // namespace contactcert::queries
