// The options every subcommand takes and the report of a query's limit (cli/command.h), in the library so that
// every command's object links without main.cpp.
#include "cli/command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli/option_checks.h"

namespace contactcert::cli {

void add_common_options(CLI::App& sub, CommonOptions& opts) {
  sub.add_flag("--json", opts.json, "Machine output: one JSON object on stdout");
  sub.add_option("--arith", opts.arith,
                 "exact: rationals only; float: doubles only, unchecked; verified: float checked and "
                 "if need be redone exactly; adaptive: double, intervals, MPFR, exact, climbed only as far as "
                 "needed (ucp; the other commands treat it as verified)")
      ->check(CLI::IsMember({"exact", "float", "verified", "adaptive"}))
      ->default_str("verified");
  add_time_limit(sub, opts.time_limit);
}

void add_time_limit(CLI::App& sub, double& seconds) {
  sub.add_option("--time-limit", seconds, "Seconds of wall clock before the run stops with exit 3 (0 = none)")
      ->check(seconds_in_range())
      ->default_str("0");
}

int report_limit(const std::string& command, const queries::Limit& limit, bool json) {
  switch (limit.kind) {
    case queries::Limit::Kind::kBudget:
      std::cerr << "contactcert: budget exceeded: " << limit.text() << "\n";
      break;
    case queries::Limit::Kind::kStopped:
      std::cerr << "contactcert: " << limit.text() << "\n";
      break;
    case queries::Limit::Kind::kUndecided:
      if (json)
        std::cout << nlohmann::json{{"status", "undecided"}, {"arith", "float"}, {"reason", limit.what}}.dump() << "\n";
      std::cerr << "contactcert: " << command << ": undecided in floating point: " << limit.what
                << "; rerun with --arith verified for an exact answer\n";
      break;
  }
  return 3;
}

void start_watchdog(const std::string& command, double limit) {
  const double grace = std::max(1.0, 0.05 * limit);
  std::thread([command, limit, grace] {
    std::this_thread::sleep_for(std::chrono::duration<double>(limit + grace));
    std::fprintf(stderr, "\ncontactcert: %s: time limit of %g s reached before an answer (stopped)\n", command.c_str(),
                 limit);
    std::_Exit(3);
  }).detach();
}

}  // namespace contactcert::cli
