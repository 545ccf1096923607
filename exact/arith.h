// Which arithmetic answers a question (SPEC section 6, --arith).
#pragma once

#include <string>

namespace contactcert::exact {

/// kFloat: doubles only, unchecked; kExact: rationals only; kVerified: the float path proposes, exact
/// arithmetic checks and if need be redoes (the default).
enum class Arith { kFloat, kExact, kVerified };

/// "float" | "exact" | "verified" -> Arith (throws std::invalid_argument otherwise).
Arith parse_arith(const std::string& name);
const char* arith_name(Arith arith);

}  // namespace contactcert::exact
