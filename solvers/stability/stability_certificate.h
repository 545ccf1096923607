// The "stability" certificate of `contactcert stability --certificate FILE` (its checker: checker/stability_check.h).
// One JSON object: "kind": "stability", "scene" (the scene file's text, embedded verbatim so the checker
// re-reads the problem itself), "wrench" [fx, fy, tz], "verdict", and the evidence (exact strings):
//   "resting": {"forces": [c_1n..c_kn, c_1t..c_kt]}  or  {"motzkin": [[row, w], ...]}  (J c + g = 0, or not)
//   "moving":  {"mode", "forces", "acceleration"}                               (a solution with vdot != 0)
//   "proofs":  [{"mode", "kinematic", "motzkin": [...]}, ...]    (strongly stable: the mode tree's dead prefixes,
//              "kinematic": true, "mode" a prefix; then each feasible moving mode's proof for g; mode_tree.h)
// Motzkin vectors are sparse (sparse_motzkin.h). The checker rebuilds every system from the scene with its own
// code (checker/table2_rows.h, not the solver's motion_system.h), verifies each vector exactly, and accepts each
// proof once (mode_coverage: no repeated or extra entry).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "exact/json_input.h"
#include "solvers/stability/strong_stability.h"

namespace contactcert::solvers {

/// The members a verdict's certificate starts with (also "spatial_stability", solvers/spatial/spatial_stability.h):
/// "kind", "verdict", "wrench" and "scene" (exact strings), "problem_sha256" (the scene's canonical digest).
nlohmann::ordered_json stability_certificate_head(const char* kind, StabilityVerdict v, const std::string& scene_text,
                                                  const Vec<Q>& g);
/// A vector as a JSON array of exact strings.
nlohmann::ordered_json exact_strings(const Vec<Q>& v);

/// The certificate as a JSON value.
nlohmann::ordered_json stability_certificate_json(const std::string& scene_text, const Vec<Q>& g,
                                                  const StabilityResult<Q>& result);
/// The same as JSON text (one member or element per line).
std::string stability_certificate(const std::string& scene_text, const Vec<Q>& g, const StabilityResult<Q>& result);

}  // namespace contactcert::solvers
