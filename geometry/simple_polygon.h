// Is a closed polygonal chain simple? The Shamos-Hoey sweep (Shamos and Hoey 1976): O(n log n) exact
// orientation tests instead of comparing every pair of edges.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/workpiece.h"

namespace contactcert::geometry {

/// The sign of (b - a) x (c - a): +1 if c is left of the line from a to b, -1 if right, 0 if on it.
int orient(const Point2& a, const Point2& b, const Point2& c);
/// p lies on the closed segment ab.
bool on_segment(const Point2& a, const Point2& b, const Point2& p);

/// An edge i (from V[i] to V[i+1 mod n]) that meets an edge other than its two neighbours (touching counts),
/// or nullopt if none does. Precondition: no vertex repeats its predecessor and none is collinear with its
/// neighbours, so neighbouring edges share exactly their common vertex.
std::optional<std::size_t> crossing_edge(const std::vector<Point2>& V);

}  // namespace contactcert::geometry
