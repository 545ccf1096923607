// The "spatial_stability" certificate (issue 34; docs/formats.md section 5c) of solvers/spatial/spatial_stability.h's
// verdict, in lines: the head (scene, digest, wrench, verdict, resting and moving evidence) one member a line, then
// each distinct Motzkin vector once, written by the functionals it weighs (contact, and a letter's row naming the
// direction u of w_u = (u, r x u) up to sign), each dead prefix by its parent and its letter with the vector that
// proves it, and each moving mode with its vector. The tree reuses a dead prefix's vector on later prefixes weighing
// the same functionals, and the verdict a mode's vector on later modes (move_rows), so ~110 000 proofs at k = 16
// name ~1 600 vectors (the tree's proofs are sparse, spatial_modes.h: each is made dense once, for its line); the
// checker (checker/spatial_stability_check.h) verifies each vector's balance once and its signs on every row set it
// is applied to.
#pragma once

#include <string>

#include "solvers/spatial/spatial_stability.h"

namespace contactcert::solvers::spatial {

/// The certificate text of verdict r for wrench g on `scene` (read from scene_text, embedded verbatim).
std::string spatial_stability_certificate(const geometry::SpatialScene& scene, const std::string& scene_text,
                                          const Vec<Q>& g, const SpatialStability& r);

}  // namespace contactcert::solvers::spatial
