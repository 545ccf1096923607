// The independent checker of the "modes" certificate (its format: solvers/stability/contact_modes.h).
#pragma once

#include <string>

#include "exact/json_input.h"

namespace contactcert::checker {

struct ModesCertificateCheck {
  bool valid = false;
  std::string reason;
  long modes = 0, dead = 0;
};

/// Verifies a "modes" certificate against its embedded scene: each listed acceleration realises its mode
/// (Table 2, exact signs), each dead prefix's certificate proves its kinematic rows infeasible (both with the
/// checker's own rows, table2_rows.h), and together they partition the mode strings (mode_coverage: no
/// string listed twice or inside a dead prefix, none missing), so the list is exactly the feasible modes, each
/// once, and its count is theirs. Malformed certificates (among them a Motzkin vector with a repeated or
/// out-of-range row, sparse_motzkin.h) throw InputError naming the field.
ModesCertificateCheck check_modes_certificate(const exact::JsonInput& certificate);

}  // namespace contactcert::checker
