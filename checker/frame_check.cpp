#include "checker/frame_check.h"

#include <optional>

#include "exact/rational_text.h"
#include "geometry/point_text.h"
#include "geometry/scene_json.h"

namespace contactcert::checker::frame_check {
namespace {

using exact::Q;
using geometry::ContactFrame;
using geometry::DiskShape;
using geometry::FrameInput;
using geometry::FrameResult;
using geometry::FrameStatus;
using geometry::Point2;
using geometry::Shape;

FrameResult fails(FrameStatus s, std::string why) { return {s, {}, std::move(why)}; }

/// x = s y for some s > 0.
bool positive_multiple(const Point2& x, const Point2& y) {
  return sgn(Q(geometry::cross(x, y))) == 0 && sgn(Q(geometry::dot(x, y))) > 0;
}

/// p on the closed segment [a, b].
bool on_segment(const Point2& a, const Point2& b, const Point2& p) {
  const Point2 e = b - a;
  const Q s = geometry::dot(p - a, e);
  return sgn(Q(geometry::cross(e, p - a))) == 0 && sgn(s) >= 0 && s <= geometry::norm2(e);
}

/// The point of the segment [a, b] closest to f: a + t (b - a), t = (f - a).(b - a) / |b - a|^2 clamped to [0, 1].
Point2 closest_on_segment(const Point2& a, const Point2& b, const Point2& f) {
  const Point2 e = b - a;
  Q t = geometry::dot(f - a, e) / geometry::norm2(e);
  if (sgn(t) < 0) t = 0;
  if (t > 1) t = 1;
  return a + t * e;
}

/// f strictly inside the polygon: on no edge segment, and a ray from f toward +x crosses the boundary an odd
/// number of times (an edge counts when its ends lie on either side of the ray's line, half-open in y).
bool strictly_inside(const std::vector<Point2>& V, const Point2& f) {
  bool inside = false;
  for (std::size_t i = 0; i < V.size(); ++i) {
    const Point2& a = V[i];
    const Point2& b = V[(i + 1) % V.size()];
    if (on_segment(a, b, f)) return false;
    if ((a.y > f.y) != (b.y > f.y) && a.x + (f.y - a.y) * (b.x - a.x) / (b.y - a.y) > f.x) inside = !inside;
  }
  return inside;
}

/// Whether p is on a boundary piece of the polygon and n an inward normal there (kOk), or why not.
FrameResult polygon_piece_violation(const std::vector<Point2>& V, const Point2& p, const Point2& n) {
  const std::size_t k = V.size();
  for (std::size_t i = 0; i < k; ++i) {
    if (!(V[i] == p)) continue;
    const Point2 u = geometry::perp(V[i] - V[(i + k - 1) % k]);  // the edge that ends at vertex i
    const Point2 v = geometry::perp(V[(i + 1) % k] - V[i]);      // the edge that starts there
    // n in pos(u, v) (u, v not parallel: no collinear consecutive vertices): n = alpha u + beta v with
    // alpha = cross(n, v) / cross(u, v) >= 0 and beta = cross(u, n) / cross(u, v) >= 0, n != 0.
    const int s = sgn(Q(geometry::cross(u, v)));
    if (sgn(geometry::norm2(n)) == 0 || sgn(Q(geometry::cross(n, v))) * s < 0 || sgn(Q(geometry::cross(u, n))) * s < 0)
      return fails(FrameStatus::kNormalNotUnique, "the normal " + point_text(n) + " at vertex " + std::to_string(i) +
                                                      " is not in the cone of its edges' inward normals " +
                                                      point_text(u) + " and " + point_text(v));
    return {};
  }
  for (std::size_t i = 0; i < k; ++i) {
    if (!on_segment(V[i], V[(i + 1) % k], p)) continue;
    const Point2 in = geometry::perp(V[(i + 1) % k] - V[i]);
    if (!positive_multiple(n, in))
      return fails(FrameStatus::kNormalNotUnique, "the normal " + point_text(n) +
                                                      " is not a positive multiple of the inward normal " +
                                                      point_text(in) + " of edge " + std::to_string(i) +
                                                      ", whose segment holds the point " + point_text(p));
    return {};
  }
  return fails(FrameStatus::kClosestNotUnique, "the point " + point_text(p) + " is on no edge segment of the polygon");
}

/// Why p is not the unique closest polygon point to f at squared distance gap2, or "".
std::string polygon_closest_violation(const std::vector<Point2>& V, const Point2& f, const Point2& p, const Q& gap2) {
  for (std::size_t i = 0; i < V.size(); ++i) {
    const Point2 q = closest_on_segment(V[i], V[(i + 1) % V.size()], f);
    const Q d2 = geometry::norm2(f - q);
    if (d2 < gap2 || (d2 == gap2 && !(q == p)))
      return "the point " + point_text(q) + " of edge " + std::to_string(i) + " is " +
             (d2 < gap2 ? "closer to the fixel at " + point_text(f) + " than "
                        : "as close to the fixel at " + point_text(f) + " as ") +
             point_text(p);
  }
  return "";
}

/// sqrt(q) if q is the square of a rational.
std::optional<Q> rational_sqrt(const Q& q) {
  if (sgn(q) < 0 || !mpz_perfect_square_p(q.get_num_mpz_t()) || !mpz_perfect_square_p(q.get_den_mpz_t()))
    return std::nullopt;
  exact::Z num, den;
  mpz_sqrt(num.get_mpz_t(), q.get_num_mpz_t());
  mpz_sqrt(den.get_mpz_t(), q.get_den_mpz_t());
  return Q(num, den);
}

/// The frame of a fixel at f on the disk: the circle's point on the ray from c through f, normal c - f.
FrameResult disk_frame(const DiskShape& d, const Point2& f) {
  const Q d2 = geometry::norm2(f - d.center);
  if (d2 < d.radius * d.radius)
    return fails(FrameStatus::kInsideWorkpiece, "the fixel at " + point_text(f) + " is inside the disk");
  const std::optional<Q> len = rational_sqrt(d2);
  if (!len)
    return fails(FrameStatus::kIrrationalDirection,
                 "the fixel at " + point_text(f) + " is at irrational distance from the disk centre");
  const Q gap = *len - d.radius;
  return {FrameStatus::kOk, {d.center + Q(d.radius / *len) * (f - d.center), d.center - f, gap * gap}, {}};
}

/// The frame of a fixel at f on the polygon: its closest point (the first found), normal p - f, or at gap zero the
/// inward normal of the edge segment that holds f.
FrameResult polygon_frame(const std::vector<Point2>& V, const Point2& f) {
  if (strictly_inside(V, f))
    return fails(FrameStatus::kInsideWorkpiece, "the fixel at " + point_text(f) + " is inside the polygon");
  for (std::size_t i = 0; i < V.size(); ++i)
    if (V[i] == f)
      return fails(FrameStatus::kNormalNotUnique, "the fixel at " + point_text(f) + " touches vertex " +
                                                      std::to_string(i) + ", where the normal is not unique");
  std::size_t edge = 0;
  Point2 p = closest_on_segment(V[0], V[1], f);
  for (std::size_t i = 1; i < V.size(); ++i)
    if (const Point2 q = closest_on_segment(V[i], V[(i + 1) % V.size()], f);
        geometry::norm2(f - q) < geometry::norm2(f - p))
      p = q, edge = i;
  const Q gap2 = geometry::norm2(f - p);
  const Point2 n = sgn(gap2) == 0 ? geometry::perp(V[(edge + 1) % V.size()] - V[edge]) : p - f;
  return {FrameStatus::kOk, {p, n, gap2}, {}};
}

}  // namespace

FrameResult frame_violation(const Shape& shape, const FrameInput& given, const ContactFrame& frame) {
  const Point2& p = frame.point;
  const Point2& n = frame.normal;
  const Q& gap2 = frame.gap_squared;
  const auto* disk = std::get_if<DiskShape>(&shape);
  const std::vector<Point2>* V = disk ? nullptr : &std::get<geometry::PolygonShape>(shape).vertices;
  // The point on a boundary piece and the normal perpendicular to it, into the workpiece.
  if (disk) {
    if (geometry::norm2(p - disk->center) != disk->radius * disk->radius)
      return fails(FrameStatus::kClosestNotUnique, "the point " + point_text(p) + " is not on the disk's circle");
    if (!positive_multiple(n, disk->center - p))
      return fails(FrameStatus::kNormalNotUnique, "the normal " + point_text(n) + " is not a positive multiple of " +
                                                      point_text(disk->center - p) +
                                                      ", from the point to the disk centre");
  } else if (FrameResult piece = polygon_piece_violation(*V, p, n); piece.status != FrameStatus::kOk) {
    return piece;
  }
  if (!given.position) {
    if (sgn(given.gap) < 0)
      return fails(FrameStatus::kInsideWorkpiece, "the gap " + exact::to_string(given.gap) + " is negative");
    if (gap2 != given.gap * given.gap)
      return fails(FrameStatus::kClosestNotUnique, "the squared gap is not the square of the file's gap");
    return {FrameStatus::kOk, frame, {}};
  }
  // A fixel at f: outside or on the boundary, p its unique closest point, n from f toward p.
  const Point2& f = *given.position;
  if (disk ? geometry::norm2(f - disk->center) < disk->radius * disk->radius : strictly_inside(*V, f))
    return fails(FrameStatus::kInsideWorkpiece, "the fixel at " + point_text(f) + " is inside the workpiece");
  if (gap2 != geometry::norm2(p - f))
    return fails(FrameStatus::kClosestNotUnique, "the squared gap " + exact::to_string(gap2) +
                                                     " is not |p - f|^2 = " + exact::to_string(geometry::norm2(p - f)));
  if (sgn(gap2) != 0 && !positive_multiple(n, p - f))
    return fails(FrameStatus::kNormalNotUnique, "the normal " + point_text(n) + " is not a positive multiple of " +
                                                    point_text(p - f) + ", from the fixel to the point");
  if (disk) {
    if (!positive_multiple(p - disk->center, f - disk->center))
      return fails(
          FrameStatus::kClosestNotUnique,
          "the point " + point_text(p) + " is not the circle's point closest to the fixel at " + point_text(f));
  } else if (std::string why = polygon_closest_violation(*V, f, p, gap2); !why.empty()) {
    return fails(FrameStatus::kClosestNotUnique, why);
  }
  return {FrameStatus::kOk, frame, {}};
}

FrameResult checked_frame(const Shape& shape, const FrameInput& given) {
  FrameResult derived{FrameStatus::kOk, {given.point, given.normal, given.gap * given.gap}, {}};
  if (given.position) {
    const auto* disk = std::get_if<DiskShape>(&shape);
    derived = disk ? disk_frame(*disk, *given.position)
                   : polygon_frame(std::get<geometry::PolygonShape>(shape).vertices, *given.position);
    if (derived.status != FrameStatus::kOk) return derived;
  }
  return frame_violation(shape, given, derived.frame);
}

CheckedSceneRead read_checked_scene(const exact::JsonInput& root) {
  const geometry::PlanarSceneInput in = geometry::read_planar_scene_input(root);
  CheckedSceneRead out{{in.workpiece, {}}, {}};
  for (std::size_t i = 0; i < in.fixels.size(); ++i) {
    const geometry::FixelInput& f = in.fixels[i];
    const FrameResult r = checked_frame(in.workpiece.shape, f.given);
    if (r.status != FrameStatus::kOk) {
      out.violation = "the frame of fixel " + std::to_string(i) + " of the scene: " + r.message;
      return out;
    }
    out.scene.fixels.push_back({r.frame, f.mu_s, f.mu_k, f.given.position});
  }
  return out;
}

CheckedSceneRead read_embedded_scene(const exact::JsonInput& certificate) {
  const exact::JsonInput embedded =
      exact::JsonInput::parse(certificate.at("scene").string(), certificate.file() + " (embedded scene)");
  if (certificate.at("problem_sha256").string() != embedded.canonical_sha256())
    return {{}, "problem_sha256 is not the digest of the embedded scene"};
  return read_checked_scene(embedded);
}

}  // namespace contactcert::checker::frame_check
