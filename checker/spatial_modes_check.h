// The independent checker of the "spatial_modes" certificate (issue 34; its format: docs/formats.md section 5b). Its
// own reading of a contact from rest: the contact point's acceleration is A vdot = a + alpha x r (r = p - com), a
// world vector, and the letters read it directly: s if n . A vdot > 0; f if A vdot = 0; a sliding letter if
// n . A vdot = 0, A vdot != 0 and the pyramid edges d_j minimising d_j . A vdot are edge j alone (letter 2j) or edges
// j and j + 1 (letter 2j + 1): the maximal-dissipation law read globally, over all edges.
#pragma once

#include "checker/modes_check.h"
#include "exact/json_input.h"

namespace contactcert::checker {

/// Verifies a "spatial_modes" certificate against its embedded scene: each listed acceleration realises its mode,
/// each dead prefix's Motzkin vector proves its rows infeasible (the rows of solvers/spatial/spatial_modes.h's
/// table, rebuilt here from the scene), and together they partition the mode strings (mode_coverage). Malformed
/// certificates throw InputError naming the field.
ModesCertificateCheck check_spatial_modes_certificate(const exact::JsonInput& certificate);

}  // namespace contactcert::checker
