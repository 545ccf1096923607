// The independent checker of strong stability verdicts and of the "stability" certificate (its format:
// solvers/stability/stability_certificate.h). Every system is rebuilt from the scene by the checker's own code
// (table2_rows.h, not the solver's motion_system.h) with the checker's own frames (frame_check.h); each vector is
// verified exactly and each proof accepted once (mode_coverage: no repeated or extra entry).
#pragma once

#include <string>

#include "exact/json_input.h"
#include "solvers/stability/strong_stability.h"

namespace contactcert::checker {

/// Independent exact check of a verdict's evidence against the scene and g: every system is rebuilt by the
/// checker's own code (table2_rows.h), not by motion_system.h.
/// Returns an empty string if valid, else the reason.
std::string check_stability(const geometry::PlanarScene& scene, const exact::Vec<exact::Q>& g,
                            const solvers::StabilityResult<exact::Q>& claim);

struct StabilityCertificateCheck {
  bool valid = false;
  std::string reason;
};

/// Verifies a "stability" certificate; malformed certificates throw InputError naming the field.
StabilityCertificateCheck check_stability_certificate(const exact::JsonInput& certificate);

}  // namespace contactcert::checker
