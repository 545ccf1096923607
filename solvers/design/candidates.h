// Candidate fixel positions on the workpiece boundary for fixture design (wrench cone paper, sections 8-10:
// "the intended use of our algorithm was fixture design"): exact rational boundary points with their inward
// normals, placed equally in arc length, read from a file, or at the holes of a square lattice.
#pragma once

#include <string>
#include <vector>

#include "geometry/workpiece.h"

namespace contactcert::solvers {

/// One candidate: a point on the boundary (never a polygon vertex) and the inward normal there (not unit).
struct Candidate {
  geometry::Point2 point;
  geometry::Point2 normal;
};

/// The inward normal at boundary point p: the left normal perp(b - a) of the polygon edge holding p, or
/// c - p on a disk. Empty message when p is a usable candidate, else why not (off the boundary, a vertex).
struct CandidateCheck {
  Candidate candidate;
  std::string message;
};
CandidateCheck candidate_at(const geometry::Shape& shape, const geometry::Point2& p);

/// n points equally spaced in arc length, the first half a step from vertex 0 (or from angle 0 on a disk).
/// Polygon with rational edge lengths: exactly at arc length s_k = (k + 1/2) L / n. When some edge length is
/// irrational, edge e gets n_e points (largest remainder of n L_e / L, the lengths taken as floor(L_e 2^40) /
/// 2^40 when irrational) at equal parameter steps t = (j + 1/2) / n_e: exact points on the edge, spacing equal
/// within an edge and within one step across edges. Points that land on a vertex are dropped. Disk: the
/// rational point c + r ((1 - t^2) / (1 + t^2), 2 t / (1 + t^2)) (rotated by the quadrant) with t the nearest
/// multiple of 2^-24 to tan(phi / 2): exactly on the circle, within about 1e-7 r of equal spacing.
std::vector<Candidate> arc_length_candidates(const geometry::Shape& shape, long n);

/// The lattice points (i pitch, j pitch) on the boundary that are not polygon vertices (modular fixturing:
/// holes of a fixture plate), in boundary order. At most `max_lines` lattice lines are scanned (BudgetExceeded).
std::vector<Candidate> lattice_candidates(const geometry::Shape& shape, const geometry::Q& pitch,
                                          long max_lines = 1000000);
/// How many candidates lattice_candidates would give, counted without storing them (the same scan and budget).
long lattice_candidate_count(const geometry::Shape& shape, const geometry::Q& pitch, long max_lines = 1000000);

}  // namespace contactcert::solvers
