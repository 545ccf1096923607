// The independent checker of the "assembly_modes" certificate (its format: solvers/assembly/assembly_modes.h), with
// the checker's own relative accelerations (assembly_check.h checked_accelerations, from frames it re-verifies),
// never the solver's J.
#pragma once

#include "checker/modes_check.h"
#include "exact/json_input.h"

namespace contactcert::checker {

/// Verifies an "assembly_modes" certificate against its embedded assembly: each acceleration realises its mode by
/// Table 2's signs, each dead prefix's vector is a Motzkin certificate of the prefix's kinematic rows (layout:
/// vdot's 3N columns, then one slack per signed row, > 0, in contact order; per contact s: a_n - sigma = 0, l:
/// a_n = 0 and a_t - sigma = 0, r: a_n = 0 and a_t + sigma = 0, n: a_n = 0 and a_t = 0), and together they partition
/// the mode strings (modes_coverage_check). A malformed certificate throws InputError naming the field.
ModesCertificateCheck check_assembly_modes_certificate(const exact::JsonInput& certificate);

}  // namespace contactcert::checker
