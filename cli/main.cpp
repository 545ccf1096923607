// contactcert: exact answers for planar rigid bodies in frictional contact.
// Exit codes (SPEC section 6): 0 success, 1 internal error, 2 bad input or usage (also: an output that cannot be
// written, an INVALID certificate), 3 budget exceeded (also: out of memory, a float run that cannot decide).
//
// A query's limit (a budget, the time limit, a float run that cannot decide) is its answer's status, which each
// command reports through report_limit (cli/command.h); what reaches the handlers below is input, memory or a bug.
//
// Out of memory, in GMP as elsewhere, is exit 3 "out of memory": GMP allocates through functions that throw
// std::bad_alloc (its default ones abort; runtime/memory.h).
//
// --time-limit: commands with a search loop (ucp) test the deadline between units of work and end with
// `unknown`, exit 3 and what they covered. As a backstop for every command, a watchdog thread ends the
// process with exit 3 shortly after the limit (a 5% grace, at least one second, lets the loops report first).
// Every subcommand takes the option: those that do not register it themselves get it here.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <new>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "exact/input_error.h"
#include "runtime/memory.h"

#ifndef CONTACTCERT_VERSION
#define CONTACTCERT_VERSION "unknown"
#endif

namespace contactcert::cli {
namespace {

double no_time_limit = 0;  // --time-limit of the subcommands that do not register it themselves

}  // namespace
}  // namespace contactcert::cli

int main(int argc, char** argv) {
  using namespace contactcert;
  runtime::keep_heap_until_exit();
  runtime::use_pooled_gmp_memory();
  CLI::App app{"contactcert " CONTACTCERT_VERSION
               ": exact answers for planar rigid bodies in frictional contact.\n"
               "Quasistatic contact problems (Pang, Trinkle, Lo 1994) solved or proven jammed; wrench cones, strong\n"
               "stability and sensorless insertion (Balkcom, Trinkle 2002) computed in rational arithmetic.",
               "contactcert"};
  app.set_version_flag("--version", "contactcert " CONTACTCERT_VERSION);
  app.require_subcommand(1);
  cli::Action action;
  for (cli::Register* add : {cli::register_demo, cli::register_ucp, cli::register_check, cli::register_stability,
                             cli::register_insert, cli::register_modes, cli::register_cone, cli::register_convert,
                             cli::register_bench, cli::register_design, cli::register_simulate, cli::register_assembly})
    add(app, action);
  for (CLI::App* sub : app.get_subcommands({}))
    if (sub->get_option_no_throw("--time-limit") == nullptr)
      sub->add_option("--time-limit", cli::no_time_limit,
                      "Seconds of wall clock before the run stops with exit 3 (0 = none)")
          ->check(cli::seconds_in_range())
          ->default_str("0");
  int code = 0;
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "contactcert: " << e.what() << " (run with --help for usage)\n";  // one line, exit 2
    return 2;
  } catch (const exact::InputError& e) {
    std::cerr << "contactcert: " << e.what() << "\n";
    return 2;
  }
  for (const CLI::App* sub : app.get_subcommands()) {
    const CLI::Option* limit = sub->get_option_no_throw("--time-limit");
    if (limit != nullptr && limit->count() > 0 && limit->as<double>() > 0)
      cli::start_watchdog(sub->get_name(), limit->as<double>());
  }
  try {
    code = action ? action() : 0;
  } catch (const exact::InputError& e) {
    std::cerr << "contactcert: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "contactcert: out of memory\n";
    return 3;
  } catch (const nlohmann::json::type_error& e) {
    // JSON text is UTF-8; input files are checked when read, so only a command-line text (a file name echoed in
    // the --json output) can bring other bytes. Other type errors are internal.
    if (e.id != 316) {
      std::cerr << "contactcert: internal error: a JSON value of an unexpected type\n";
      return 1;
    }
    std::cerr << "contactcert: command line: a text given on it (a file name?) is not UTF-8, which the JSON output "
                 "cannot hold\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "contactcert: internal error: " << e.what() << "\n";
    return 1;
  }
  if (!std::cout.flush()) {
    std::cerr << "contactcert: standard output: cannot write the output\n";
    return 2;
  }
  return code;
}
