#include "cli/option_checks.h"

#include <cmath>
#include <cstdlib>

#include "exact/input_error.h"
#include "exact/json_input.h"

namespace contactcert::cli {
namespace {

/// digits [. digits] [e|E [+|-] digits], at least one digit before the exponent.
bool plain_decimal(const std::string& s) {
  std::size_t i = 0, mantissa = 0;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i - from;
  };
  mantissa += digits();
  if (i < s.size() && s[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == s.size();
}

}  // namespace

CLI::Validator seconds_in_range() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        const double v = plain_decimal(s) ? std::strtod(s.c_str(), nullptr) : -1;
        if (!std::isfinite(v) || v < 0 || v > kMaxTimeLimit)
          return "expected a number of seconds from 0 to 1e7, found " + exact::quoted_excerpt(s);
        return "";
      },
      "SECONDS in [0, 1e7]");
}

void refuse_given(const CLI::App& sub, std::initializer_list<const char*> options, const std::string& why) {
  for (const char* name : options)
    if (const CLI::Option* o = sub.get_option_no_throw(name); o != nullptr && o->count() > 0)
      throw exact::InputError("command line", name, why);
}

}  // namespace contactcert::cli
