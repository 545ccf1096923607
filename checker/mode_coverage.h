// Whether listed mode prefixes partition the modes of k fixels (Table 2's letters, mode_letters.h): the completeness
// half of a mode tree's certificate (modes, assembly_modes, and the proofs of a stability certificate). Each mode
// must extend exactly one dead prefix or equal exactly one listed mode; the walk visits only the prefixes of
// listed strings, so a forged list is rejected in time linear in its size.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "checker/mode_letters.h"

namespace contactcert::checker {

/// Why listed prefixes do not partition the modes: a mode prefix that no listed string accounts for
/// (kMissing), a string listed twice (kRepeated), or a listed string that extends another one (kInside: its
/// modes are already accounted for, so a count of the list would count them twice).
struct CoverageGap {
  enum class Kind { kMissing, kRepeated, kInside };
  Kind kind;
  std::string prefix;  ///< the prefix no string accounts for, the repeated string, or the string inside another
  std::string within;  ///< kInside: the listed string that `prefix` extends
};

/// Whether the listed prefixes partition the modes of k fixels over the alphabet: each mode extends exactly one
/// `dead` prefix or equals exactly one `leaves` mode, and no listed string is listed twice or extends another.
/// Walks only the prefixes of listed strings, at most (total length of the lists) x (letters per fixel) of them,
/// so a forged list is rejected in time linear in its size. Returns nullopt if they do, else the first gap found.
std::optional<CoverageGap> mode_coverage(std::size_t k, const ModeAlphabet& alphabet,
                                         const std::vector<std::string>& dead, const std::vector<std::string>& leaves);
/// The same over any alphabet: `letters(i)` is the letters of contact i, one char each (the spatial modes,
/// spatial_modes_check.h).
std::optional<CoverageGap> mode_coverage(std::size_t k, const std::function<std::string(std::size_t)>& letters,
                                         const std::vector<std::string>& dead, const std::vector<std::string>& leaves);

/// The gap as a checker's reason.
std::string coverage_gap_text(const CoverageGap& gap);

}  // namespace contactcert::checker
