#include "cli/option_checks.h"

#include <cmath>
#include <cstdlib>

namespace contactcert::cli {

CLI::Validator seconds_in_range() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        const bool decimal = s.find_first_not_of("0123456789.eE+-") == std::string::npos;  // no hex, no "inf"
        if (s.empty() || !decimal || end != s.c_str() + s.size() || !std::isfinite(v) || v < 0 || v > kMaxTimeLimit)
          return "expected a number of seconds from 0 to 1e7, found \"" + s + "\"";
        return "";
      },
      "SECONDS in [0, 1e7]");
}

}  // namespace contactcert::cli
