// `contactcert assembly FILE`: the questions on an assembly of several bodies (docs/formats.md section 3a) through
// the query layer (queries/assembly_query.h): stability from rest under the bodies' loads (strongly stable, weakly
// stable or unstable, with a witness or a certificate), or with --ucp Pang, Trinkle and Lo's quasistatic problem for
// N bodies (with --all: is the bodies' motion unique?). Exit 3 when a budget runs out before an answer.
#include <CLI/CLI.hpp>
#include <iostream>
#include <limits>

#include "cli/assembly_answers.h"
#include "cli/command.h"
#include "cli/option_checks.h"
#include "queries/assembly_query.h"
#include "queries/ucp_query.h"
#include "solvers/motion/simulate.h"

namespace contactcert::cli {

int print_assembly_answer(const queries::Limited<queries::AssemblyStabilityAnswer>& r, const std::string& file,
                          bool json, const std::string& command) {
  if (!r) return report_limit(command, r.limit(), json);
  if (const auto limit = queries::limit_of(*r)) return report_limit(command, *limit, json);
  std::cout << (json ? queries::to_json(*r).dump() + "\n" : queries::to_text(*r, file));
  return 0;
}

int print_assembly_answer(const queries::Limited<queries::AssemblyUcpAnswer>& r, const std::string& file, bool json,
                          const std::string& command) {
  if (!r) return report_limit(command, r.limit(), json);
  const queries::AssemblyUcpAnswer& a = *r;
  if (const auto limit = queries::limit_of(a.report)) return report_limit(command, *limit, json);
  std::cout << (json ? queries::to_json(a).dump() + "\n" : queries::to_text(a, file));
  return a.report.status == solvers::ucp::UcpStatus::kUnknown ? 3 : 0;
}

int print_assembly_answer(const queries::Limited<queries::AssemblyModesAnswer>& r, const std::string& file, bool json,
                          const std::string& command) {
  if (!r) return report_limit(command, r.limit(), json);
  const queries::AssemblyModesAnswer& a = *r;
  std::cout << (json ? queries::to_json(a).dump() + "\n" : queries::to_text(a, file));
  return 0;
}

namespace {

struct AssemblyCliOptions {
  CommonOptions common;
  std::string file;
  bool ucp = false;
  long max_nodes = 0;  ///< 0: the query's default (it differs between the questions)
  long max_bases = 0;
  std::string certificate, svg;
  long max_modes = solvers::motion::SimulateOptions{}.max_uniqueness_modes;  // shown as the default; unset unless given
  queries::UniquenessOptions uniqueness;  ///< --ucp --all; its max_modes set from the above by the callback
};

int run_assembly(const AssemblyCliOptions& o) {
  const queries::AssemblyInput in = queries::load_assembly(o.file);
  if (o.ucp) {
    queries::AssemblyUcpOptions q;
    q.common = o.common.query();
    if (o.max_nodes > 0) q.max_nodes = o.max_nodes;
    if (o.max_bases > 0) q.max_bases = o.max_bases;
    q.certificate = o.certificate;
    q.svg = o.svg;
    q.uniqueness = o.uniqueness;
    return print_assembly_answer(queries::run_assembly_ucp(in, q), o.file, o.common.json, "assembly");
  }
  queries::AssemblyStabilityOptions q;
  q.common = o.common.query();
  if (o.max_nodes > 0) q.max_nodes = o.max_nodes;
  q.certificate = o.certificate;
  q.svg = o.svg;
  return print_assembly_answer(queries::run_assembly_stability(in, q), o.file, o.common.json, "assembly");
}

}  // namespace

void register_assembly(CLI::App& app, Action& action) {
  auto o = std::make_shared<AssemblyCliOptions>();
  CLI::App* sub = app.add_subcommand("assembly",
                                     "Several bodies: is the assembly strongly stable, weakly stable or unstable (or, "
                                     "--ucp, its quasistatic problem)?");
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file,
                  "Assembly file: a planar or quasistatic_scene file with bodies (docs/formats.md, "
                  "section 3a)")
      ->required();
  sub->add_flag("--ucp", o->ucp,
                "Solve the quasistatic problem (each body's velocity and every contact's world force) or prove it "
                "jammed, instead of stability from rest");
  sub->add_option("--max-nodes", o->max_nodes,
                  std::string("Budget: prefixes of the stability walk (default ") +
                      std::to_string(queries::AssemblyStabilityOptions{}.max_nodes) +
                      "), or nodes of --ucp's search (default " +
                      std::to_string(queries::AssemblyUcpOptions{}.max_nodes) + ")")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()));
  sub->add_option("--max-bases", o->max_bases,
                  std::string("With --ucp: Step 3's bases per degenerate vertex (default ") +
                      std::to_string(queries::AssemblyUcpOptions{}.max_bases) + ")")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()));
  sub->add_option("--certificate", o->certificate,
                  "Write the evidence for `contactcert check` here (assembly_stability; with --ucp ucp_solvable or "
                  "ucp_jammed)");
  sub->add_option("--svg", o->svg, "Draw the assembly with its contacts and the witness's contact forces here");
  sub->add_flag("--all", o->uniqueness.all,
                "With --ucp: also decide whether the bodies' motion is unique (the prefix tree of simulate's steps)");
  sub->add_option("--max-modes", o->max_modes, "--ucp --all: LP budget of the uniqueness prefix tree")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->capture_default_str();
  sub->add_option("--uniqueness-certificate", o->uniqueness.certificate,
                  "--ucp --all: write the motion_uniqueness certificate of its verdict to this file");
  sub->callback([o, sub, &action] {
    if (!o->ucp) {
      refuse_given(*sub, {"--max-bases"}, "only --ucp has a Step 3");
      refuse_given(*sub, {"--all", "--max-modes", "--uniqueness-certificate"},
                   "an option of --ucp's uniqueness question (stability from rest asks none)");
    }
    if (sub->count("--max-modes") > 0) o->uniqueness.max_modes = o->max_modes;
    queries::check_uniqueness_options(o->uniqueness, o->common.query().arith);
    action = [o] { return run_assembly(*o); };
  });
}

}  // namespace contactcert::cli
