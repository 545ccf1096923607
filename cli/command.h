// Shared pieces of the contactcert subcommands: options every command takes, the report of a limit, and
// registration.
#pragma once

#include <functional>
#include <string>

#include "queries/limit.h"
#include "queries/options.h"

namespace CLI {
class App;
}

namespace contactcert::cli {

using namespace queries;  // the front end names the query layer's writers unqualified

/// Options every subcommand takes (SPEC section 6).
struct CommonOptions {
  bool json = false;               ///< machine output: one JSON object on stdout
  std::string arith = "verified";  ///< exact | float | verified | adaptive
  double time_limit = 0;           ///< --time-limit seconds (0 = none); see main.cpp for how it is enforced
  /// The typed options of the query layer (queries/options.h).
  queries::CommonOptions query() const { return {queries::parse_arith(arith, "--arith"), time_limit}; }
};

/// A subcommand's work, run after parsing; returns the exit code.
using Action = std::function<int()>;

/// Adds --json, --arith and --time-limit to a subcommand.
void add_common_options(CLI::App& sub, CommonOptions& opts);
/// Adds --time-limit alone (a command whose query takes no arithmetic).
void add_time_limit(CLI::App& sub, double& seconds);

/// Reports the limit that stopped `command` (SPEC section 6) and returns its exit code, 3. On stderr: "budget
/// exceeded: WHAT (covered: ...)" (a budget inside the computation), "WHAT (covered: ...)" (the command's own
/// stop), or for a float run that cannot decide "COMMAND: undecided in floating point: WHY; rerun with --arith
/// verified ...", with `json` also {"status": "undecided", "arith": "float", "reason"} on stdout.
int report_limit(const std::string& command, const queries::Limit& limit, bool json);

/// Ends the process with exit code 3 if the command is still running `limit` seconds (+ grace) from now: the
/// backstop of --time-limit (main.cpp), and of a command's own default time budget.
void start_watchdog(const std::string& command, double limit);

/// A subcommand's registration: adds it to `app` and, when it is selected, stores its work in `action`.
using Register = void(CLI::App& app, Action& action);
/// One per subcommand (cli/<command>.cpp), in the order of `contactcert --help`.
Register register_demo, register_ucp, register_check, register_stability, register_insert, register_modes,
    register_cone, register_convert, register_bench, register_design, register_simulate, register_assembly;

}  // namespace contactcert::cli
