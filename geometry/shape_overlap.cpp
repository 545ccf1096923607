#include "geometry/shape_overlap.h"

#include <algorithm>

namespace contactcert::geometry {
namespace {

/// Squared distance from p to the closed segment [a, b].
Q segment_distance2(const Point2& a, const Point2& b, const Point2& p) {
  const Point2 e = b - a;
  Q s = dot(p - a, e) / norm2(e);
  if (sgn(s) < 0) s = 0;
  if (s > 1) s = 1;
  return norm2(p - (a + s * e));
}

/// The parameters s in [0, 1] of the points a + s (b - a) where [a, b] meets [c, d].
void meeting_parameters(const Point2& a, const Point2& b, const Point2& c, const Point2& d, std::vector<Q>& out) {
  const Point2 e = b - a, f = d - c;
  const Q den = cross(e, f);
  if (sgn(den) != 0) {  // a + s e = c + u f
    const Q s = cross(c - a, f) / den, u = cross(c - a, e) / den;
    if (sgn(s) >= 0 && s <= 1 && sgn(u) >= 0 && u <= 1) out.push_back(s);
    return;
  }
  if (sgn(Q(cross(c - a, e))) != 0) return;  // parallel, not collinear
  for (const Point2& x : {c, d}) {
    const Q s = dot(x - a, e) / norm2(e);
    if (sgn(s) >= 0 && s <= 1) out.push_back(s);
  }
}

/// Whether some point of the closed segment [a, b] lies inside polygon Q: the segment is cut where it meets Q's
/// boundary; each piece between cuts lies wholly inside, outside or on the boundary, so its midpoint decides.
bool segment_enters(const Point2& a, const Point2& b, const PolygonShape& poly) {
  std::vector<Q> s{Q(0), Q(1)};
  const auto& V = poly.vertices;
  for (std::size_t j = 0; j < V.size(); ++j) meeting_parameters(a, b, V[j], V[(j + 1) % V.size()], s);
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    const Q mid = (s[i] + s[i + 1]) / 2;
    if (locate_in_shape(poly, a + mid * (b - a)) == ShapeLocation::kInside) return true;
  }
  return false;
}

bool polygons_overlap(const PolygonShape& p, const PolygonShape& q) {
  for (const auto* pair : {&p, &q}) {
    const PolygonShape& self = *pair;
    const PolygonShape& other = pair == &p ? q : p;
    const auto& V = self.vertices;
    for (std::size_t i = 0; i < V.size(); ++i)
      if (segment_enters(V[i], V[(i + 1) % V.size()], other)) return true;
  }
  // No boundary point of one is inside the other: the interiors are disjoint or equal, and equal polygons (without
  // collinear vertices) have the same vertices.
  if (p.vertices.size() != q.vertices.size()) return false;
  return std::all_of(p.vertices.begin(), p.vertices.end(), [&](const Point2& v) {
    return std::find(q.vertices.begin(), q.vertices.end(), v) != q.vertices.end();
  });
}

bool disk_polygon_overlap(const DiskShape& d, const PolygonShape& p) {
  if (locate_in_shape(p, d.center) == ShapeLocation::kInside) return true;
  const auto& V = p.vertices;
  const Q r2 = d.radius * d.radius;
  for (std::size_t i = 0; i < V.size(); ++i)
    if (segment_distance2(V[i], V[(i + 1) % V.size()], d.center) < r2) return true;
  return false;
}

}  // namespace

bool interiors_overlap(const Shape& a, const Shape& b) {
  const auto* da = std::get_if<DiskShape>(&a);
  const auto* db = std::get_if<DiskShape>(&b);
  if (da && db) {
    const Q r = da->radius + db->radius;
    return norm2(da->center - db->center) < r * r;
  }
  if (da) return disk_polygon_overlap(*da, std::get<PolygonShape>(b));
  if (db) return disk_polygon_overlap(*db, std::get<PolygonShape>(a));
  return polygons_overlap(std::get<PolygonShape>(a), std::get<PolygonShape>(b));
}

}  // namespace contactcert::geometry
