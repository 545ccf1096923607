// The options every subcommand takes (cli/command.h), in the library so that every command's object links
// without main.cpp.
#include "cli/command.h"

#include <CLI/CLI.hpp>

namespace contactcert::cli {

void add_common_options(CLI::App& sub, CommonOptions& opts) {
  sub.add_flag("--json", opts.json, "Machine output: one JSON object on stdout");
  sub.add_option("--arith", opts.arith,
                 "exact: rationals only; float: doubles only, unchecked; verified: float checked and "
                 "if need be redone exactly; adaptive: double, intervals, MPFR, exact, climbed only as far as "
                 "needed (ucp; the other commands treat it as verified)")
      ->check(CLI::IsMember({"exact", "float", "verified", "adaptive"}))
      ->default_str("verified");
  sub.add_option("--time-limit", opts.time_limit, "Seconds of wall clock before the run stops with exit 3 (0 = none)")
      ->check(CLI::NonNegativeNumber)
      ->default_str("0");
}

}  // namespace contactcert::cli
