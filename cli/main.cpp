// contactcert: exact answers for planar rigid bodies in frictional contact.
// Exit codes (SPEC section 6): 0 success, 1 internal error, 2 bad input or usage, 3 budget exceeded.
//
// --time-limit: commands with a search loop (ucp) test the deadline between units of work and end with
// `unknown`, exit 3 and what they covered. As a backstop for every command, a watchdog thread ends the
// process with exit 3 shortly after the limit (a 5% grace, at least one second, lets the loops report first).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <thread>

#include "cli/command.h"
#include "exact/input_error.h"

#ifndef CONTACTCERT_VERSION
#define CONTACTCERT_VERSION "unknown"
#endif

namespace contactcert::cli {
namespace {

/// Ends the process with exit code 3 if the command is still running `limit` seconds (+ grace) from now.
void start_watchdog(const std::string& command, double limit) {
  const double grace = std::max(1.0, 0.05 * limit);
  std::thread([command, limit, grace] {
    std::this_thread::sleep_for(std::chrono::duration<double>(limit + grace));
    std::fprintf(stderr, "\ncontactcert: %s: time limit of %g s reached before an answer (stopped)\n",
                 command.c_str(), limit);
    std::_Exit(3);
  }).detach();
}

}  // namespace

}  // namespace contactcert::cli

int main(int argc, char** argv) {
  using namespace contactcert;
  CLI::App app{
      "contactcert " CONTACTCERT_VERSION
      ": exact answers for planar rigid bodies in frictional contact.\n"
      "Quasistatic contact problems (Pang, Trinkle, Lo 1994) solved or proven jammed; wrench cones, strong\n"
      "stability and sensorless insertion (Balkcom, Trinkle 2002) computed in rational arithmetic.",
      "contactcert"};
  app.set_version_flag("--version", "contactcert " CONTACTCERT_VERSION);
  app.require_subcommand(1);
  cli::Action action;
  cli::register_demo(app, action);
  cli::register_ucp(app, action);
  cli::register_check(app, action);
  cli::register_stability(app, action);
  cli::register_insert(app, action);
  cli::register_modes(app, action);
  cli::register_cone(app, action);
  cli::register_convert(app, action);
  cli::register_bench(app, action);
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
    return action ? action() : 0;
  } catch (const exact::InputError& e) {
    std::cerr << "contactcert: " << e.what() << "\n";
    return 2;
  } catch (const exact::BudgetExceeded& e) {
    std::cerr << "contactcert: budget exceeded: " << e.what() << " (covered: " << e.covered << ")\n";
    return 3;
  } catch (const std::bad_alloc&) {
    std::cerr << "contactcert: out of memory\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "contactcert: internal error: " << e.what() << "\n";
    return 1;
  }
}
