#include "geometry/workpiece.h"

#include <algorithm>

namespace contactcert::geometry {
namespace {

int orient(const Point2& a, const Point2& b, const Point2& c) { return sgn(Q(cross(b - a, c - a))); }

bool on_segment(const Point2& a, const Point2& b, const Point2& p) {
  return orient(a, b, p) == 0 && sgn(Q(dot(p - a, p - b))) <= 0;
}

bool segments_intersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

}  // namespace

std::string PolygonCheck::message() const {
  const std::string v = "vertex " + std::to_string(vertex);
  switch (defect) {
    case PolygonDefect::kNone:
      return "a valid polygon";
    case PolygonDefect::kTooFewVertices:
      return "at least 3 vertices";
    case PolygonDefect::kRepeatedVertex:
      return v + " repeats the previous vertex; remove it";
    case PolygonDefect::kCollinearVertex:
      return v + " is collinear with its neighbours (degenerate polygon); remove it";
    case PolygonDefect::kSelfIntersecting:
      return "a simple polygon, but the edge from " + v + " crosses another edge";
    case PolygonDefect::kNotCounterClockwise:
      return "vertices in counter-clockwise order (the signed area is negative); reverse them";
  }
  return "a valid polygon";
}

PolygonCheck check_polygon(const std::vector<Point2>& V) {
  const std::size_t n = V.size();
  if (n < 3) return {PolygonDefect::kTooFewVertices, 0};
  for (std::size_t i = 0; i < n; ++i)
    if (V[i] == V[(i + n - 1) % n]) return {PolygonDefect::kRepeatedVertex, i};
  for (std::size_t i = 0; i < n; ++i)
    if (orient(V[(i + n - 1) % n], V[i], V[(i + 1) % n]) == 0) return {PolygonDefect::kCollinearVertex, i};
  // Non-adjacent edges must not meet (adjacent ones share exactly their common vertex, since no
  // vertex is collinear with its neighbours).
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;
      if (segments_intersect(V[i], V[(i + 1) % n], V[j], V[(j + 1) % n])) return {PolygonDefect::kSelfIntersecting, i};
    }
  if (sgn(shoelace_area2(V)) <= 0) return {PolygonDefect::kNotCounterClockwise, 0};
  return {};
}

Q shoelace_area2(const std::vector<Point2>& V) {
  Q s = 0;
  for (std::size_t i = 0, n = V.size(); i < n; ++i) s += cross(V[i], V[(i + 1) % n]);
  return s;
}

Point2 polygon_centroid(const std::vector<Point2>& V) {
  // c = 1/(6A) sum (v_i + v_{i+1}) (v_i x v_{i+1}), with 2A = sum v_i x v_{i+1}.
  Q sx = 0, sy = 0;
  for (std::size_t i = 0, n = V.size(); i < n; ++i) {
    const Point2& a = V[i];
    const Point2& b = V[(i + 1) % n];
    const Q w = cross(a, b);
    sx += (a.x + b.x) * w;
    sy += (a.y + b.y) * w;
  }
  const Q six_area = 3 * shoelace_area2(V);
  return {sx / six_area, sy / six_area};
}

Q polygon_inertia_per_mass(const std::vector<Point2>& V, const Point2& about) {
  // Polar moment about `about` of the uniform polygon per unit area:
  // I/m = sum w_i (a.a + a.b + b.b) / (6 * 2A) with a, b relative to `about`, w_i = a x b.
  Q s = 0;
  for (std::size_t i = 0, n = V.size(); i < n; ++i) {
    const Point2 a = V[i] - about;
    const Point2 b = V[(i + 1) % n] - about;
    s += cross(a, b) * (dot(a, a) + dot(a, b) + dot(b, b));
  }
  return s / (6 * shoelace_area2(V));
}

Q disk_inertia_per_mass(const DiskShape& disk, const Point2& about) {
  return disk.radius * disk.radius / 2 + norm2(disk.center - about);
}

Point2 centroid(const Shape& shape) {
  if (const auto* d = std::get_if<DiskShape>(&shape)) return d->center;
  return polygon_centroid(std::get<PolygonShape>(shape).vertices);
}

Q inertia_per_mass(const Shape& shape, const Point2& about) {
  if (const auto* d = std::get_if<DiskShape>(&shape)) return disk_inertia_per_mass(*d, about);
  return polygon_inertia_per_mass(std::get<PolygonShape>(shape).vertices, about);
}

ShapeLocation locate_in_shape(const Shape& shape, const Point2& p) {
  if (const auto* d = std::get_if<DiskShape>(&shape)) {
    const int s = sgn(Q(norm2(p - d->center) - d->radius * d->radius));
    return s > 0 ? ShapeLocation::kOutside : (s == 0 ? ShapeLocation::kBoundary : ShapeLocation::kInside);
  }
  const auto& V = std::get<PolygonShape>(shape).vertices;
  const std::size_t n = V.size();
  bool inside = false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = V[i];
    const Point2& b = V[(i + 1) % n];
    if (on_segment(a, b, p)) return ShapeLocation::kBoundary;
    // Crossing test with the half-open rule on y.
    if ((a.y > p.y) != (b.y > p.y)) {
      const int o = orient(a, b, p);
      if ((b.y > a.y && o > 0) || (b.y < a.y && o < 0)) inside = !inside;
    }
  }
  return inside ? ShapeLocation::kInside : ShapeLocation::kOutside;
}

}  // namespace contactcert::geometry
