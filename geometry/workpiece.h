// Planar workpieces of the wrench cone paper (Balkcom, Trinkle 2002): a simple counter-clockwise
// polygon or a disk, with its centre of mass and I/m (only the ratio of inertia to mass matters),
// all exact.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "exact/number.h"

namespace contactcert::geometry {

using exact::Q;

/// A point or vector of the plane, exact.
struct Point2 {
  Q x, y;
};

inline Point2 operator+(const Point2& a, const Point2& b) { return {a.x + b.x, a.y + b.y}; }
inline Point2 operator-(const Point2& a, const Point2& b) { return {a.x - b.x, a.y - b.y}; }
inline Point2 operator*(const Q& s, const Point2& a) { return {s * a.x, s * a.y}; }
inline bool operator==(const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }
/// a . b
inline Q dot(const Point2& a, const Point2& b) { return a.x * b.x + a.y * b.y; }
/// a x b = a_x b_y - a_y b_x (the torque of force b applied at a).
inline Q cross(const Point2& a, const Point2& b) { return a.x * b.y - a.y * b.x; }
/// |a|^2
inline Q norm2(const Point2& a) { return dot(a, a); }
/// a rotated by +90 degrees: (-a_y, a_x). The paper's t_i from n_i (docs/papers.md errata).
inline Point2 perp(const Point2& a) { return {-a.y, a.x}; }

/// A simple polygon, vertices counter-clockwise.
struct PolygonShape {
  std::vector<Point2> vertices;
};

/// A disk.
struct DiskShape {
  Point2 center;
  Q radius;
};

using Shape = std::variant<PolygonShape, DiskShape>;

/// A rigid workpiece: its shape, centre of mass and inertia about the centre of mass per unit mass.
struct Workpiece {
  Shape shape;
  Point2 com;
  Q inertia_per_mass;  ///< I / m, the only inertial quantity the wrench cones depend on
};

/// Why a vertex list is not a usable simple counter-clockwise polygon.
enum class PolygonDefect {
  kNone,
  kTooFewVertices,
  kTooManyVertices,
  kRepeatedVertex,
  kCollinearVertex,
  kSelfIntersecting,
  kNotCounterClockwise
};

/// Most vertices of a polygon accepted: bounds the time of its exact O(n log n) simple-polygon test.
inline constexpr std::size_t kMaxPolygonVertices = 100000;

/// The first defect of a vertex list (kNone for a simple CCW polygon without collinear consecutive
/// vertices), and the index of the offending vertex.
struct PolygonCheck {
  PolygonDefect defect = PolygonDefect::kNone;
  std::size_t vertex = 0;
  std::string message() const;  ///< what is wrong and how to fix it
};

/// Checks that the vertices form a simple, counter-clockwise polygon.
PolygonCheck check_polygon(const std::vector<Point2>& vertices);

/// Twice the signed area (shoelace formula); positive for counter-clockwise vertices.
Q shoelace_area2(const std::vector<Point2>& vertices);

/// Centroid of the uniform-density polygon (shoelace formula). Precondition: non-zero area.
Point2 polygon_centroid(const std::vector<Point2>& vertices);

/// Polar moment of inertia per unit mass of the uniform-density polygon about point `about`.
Q polygon_inertia_per_mass(const std::vector<Point2>& vertices, const Point2& about);

/// Polar moment of inertia per unit mass of the uniform disk about point `about`: r^2/2 + |c - about|^2.
Q disk_inertia_per_mass(const DiskShape& disk, const Point2& about);

/// Uniform-density centroid of a shape.
Point2 centroid(const Shape& shape);

/// Uniform-density I/m of a shape about `about`.
Q inertia_per_mass(const Shape& shape, const Point2& about);

/// Where a point lies relative to a shape.
enum class ShapeLocation { kOutside, kBoundary, kInside };

/// Exact point location (crossing test for polygons, |p - c|^2 vs r^2 for disks).
ShapeLocation locate_in_shape(const Shape& shape, const Point2& p);

}  // namespace contactcert::geometry
