// `contactcert check FILE [--problem PROBLEM]`: independent verification of a certificate by the checker module
// (queries/check.h), printed. Exit 0: VALID; exit 2: INVALID (or a malformed certificate).
#include "queries/check.h"

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>

#include "cli/command.h"
#include "exact/input_error.h"
#include "exact/json_input.h"

namespace contactcert::cli {
namespace {

struct CheckOptions {
  CommonOptions common;
  std::string file;
  std::string problem;
};

int run_check(const CheckOptions& o) {
  const std::string cert = exact::JsonInput::read_text(o.file);
  std::optional<exact::JsonInput> problem;
  if (!o.problem.empty()) problem = exact::JsonInput::load(o.problem);
  // A checker re-derives cones and LPs under the solvers' budgets: one that runs out is the command's limit.
  const Limited<queries::CheckResult> r = with_limits(
      o.common.query().arith, [&] { return queries::check_text(cert, o.file, problem ? &*problem : nullptr); });
  if (!r) return report_limit("check", r.limit(), o.common.json);
  const queries::CheckResult& c = *r;
  if (o.common.json) {
    std::cout << queries::to_json(c).dump() << "\n";
  } else {
    std::cout << "check " << o.file << ": " << c.kind << " certificate is " << (c.valid() ? "VALID" : "INVALID")
              << (o.problem.empty() || !c.valid() ? "" : " for " + o.problem) << "\n  " << c.reason << "\n"
              << (c.valid() ? c.text : "") << "  problem sha256 " << c.digest << "\n";
  }
  return c.valid() ? 0 : 2;
}

}  // namespace

void register_check(CLI::App& app, Action& action) {
  auto o = std::make_shared<CheckOptions>();
  CLI::App* sub = app.add_subcommand(
      "check", "Verify a certificate written by ucp, stability, modes, cone or design, independently");
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Certificate file")->required();
  sub->add_option("--problem", o->problem,
                  "Problem, scene or assembly file the certificate must be about: INVALID if its embedded problem differs");
  sub->callback([o, &action] {
    // The checkers re-derive everything in rationals: a float check would be ignored, so it is refused.
    if (o->common.arith == "float")
      throw exact::InputError("command line", "--arith", "check verifies exactly (use exact or verified)");
    action = [o] { return run_check(*o); };
  });
}

}  // namespace contactcert::cli
