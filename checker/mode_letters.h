// The mode letters of a certificate as the checker reads them (Table 2; SPEC section 5): one letter per fixel (or
// contact), each from the letters its fixel admits: a touching fixel s l r n, a gap s a, with the unions also m and
// u, and S (s as Table 2 prints it) where a certificate may spell it. One reader for every certificate kind that
// lists modes or prefixes (modes, assembly_modes, stability, cone_*), so that a letter is refused in one wording.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "exact/json_input.h"

namespace contactcert::checker {

/// The letters each fixel admits, in the order the coverage walk tries them (mode_coverage.h).
struct ModeAlphabet {
  std::vector<bool> touching;  ///< per fixel; empty: every fixel touches
  bool unions = false;         ///< also m at a touching fixel and u at a gap
  bool printed = false;        ///< also S at every fixel (a cone's mode as Table 2 prints s)
  /// touching: s l r n (m) (S); gap: s a (u) (S).
  std::string letters(std::size_t fixel) const;
};

/// The letters of `j`: a mode (exactly k letters) or, with `prefix`, a prefix of one (1 to k letters), each one of
/// its fixel's letters in the alphabet. InputError naming `j` otherwise.
std::string read_mode_letters(const exact::JsonInput& j, const ModeAlphabet& alphabet, std::size_t k, bool prefix);

}  // namespace contactcert::checker
