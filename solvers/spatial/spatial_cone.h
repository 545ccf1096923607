// The wrench cone of a spatial contact mode (issue 34): the external wrenches g = (f, torque about the com) for which
// the mode's system of solvers/spatial/spatial_stability.h has a solution,
//     { g : exists vdot, sigma > 0, beta >= 0 with the mode's kinematic rows and M vdot - sum beta w(n + d) = g },
// the 6-D analogue of the wrench cone paper's eqs. (13)-(17). With vdot = v+ - v- (both >= 0) it is the cone
// { g : K z = P g, z >= 0, z_i > 0 on the strict slacks } of geometry/projection.h, projected by its polar route
// (the strict rows as exact limits, Theorem 1 with k -> 0+) and given in both forms (geometry/nnc_cone.h).
#pragma once

#include <string>

#include "geometry/nnc_cone.h"
#include "geometry/projection.h"
#include "geometry/spatial_scene.h"

namespace contactcert::solvers::spatial {

/// The problem K z = P g of a mode (one letter per contact): z = (v+, v-, the system's other columns), P = [0; I_6].
geometry::ProjectionProblem<exact::Q> spatial_cone_problem(const geometry::SpatialScene& scene,
                                                           const std::string& mode);

/// The mode's wrench cone in both forms (minimal face form with its strict rows, span form of the closure, the open
/// faces). Past the budget, exact::BudgetExceeded.
geometry::NncForm<exact::Q> spatial_wrench_cone(const geometry::SpatialScene& scene, const std::string& mode,
                                                const exact::DdBudget& budget = {});

}  // namespace contactcert::solvers::spatial
