// The independent checker of the "spatial_modes" certificate (issue 34; its format: docs/formats.md section 5b). Its
// own reading of a contact from rest: the contact point's acceleration is A vdot = a + alpha x r (r = p - com), a
// world vector, and the letters read it directly: s if n . A vdot > 0; f if A vdot = 0; a sliding letter if
// n . A vdot = 0, A vdot != 0 and the pyramid edges d_j minimising d_j . A vdot are edge j alone (letter 2j) or edges
// j and j + 1 (letter 2j + 1): the maximal-dissipation law read globally, over all edges.
#pragma once

#include "checker/certificate_lines.h"
#include "checker/modes_check.h"

namespace contactcert::checker {

/// Verifies a "spatial_modes" certificate against its embedded scene: each listed acceleration realises its mode,
/// each dead prefix's vector proves its rows infeasible (the rows of solvers/spatial/spatial_modes.h's table,
/// rebuilt here from the scene; spatial_proofs.h), and together they partition the mode strings (mode_coverage). The
/// certificate is read in lines (certificate_lines.h: its members, then the lists "vectors", "dead" and "modes" one
/// element a line, each parsed alone); a malformed one throws InputError naming the line and the field.
ModesCertificateCheck check_spatial_modes_certificate(const CertificateLines& certificate);

}  // namespace contactcert::checker
