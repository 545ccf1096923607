// The "assembly_stability" certificate of `contactcert assembly FILE --certificate F` and its reading for
// `contactcert check` (docs/formats.md, section 5). One JSON object: "kind": "assembly_stability", "verdict",
// "scene" (the assembly file's text, embedded verbatim so that the checker re-reads the bodies and contacts itself),
// "problem_sha256" (its canonical digest), and the evidence, exact strings (assembly_stability.h):
//   "resting": {"forces": [c_1n..c_kn, c_1t..c_kt]}  or  {"motzkin": [[row, w], ...]}  (the resting system's proof)
//   "moving":  {"mode", "acceleration": [vdot_0..vdot_{N-1}], "forces"}                (a solution with vdot != 0)
//   "contact_order": [i_1, ..., i_k]            (the walk's order of the contacts, if not the file's: letter j of a
//                                                 prefix is contact i_j's; written only where a prefix has letters)
//   "dead":    [{"prefix", "motzkin"}, ...]      (strongly stable: prefixes over s l r n whose systems have none)
// Motzkin vectors are sparse (solvers/stability/sparse_motzkin.h) over the rows of docs/formats.md section 3a's
// systems; the checker (checker/assembly_check.h) rebuilds every system with its own code and verifies each vector.
#pragma once

#include <string>

#include "exact/json_input.h"
#include "solvers/assembly/assembly_stability.h"

namespace contactcert::solvers::assembly {

/// The certificate of a decided verdict `r` on the assembly of `scene_text`, as JSON text.
std::string assembly_certificate(const std::string& scene_text, const AssemblyStabilityResult& r);

}  // namespace contactcert::solvers::assembly
