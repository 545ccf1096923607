#include "exact/arith.h"

#include <stdexcept>

namespace contactcert::exact {

Arith parse_arith(const std::string& name) {
  if (name == "float") return Arith::kFloat;
  if (name == "exact") return Arith::kExact;
  if (name == "verified") return Arith::kVerified;
  throw std::invalid_argument("arithmetic must be exact, float or verified, not \"" + name + "\"");
}

const char* arith_name(Arith arith) {
  switch (arith) {
    case Arith::kFloat: return "float";
    case Arith::kExact: return "exact";
    case Arith::kVerified: return "verified";
  }
  return "?";
}

}  // namespace contactcert::exact
