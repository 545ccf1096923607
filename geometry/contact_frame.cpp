#include "geometry/contact_frame.h"

#include "exact/rational_text.h"
#include "geometry/point_text.h"

namespace contactcert::geometry {
namespace {

FrameResult failure(FrameStatus s, std::string message) { return {s, {}, std::move(message)}; }

/// sqrt(q) when q >= 0 is the square of a rational.
bool rational_sqrt(const Q& q, Q& root) {
  if (sgn(q) < 0) return false;
  if (!mpz_perfect_square_p(q.get_num_mpz_t()) || !mpz_perfect_square_p(q.get_den_mpz_t())) return false;
  exact::Z num, den;
  mpz_sqrt(num.get_mpz_t(), q.get_num_mpz_t());
  mpz_sqrt(den.get_mpz_t(), q.get_den_mpz_t());
  root = Q(num, den);
  root.canonicalize();
  return true;
}

FrameResult disk_frame(const DiskShape& disk, const Point2& f) {
  const Point2 d = f - disk.center;
  const Q d2 = norm2(d);
  const Q r2 = disk.radius * disk.radius;
  const int s = sgn(Q(d2 - r2));
  if (s < 0)
    return failure(FrameStatus::kInsideWorkpiece,
                   "fixel at " + point_text(f) + " lies inside the disk; move it onto or outside the boundary");
  if (s == 0) return {FrameStatus::kOk, {f, disk.center - f, Q(0)}, {}};
  Q len;
  if (!rational_sqrt(d2, len))
    return failure(FrameStatus::kIrrationalDirection,
                   "fixel at " + point_text(f) + " is at irrational distance sqrt(" + exact::to_string(d2) +
                       ") from the disk centre, so its closest point is not rational; place it along a "
                       "Pythagorean direction such as centre + s*(3/5, 4/5), or give an explicit contact "
                       "{point, normal, gap}");
  const Q gap = len - disk.radius;
  return {FrameStatus::kOk, {disk.center + Q(disk.radius / len) * d, disk.center - f, gap * gap}, {}};
}

/// Whether p lies on the closed segment [a, b]: collinear with it and between its ends.
bool on_segment(const Point2& a, const Point2& b, const Point2& p) {
  const Point2 e = b - a;
  if (sgn(Q(cross(e, p - a))) != 0) return false;
  const Q s = dot(p - a, e);
  return sgn(s) >= 0 && s <= norm2(e);
}

/// The index of the first edge (V[i], V[i+1]) whose segment holds p, or V.size() if none does.
std::size_t edge_holding(const std::vector<Point2>& V, const Point2& p) {
  const std::size_t n = V.size();
  for (std::size_t i = 0; i < n; ++i)
    if (on_segment(V[i], V[(i + 1) % n], p)) return i;
  return n;
}

FrameResult polygon_frame(const std::vector<Point2>& V, const Point2& f) {
  const std::size_t n = V.size();
  const ShapeLocation where = locate_in_shape(PolygonShape{V}, f);
  if (where == ShapeLocation::kInside)
    return failure(FrameStatus::kInsideWorkpiece,
                   "fixel at " + point_text(f) + " lies inside the polygon; move it onto or outside the boundary");
  if (where == ShapeLocation::kBoundary) {
    for (std::size_t i = 0; i < n; ++i)
      if (V[i] == f)
        return failure(FrameStatus::kNormalNotUnique,
                       "fixel at " + point_text(f) + " touches polygon vertex " + std::to_string(i) +
                           ", where the contact normal is not unique; give an explicit contact {point, normal, gap}");
    // Not a vertex, so exactly one edge segment of the simple polygon holds f (a line through another edge may
    // pass through f on a non-convex polygon: only the segment counts).
    const std::size_t i = edge_holding(V, f);
    return {FrameStatus::kOk, {f, perp(V[(i + 1) % n] - V[i]), Q(0)}, {}};
  }
  // Outside: the closest point of every edge; it must be the same point for all minimising edges.
  Q best = -1;
  Point2 p;
  bool unique = true;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = V[i];
    const Point2 e = V[(i + 1) % n] - a;
    Q t = dot(f - a, e) / norm2(e);
    if (sgn(t) < 0) t = 0;
    if (t > 1) t = 1;
    const Point2 q = a + t * e;
    const Q d2 = norm2(f - q);
    if (sgn(best) < 0 || d2 < best) {
      best = d2;
      p = q;
      unique = true;
    } else if (d2 == best && !(q == p)) {
      unique = false;
    }
  }
  if (!unique)
    return failure(FrameStatus::kClosestNotUnique,
                   "fixel at " + point_text(f) +
                       " is equally close to two points of the polygon, so its frame is not "
                       "defined; move it or give an explicit contact {point, normal, gap}");
  return {FrameStatus::kOk, {p, p - f, best}, {}};
}

bool in_cone2(const Point2& u, const Point2& v, const Point2& x) {
  // x in pos(u, v), for cross(u, v) > 0.
  return sgn(Q(cross(u, x))) >= 0 && sgn(Q(cross(x, v))) >= 0;
}

// At vertex i the contact normal may be any non-zero n in pos(u, v), u and v the inward normals of the two edges
// that meet there: the normal forces the two edges can exert, at a convex vertex (cross(u, v) > 0) and at a reflex
// one (cross(u, v) < 0) alike. On the inside of an edge segment it is a positive multiple of the edge's inward
// normal. The caller has checked that p is on the boundary.
std::string check_polygon_normal(const std::vector<Point2>& V, const Point2& p, const Point2& nrm) {
  const std::size_t n = V.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!(V[i] == p)) continue;
    const Point2 u = perp(V[i] - V[(i + n - 1) % n]);  // inward normal of the edge ending at vertex i
    const Point2 v = perp(V[(i + 1) % n] - V[i]);      // inward normal of the edge starting there
    const bool ok = sgn(Q(cross(u, v))) > 0 ? in_cone2(u, v, nrm) : in_cone2(v, u, nrm);
    if (!ok)
      return "a normal that points into the polygon at vertex " + std::to_string(i) + ", in the cone of " +
             point_text(u) + " and " + point_text(v);
    return {};
  }
  const std::size_t i = edge_holding(V, p);
  const Point2 in = perp(V[(i + 1) % n] - V[i]);
  if (sgn(Q(cross(in, nrm))) != 0 || sgn(Q(dot(in, nrm))) <= 0)
    return "a normal perpendicular to edge " + std::to_string(i) +
           " and pointing into the polygon, a positive multiple of " + point_text(in);
  return {};
}

}  // namespace

FrameResult frame_from_position(const Shape& shape, const Point2& fixel) {
  if (const auto* d = std::get_if<DiskShape>(&shape)) return disk_frame(*d, fixel);
  return polygon_frame(std::get<PolygonShape>(shape).vertices, fixel);
}

FrameResult frame_from_contact(const Shape& shape, const Point2& point, const Point2& normal, const Q& gap) {
  if (sgn(gap) < 0) return failure(FrameStatus::kInsideWorkpiece, "a gap >= 0");
  if (sgn(norm2(normal)) == 0) return failure(FrameStatus::kNormalNotUnique, "a non-zero normal");
  if (locate_in_shape(shape, point) != ShapeLocation::kBoundary)
    return failure(FrameStatus::kClosestNotUnique, "a point on the workpiece boundary, not " + point_text(point));
  if (const auto* d = std::get_if<DiskShape>(&shape)) {
    const Point2 in = d->center - point;
    if (sgn(Q(cross(in, normal))) != 0 || sgn(Q(dot(in, normal))) <= 0)
      return failure(FrameStatus::kNormalNotUnique,
                     "a normal pointing at the disk centre, a positive multiple of " + point_text(in));
  } else {
    const std::string why = check_polygon_normal(std::get<PolygonShape>(shape).vertices, point, normal);
    if (!why.empty()) return failure(FrameStatus::kNormalNotUnique, why);
  }
  return {FrameStatus::kOk, {point, normal, gap * gap}, {}};
}

FrameResult frame_of(const Shape& shape, const FrameInput& given) {
  if (given.position) return frame_from_position(shape, *given.position);
  return frame_from_contact(shape, given.point, given.normal, given.gap);
}

}  // namespace contactcert::geometry
