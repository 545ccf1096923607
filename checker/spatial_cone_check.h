// The independent checker of the "spatial_cone" certificate (issue 34; docs/formats.md section 5; written by
// solvers/spatial/spatial_cone_certificate.h): the wrench cone of a spatial contact mode in both forms. Its own
// rows of the mode (spatial_rows.h: the kinematic rows and Newton-Euler, x = vdot, the slacks sigma, the weights
// beta), rebuilt from the embedded scene, and the written cone's numbers; nothing from the solver.
#pragma once

#include <string>

#include "exact/json_input.h"

namespace contactcert::checker {

struct SpatialConeCheck {
  bool valid = false;
  std::string reason;
  long dimension = -1, rays = 0, lines = 0, inequalities = 0, strict = 0;
};

/// Verifies a "spatial_cone" certificate exactly. Empty cone: the Motzkin vector proves the mode's kinematic rows
/// infeasible. Otherwise, with C the closure { g : A x = (0; g), sigma >= 0, beta >= 0 } and the cone its part with
/// sigma > 0: every ray and both senses of every line lie in C (their points x); every inequality row a has
/// a . g <= 0 on C and every strict row s . g < 0 on the cone, every equality e . g = 0 on C (Motzkin vectors of
/// the mode's rows with g free and one row a . g - t = 0); from the written numbers alone, pos(rays) + span(lines)
/// = { inequalities, strict rows <= 0, equalities = 0 }: every generator satisfies every row, the equalities span
/// the complement of the generators' span, each inequality is tight on generators of rank dimension - 1 (a facet),
/// and every facet of pos(rays) + span(lines) (each set of rays that with the lines spans a hyperplane leaving all
/// rays on one side) is tight for a written row; the open faces are the rays each strict row is tight on; and each
/// minimal face of the closure in no strict row's hyperplane (the checker's own enumeration of the faces) holds a
/// given point of the cone. So the closure is the written cone in both forms and the cone is exactly the face form
/// with its strict rows. Malformed certificates throw InputError naming the field.
SpatialConeCheck check_spatial_cone_certificate(const exact::JsonInput& certificate);

}  // namespace contactcert::checker
