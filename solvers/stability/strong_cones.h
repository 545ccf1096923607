// The strongly stable set of a fixture as a union of convex cones in face form (wrench cone paper, section 7):
// the labelled cells of StableRegion merged where the union stays convex, so a program can test membership
// against a few face cones instead of the whole arrangement.
#pragma once

#include <string>
#include <vector>

#include "geometry/face_cone.h"
#include "solvers/stability/stable_region.h"

namespace contactcert::solvers {

/// sign(p_j . g) for every plane p_j of the region, as a string over + 0 -.
std::string sign_vector(const StableRegion<Q>& region, const Vec<Q>& g);

/// One merged cone: a sign pattern over + 0 - * (* = plane free) and its face form (strict rows for + and -,
/// equalities for 0; not minimal).
struct SignCone {
  std::string pattern;
  geometry::FaceCone<Q> cone;
};

/// The strongly stable cells merged: two patterns that differ only at plane k, + and -, merge with the pattern
/// between them (0 at k) into one with * at k when all three are strongly stable (their union is the set cut
/// out by the remaining constraints, convex). g is strongly stable iff it lies in one of the cones.
std::vector<SignCone> strongly_stable_cones(const StableRegion<Q>& region);

}  // namespace contactcert::solvers
