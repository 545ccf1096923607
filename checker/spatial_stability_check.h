// The independent checker of the "spatial_stability" certificate (issue 34; docs/formats.md section 5; written by
// solvers/spatial/spatial_stability.h). Its own model of a body in space from rest (spatial_rows.h), with its own
// Newton-Euler rows: M vdot = g + sum_ij beta_ij (u_ij, r_i x u_ij), u_ij = n_i + d_ij, M = diag(m, m, m, I),
// beta_ij >= 0 and zero off the edges each letter allows (s none, f all, 2j edge j, 2j + 1 edges j and j + 1).
#pragma once

#include "checker/certificate_lines.h"
#include "checker/stability_check.h"
#include "exact/json_input.h"

namespace contactcert::checker {

/// Verifies a "spatial_stability" certificate against its embedded scene: the resting weights balance g (or the
/// Motzkin vector proves that none do), the moving witness realises its mode (read directly from the contact
/// accelerations), moves, and satisfies Newton-Euler with forces its letters allow; a strongly stable verdict's
/// proofs (dead prefixes, each for every g, and one per moving mode for g) cover every moving mode (mode_coverage;
/// f..f needs none beside a resting solution). The certificate is read in lines (certificate_lines.h: its members,
/// then the lists "vectors", "dead" and "modes" one element a line, each parsed alone); a malformed one throws
/// InputError naming the line and the field.
StabilityCertificateCheck check_spatial_stability_certificate(const CertificateLines& certificate);

}  // namespace contactcert::checker
