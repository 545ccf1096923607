// The independent checker of the "modes" certificate (its format: solvers/stability/contact_modes.h).
#pragma once

#include <string>
#include <vector>

#include "checker/mode_letters.h"
#include "exact/json_input.h"

namespace contactcert::checker {

struct ModesCertificateCheck {
  bool valid = false;
  std::string reason;
  long modes = 0, dead = 0;
};

/// Verifies a "modes" certificate against its embedded scene: each listed acceleration realises its mode
/// (Table 2, exact signs), each dead prefix's certificate proves its kinematic rows infeasible (both with the
/// checker's own rows, table2_rows.h), and together they partition the mode strings (mode_coverage.h: no
/// string listed twice or inside a dead prefix, none missing), so the list is exactly the feasible modes, each
/// once, and its count is theirs. Malformed certificates (among them a Motzkin vector with a repeated or
/// out-of-range row, sparse_motzkin_reader.h) or a letter outside the alphabet (mode_letters.h) throw InputError naming
/// the field.
ModesCertificateCheck check_modes_certificate(const exact::JsonInput& certificate);

/// The verdict on the listed modes (`leaves`, each verified) and dead prefixes (each verified) of k contacts: valid
/// if they partition the mode strings over the alphabet (mode_coverage), else the gap.
ModesCertificateCheck modes_coverage_check(std::size_t k, const ModeAlphabet& alphabet,
                                           const std::vector<std::string>& dead,
                                           const std::vector<std::string>& leaves);
/// The same over any alphabet (mode_coverage's `letters`).
ModesCertificateCheck modes_coverage_check(std::size_t k, const std::function<std::string(std::size_t)>& letters,
                                           const std::vector<std::string>& dead,
                                           const std::vector<std::string>& leaves);

}  // namespace contactcert::checker
