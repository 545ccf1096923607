// Strict checks of numeric command-line options (SPEC section 6): a decimal integer within its range (no hex,
// octal, sign wrap or saturation, which the option parser's strtoll would allow) and a finite number of seconds.
#pragma once

#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdint>
#include <string>

namespace contactcert::cli {

/// Largest --time-limit accepted, in seconds (about 116 days): keeps the deadline's clock arithmetic exact.
inline constexpr double kMaxTimeLimit = 1e7;

/// The option's text is a decimal integer in [lo, hi].
template <class T>
CLI::Validator whole_number(T lo, T hi) {
  return CLI::Validator(
      [lo, hi](std::string& s) -> std::string {
        T v{};
        const char* end = s.data() + s.size();
        const auto [p, ec] = std::from_chars(s.data(), end, v);
        if (s.empty() || ec != std::errc() || p != end || v < lo || v > hi)
          return "expected a decimal integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", found \"" +
                 s + "\"";
        return "";
      },
      "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

/// The option's text is a finite number of seconds in [0, kMaxTimeLimit].
CLI::Validator seconds_in_range();

}  // namespace contactcert::cli
