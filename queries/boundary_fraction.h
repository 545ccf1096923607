// How much of the workpiece boundary a set of pushes covers (Figure 11's measure of G_goal).
#pragma once

#include "geometry/planar_scene.h"
#include "solvers/stability/finger_push.h"

namespace contactcert::queries {

/// The fraction of the boundary (by length on a polygon, by angle on a disk; in doubles: a summary, not a
/// verdict) on the pieces labelled true.
double boundary_fraction(const geometry::PlanarScene& scene, const solvers::BoundaryPieces<exact::Q, bool>& p);

}  // namespace contactcert::queries
