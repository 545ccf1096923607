// The "spatial_cone" certificate of a spatial mode's wrench cone (issue 34; docs/formats.md section 5), checked by
// checker/spatial_cone_check.h. With the mode's system A x = (0; g) of spatial_stability.h (x = vdot, the slacks
// sigma of its strict rows, the weights beta >= 0; the cone is { g : some x with sigma > 0 }, its closure C the same
// with sigma >= 0), the certificate holds, beside the cone in both forms (spatial_cone.h):
//   an empty cone: a Motzkin vector of the mode's kinematic rows (no vdot realises the letters);
//   else  - per ray r of the span form a point x with A x = (0; r), sigma >= 0, per line l two (l and -l):
//           pos(rays) + span(lines) lies in C;
//         - per row a of the face form a Motzkin vector of { A x - (0; g) = 0, a . g - t = 0 } with g free and
//           t > 0, sigma >= 0 (a . g <= 0 on C), for a strict row t >= 0, sigma > 0 (a . g < 0 on the cone), two per
//           equality (e and -e);
//         - "faces": per minimal face of C inside no strict row's hyperplane a point g of it (the sum of its rays)
//           with a point x, sigma > 0: the cone meets the face, so it holds the face's relative interior (the face
//           of Z above it has a point with sigma > 0, so its relative interior has), and with every such face it
//           holds each g of the face form with its strict rows (each lies in the relative interior of a face of C
//           that no strict row vanishes on, which contains a minimal one).
// The checker shows pos(rays) + span(lines) = { rows <= 0, equalities = 0 } itself, from the written numbers alone,
// and finds the minimal faces with its own enumeration.
#pragma once

#include <string>

#include "geometry/nnc_cone.h"
#include "geometry/spatial_scene.h"

namespace contactcert::solvers::spatial {

/// The certificate's text (one member or element a line) for `cone`, the wrench cone of `mode` in the scene
/// `scene_text` reads as. Past the deadline (checked between its LPs), exact::BudgetExceeded.
std::string spatial_cone_certificate(const std::string& scene_text, const geometry::SpatialScene& scene,
                                     const std::string& mode, const geometry::NncForm<exact::Q>& cone,
                                     const exact::Deadline& deadline = {});

}  // namespace contactcert::solvers::spatial
