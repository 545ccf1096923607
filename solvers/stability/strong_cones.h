// The strongly stable set of a fixture as a union of convex cones in face form (wrench cone paper, section 7):
// the labelled cells of StableRegion grouped into few maximal convex cones, so a program can test membership
// against a few face cones instead of the whole arrangement.
#pragma once

#include <string>
#include <vector>

#include "geometry/face_cone.h"
#include "solvers/stability/stable_region.h"

namespace contactcert::solvers {

/// sign(p_j . g) for every plane p_j of the region, as a string over + 0 -.
std::string sign_vector(const StableRegion<Q>& region, const Vec<Q>& g);

/// One cone: a sign pattern with one letter per plane p_j of the region: + (p_j . g > 0), - (< 0), 0 (= 0),
/// P (>= 0), N (<= 0) or * (free); and its face form (section 4: strict rows for + and -, inequality rows for P
/// and N, equalities for 0). The set is an intersection of half-spaces, so convex, and a union of cells.
struct SignCone {
  std::string pattern;
  geometry::FaceCone<Q> cone;
};

/// The strongly stable set as a union of sign cones, each maximal: relaxing any letter of its pattern (to a
/// larger sign set) adds a cell that is not strongly stable, so no constraint of a cone is redundant (dropping
/// it would change the set). No two cones merge: the smallest pattern holding both (at each plane the signs
/// their cells take) holds a cell that is not strongly stable, so their union is not a sign cone. Cones may
/// overlap; none is covered by the others. Seeded by the strongly stable cells, highest dimension first.
/// g is strongly stable iff it lies in one of the cones.
std::vector<SignCone> strongly_stable_cones(const StableRegion<Q>& region);

}  // namespace contactcert::solvers
