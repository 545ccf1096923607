// Exact overlap of two planar shapes (polygons and disks): whether their interiors meet. Touching boundaries
// (a shared edge, a vertex on an edge, tangent disks) do not count, so stacked and abutting bodies are accepted.
#pragma once

#include "geometry/workpiece.h"

namespace contactcert::geometry {

/// Whether the interiors of a and b intersect. Polygons: some edge of one has a point inside the other (each edge is
/// cut where it meets the other's boundary, and the midpoint of every piece is located), or both have the same
/// vertices. A disk and a polygon: the centre lies inside, or the boundary comes closer to it than the radius.
/// Two disks: |c_a - c_b| < r_a + r_b. O(n m^2) for polygons of n and m vertices.
bool interiors_overlap(const Shape& a, const Shape& b);

}  // namespace contactcert::geometry
