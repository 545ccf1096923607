// Which arithmetic answers a question (SPEC section 6, --arith).
#pragma once

#include <string>
#include <vector>

namespace contactcert::exact {

/// kFloat: doubles only, unchecked; kExact: rationals only; kVerified: the float path proposes, exact
/// arithmetic checks and if need be redoes (the default); kAdaptive: the precision ladder (double, intervals,
/// MPFR, exact) climbed only as far as the instance needs, every answer checked exactly (docs/precision.md).
enum class Arith { kFloat, kExact, kVerified, kAdaptive };

/// "float" | "exact" | "verified" | "adaptive" -> Arith (throws std::invalid_argument otherwise).
Arith parse_arith(const std::string& name);
const char* arith_name(Arith arith);

/// One rung of the precision ladder: doubles, double intervals, MPFR floats of `bits` bits, rationals.
struct Rung {
  enum class Kind { kDouble, kInterval, kMpfr, kExact };
  Kind kind = Kind::kDouble;
  long bits = 0;  ///< kMpfr only
  bool operator==(const Rung&) const = default;
};

/// "double", "interval", "mpfr113", "exact".
std::string rung_name(Rung rung);

/// The rungs --arith adaptive climbs: double, intervals, MPFR at 113 and 256 bits, exact.
const std::vector<Rung>& adaptive_ladder();

}  // namespace contactcert::exact
