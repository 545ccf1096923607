// The independent checker of the "motion_uniqueness" certificate of a step's uniqueness verdict (its format:
// solvers/motion/uniqueness_certificate.h). It re-derives X, Y, P and h from the embedded problem with its own code
// (ucp_sets.h; with several bodies the problem from the embedded assembly, assembly_ucp_check.h), sets each mode's
// zeros from its letters itself, and re-walks the prefix tree over the 4 letters per contact (mode_coverage.h), so
// that a dropped branch, a wrong Farkas vector, a bound that does not hold or a witness outside its face is caught.
#pragma once

#include <string>

#include "exact/json_input.h"

namespace contactcert::checker {

struct UniquenessCertificateCheck {
  bool valid = false;
  std::string reason;
  std::string verdict;  ///< "unique" or "not_unique", as the certificate states it
  long solution_modes = 0, dead = 0;
};

/// Verifies a motion_uniqueness certificate. `unique`: every dead prefix's Farkas vector proves its face of X or Y
/// empty, every listed solution mode's points lie in its faces, together they partition the 4^nc modes, and every
/// solution mode's face of X lies in a bounded mode's face whose duals pin each q_dot_k to the stated motion (weak LP
/// duality), so every solution has that q_dot. `not_unique`: two solutions (u, x, y) of the problem, each in its
/// mode's faces, with different q_dot. A malformed certificate (a field missing or of the wrong shape, a letter
/// outside s r + - ?, more than 10^7 (solution mode, bound) pairs to compare) throws InputError naming the field.
UniquenessCertificateCheck check_uniqueness_certificate(const exact::JsonInput& certificate);

}  // namespace contactcert::checker
