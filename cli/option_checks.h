// Strict checks of command-line options (SPEC section 6): a decimal integer within its range (no hex, octal, sign,
// exponent, blank or saturation, which the option parser's strtoll would allow) and a finite, plain decimal number
// of seconds; and the refusal of an option that the chosen mode of a command would ignore. Python's entry points
// apply the same rules (python/contactcert/_options.py, with kMaxTimeLimit from the extension).
#pragma once

#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <type_traits>

#include "exact/json_input.h"
#include "queries/options.h"

namespace contactcert::cli {

using queries::kMaxTimeLimit;  ///< the largest --time-limit accepted

/// The option's text is a decimal integer in [lo, hi]: digits only, with a '-' only where lo < 0.
template <class T>
CLI::Validator whole_number(T lo, T hi) {
  return CLI::Validator(
      [lo, hi](std::string& s) -> std::string {
        T v{};
        const char* end = s.data() + s.size();
        const auto [p, ec] = std::from_chars(s.data(), end, v);
        bool sign_allowed = false;  // "-0" is not a spelling of a count
        if constexpr (std::is_signed_v<T>) sign_allowed = lo < 0;
        if (s.empty() || ec != std::errc() || p != end || v < lo || v > hi || (s.front() == '-' && !sign_allowed))
          return "expected a decimal integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", found " +
                 exact::quoted_excerpt(s);
        return "";
      },
      "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

/// The option's text is a number of seconds in [0, kMaxTimeLimit] written as plain decimal digits with an optional
/// fraction and exponent ("30", "0.5", "1e3"): no sign, hex, "inf", "nan" or blanks.
CLI::Validator seconds_in_range();

/// Throws InputError naming the first of `options` given on the command line of `sub`, which the run as asked
/// would ignore: "`why`" says why (e.g. "--wrenches writes no certificate").
void refuse_given(const CLI::App& sub, std::initializer_list<const char*> options, const std::string& why);

}  // namespace contactcert::cli
