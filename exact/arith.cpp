#include "exact/arith.h"

#include <stdexcept>

namespace contactcert::exact {

Arith parse_arith(const std::string& name) {
  if (name == "float") return Arith::kFloat;
  if (name == "exact") return Arith::kExact;
  if (name == "verified") return Arith::kVerified;
  if (name == "adaptive") return Arith::kAdaptive;
  throw std::invalid_argument("arithmetic must be exact, float, verified or adaptive, not \"" + name + "\"");
}

const char* arith_name(Arith arith) {
  switch (arith) {
    case Arith::kFloat:
      return "float";
    case Arith::kExact:
      return "exact";
    case Arith::kVerified:
      return "verified";
    case Arith::kAdaptive:
      return "adaptive";
  }
  return "?";
}

std::string rung_name(Rung rung) {
  switch (rung.kind) {
    case Rung::Kind::kDouble:
      return "double";
    case Rung::Kind::kInterval:
      return "interval";
    case Rung::Kind::kMpfr:
      return "mpfr" + std::to_string(rung.bits);
    case Rung::Kind::kExact:
      return "exact";
  }
  return "?";
}

const std::vector<Rung>& adaptive_ladder() {
  static const std::vector<Rung> ladder{{Rung::Kind::kDouble, 0},
                                        {Rung::Kind::kInterval, 0},
                                        {Rung::Kind::kMpfr, 113},
                                        {Rung::Kind::kMpfr, 256},
                                        {Rung::Kind::kExact, 0}};
  return ladder;
}

}  // namespace contactcert::exact
