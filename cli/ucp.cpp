// `contactcert ucp FILE`: does the quasistatic contact problem (Pang, Trinkle, Lo) have a solution?
// `contactcert ucp --generate random|reduction`: writes problem files (section 5 generator, Proposition 2).
// The query is queries/ucp_query.h; this file parses its options and prints its answer.
#include <CLI/CLI.hpp>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>

#include "cli/assembly_answers.h"
#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/progress_line.h"
#include "exact/arith.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "queries/json_out.h"
#include "queries/scene_input_kind.h"
#include "queries/ucp_forces.h"
#include "queries/ucp_query.h"

namespace contactcert::cli {
namespace {

namespace ucp = solvers::ucp;
using exact::Q;
using exact::Vec;

struct UcpCliOptions {
  CommonOptions common;
  std::string file;
  std::string method = ucp::method_name(queries::UcpQueryOptions{}.method);
  long max_nodes = ucp::UcpOptions{}.max_nodes;  // shown as the default; unset unless given
  long max_bases = ucp::UcpOptions{}.max_bases;
  long max_modes = solvers::motion::SimulateOptions{}.max_uniqueness_modes;
  queries::UcpQueryOptions query;  ///< set from the above by the callback
  // --generate (and --seed, for both)
  std::string generate;
  std::string out = "-";
  std::string mu_max = exact::to_string(queries::UcpGenerateOptions{}.mu_max);
  queries::UcpGenerateOptions generator;
  bool seed_given = false;  ///< --seed on the command line (an assembly refuses it)
};

int run_generate(const UcpCliOptions& o) {
  queries::UcpGenerateOptions g = o.generator;
  g.generator = queries::parse_generator(o.generate, "--generate");
  g.seed = o.query.seed;
  g.mu_max = queries::parse_exact_option(o.mu_max, "--mu-max");
  write_text_file(o.out, ucp::to_json_text(queries::generate_ucp(g)));
  return 0;
}

void print_vector(const char* name, const Vec<Q>& v) {
  std::cout << "  " << name << " =";
  for (Eigen::Index i = 0; i < v.size(); ++i) std::cout << " " << exact::to_string(v(i));
  std::cout << "\n";
}

/// The text report of `ucp FILE` (without --json), from the same report as ucp_json.
void print_ucp_text(const UcpCliOptions& o, const queries::UcpAnswer& a) {
  const ucp::UcpReport& r = a.report;
  std::cout << "ucp " << o.file << ": " << ucp::status_name(r.status) << " (" << r.reason << ")\n";
  std::cout << "  method " << ucp::method_name(r.method) << ", arith " << exact::arith_name(r.arith)
            << (r.decided_by.empty() ? "" : " (decided by " + r.decided_by + ")") << ", pairs " << r.pairs << ", LPs "
            << r.lps;
  if (r.method == ucp::Method::kComplete) std::cout << ", nodes " << r.nodes;
  std::cout << ", " << r.seconds << " s\n";
  const ucp::UcpPhases& t = r.phases;
  std::cout << "  time: parse " << t.parse << " s, build " << t.build << " s, solve " << t.solve << " s, recover "
            << t.recover << " s, check " << t.check << " s, certificate " << t.certificate << " s\n";
  // On a jammed problem no pair has x^T y = 0 and the smallest value seen says nothing more: not printed.
  if (r.best_xTy && !r.x && r.status == ucp::UcpStatus::kUnknown)
    std::cout << "  smallest x^T y reached (a solution needs 0): " << exact::to_string(*r.best_xTy) << "\n";
  if (r.x) {
    print_vector("x", r.x->to_q());
    print_vector("y", r.y->to_q());
  }
  if (r.physical) {
    const ucp::PhysicalSolution& s = *r.physical;
    for (auto [name, v] : {std::pair{"c_n", &s.c_n},
                           {"c_t", &s.c_t},
                           {"v_n", &s.v_n},
                           {"v_t", &s.v_t},
                           {"q_dot", &s.q_dot},
                           {"theta_dot", &s.theta_dot},
                           {"tau", &s.tau}})
      print_vector(name, v->to_q());
    std::cout << ucp_forces_text(a.frames, s.c_n.to_q(), s.c_t.to_q());
  }
  if (r.conditions)
    std::cout << "  conditions (2)-(10): "
              << (r.conditions->status == ucp::ConditionsStatus::kSatisfied ? "satisfied exactly" : "VIOLATED") << "\n";
  if (r.solutions >= 0) std::cout << "  solution modes: " << r.solutions << "\n";
  if (!a.certificate.empty()) std::cout << "  certificate written to " << a.certificate << "\n";
  if (!o.query.certificate.empty() && a.certificate.empty())
    std::cout << "  no certificate written: the verdict is unknown\n";
  if (a.uniqueness) std::cout << queries::to_text(*a.uniqueness, 0);
}

/// `ucp ASSEMBLY` (a quasistatic_scene with bodies): the query of `contactcert assembly --ucp`, the complete search.
int run_assembly_ucp_command(const UcpCliOptions& o, const queries::AssemblyInput& in) {
  if (o.query.method != ucp::Method::kComplete)
    throw exact::InputError("command line", "--method", "an assembly's problem is solved by the complete search only");
  if (o.seed_given)
    throw exact::InputError("command line", "--seed", "the complete search on an assembly makes no random choice");
  queries::AssemblyUcpOptions q;
  q.common = o.query.common;
  q.max_nodes = o.query.max_nodes.value_or(q.max_nodes);
  q.max_bases = o.query.max_bases.value_or(q.max_bases);
  q.certificate = o.query.certificate;
  q.uniqueness = o.query.uniqueness;
  q.command = queries::AssemblyUcpOptions::Command::kUcp;
  return print_assembly_answer(queries::run_assembly_ucp(in, q), o.file, o.common.json, "ucp");
}

int run_ucp(const UcpCliOptions& o) {
  if (!o.generate.empty()) return run_generate(o);
  if (o.file.empty()) throw exact::InputError("command line", "FILE", "expected a problem file (or --generate)");
  queries::UcpQueryOptions q = o.query;
  queries::check_ucp_options(q);  // an option's error before the file's
  queries::UcpOrAssembly read = queries::load_ucp_or_assembly(o.file);
  if (const auto* assembly = std::get_if<queries::AssemblyInput>(&read)) return run_assembly_ucp_command(o, *assembly);
  const queries::UcpInput& in = std::get<queries::UcpInput>(read);
  ProgressLine progress("ucp " + o.file);
  if (progress.enabled())
    q.progress = [&progress, &q](long units, long lps) {
      progress.update(q.method == ucp::Method::kEnumerate
                          ? std::to_string(units) + " modes tested"
                          : std::to_string(units) + " nodes, " + std::to_string(lps) + " LPs");
    };
  const queries::Limited<queries::UcpAnswer> r = queries::run_ucp(in, q);
  progress.finish();
  if (!r) return report_limit("ucp", r.limit(), o.common.json);
  const queries::UcpAnswer& a = *r;
  if (const auto limit = queries::limit_of(a.report)) return report_limit("ucp", *limit, o.common.json);
  if (o.common.json)
    std::cout << exact::json_text(queries::to_json(a)) << "\n";
  else
    print_ucp_text(o, a);
  return a.report.status == ucp::UcpStatus::kUnknown ? 3 : 0;
}

}  // namespace

void register_ucp(CLI::App& app, Action& action) {
  auto o = std::make_shared<UcpCliOptions>();
  CLI::App* sub =
      app.add_subcommand("ucp", "Solve the quasistatic contact problem (Pang, Trinkle, Lo) or prove it jammed");
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Problem file (format: docs/formats.md, section 2), or an assembly (section 3a)");
  sub->add_option("--method", o->method, "paper | modified | complete | enumerate")
      ->check(CLI::IsMember({"paper", "modified", "complete", "enumerate"}))
      ->capture_default_str();
  sub->add_option("--seed", o->query.seed, "Seed of the random choices (Step 3) and of generators")
      ->check(whole_number<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()))
      ->capture_default_str();
  sub->add_option("--certificate", o->query.certificate, "Write the certificate of the verdict to this file");
  sub->add_option("--max-nodes", o->max_nodes, "Node budget of the complete search")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->capture_default_str();
  sub->add_option("--max-bases", o->max_bases, "Step 3: bases explored per degenerate vertex")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->capture_default_str();
  sub->add_flag("--all", o->query.uniqueness.all,
                "Also decide whether the solution's motion q_dot is unique (the prefix tree of simulate's steps)");
  sub->add_option("--max-modes", o->max_modes, "--all: LP budget of the uniqueness prefix tree")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->capture_default_str();
  sub->add_option("--uniqueness-certificate", o->query.uniqueness.certificate,
                  "--all: write the motion_uniqueness certificate of its verdict to this file");
  sub->add_option("--generate", o->generate, "Write a problem instead: random (section 5) | reduction (Proposition 2)")
      ->check(CLI::IsMember({"random", "reduction"}));
  sub->add_option("--out", o->out, "Generated problem file (- = stdout)")->capture_default_str();
  sub->add_option("--nc", o->generator.nc, "random: number of contacts")
      ->check(whole_number(1, 1000))
      ->capture_default_str();
  sub->add_option("--mu-max", o->mu_max, "random: friction coefficients in (0, mu-max)")->capture_default_str();
  sub->add_option("--abar", o->generator.abar, "random: |abar|, effort-controlled joints")
      ->check(whole_number(0, 2000))
      ->capture_default_str();
  sub->add_option("--rows", o->generator.rows, "reduction: rows of the 0-1 problem")
      ->check(whole_number(1, 1000))
      ->capture_default_str();
  sub->add_option("--cols", o->generator.cols, "reduction: columns of the 0-1 problem")
      ->check(whole_number(1, 60))
      ->capture_default_str();
  sub->add_flag("--planted", o->generator.planted, "reduction: plant a 0-1 solution (solvable)");
  sub->callback([o, sub, &action] {
    // Options the chosen run would ignore are refused rather than dropped silently.
    if (o->generate.empty()) {
      refuse_given(*sub, {"--out", "--nc", "--mu-max", "--abar", "--rows", "--cols", "--planted"},
                   "an option of --generate (without it, ucp solves FILE and writes no problem)");
      queries::UcpQueryOptions& q = o->query;
      q.common = o->common.query();
      q.method = queries::parse_method(o->method, "--method");
      if (sub->count("--max-nodes") > 0) q.max_nodes = o->max_nodes;
      if (sub->count("--max-bases") > 0) q.max_bases = o->max_bases;
      if (sub->count("--max-modes") > 0) q.uniqueness.max_modes = o->max_modes;
      o->seed_given = sub->count("--seed") > 0;
      // The budgets are refused here, what a certificate needs once FILE is known to be given (run_ucp): the
      // messages keep their order.
      queries::UcpQueryOptions budgets = q;
      budgets.certificate.clear();
      budgets.uniqueness.certificate.clear();
      queries::check_ucp_options(budgets);
    } else {
      refuse_given(*sub,
                   {"file", "--certificate", "--method", "--max-nodes", "--max-bases", "--arith", "--json", "--all",
                    "--max-modes", "--uniqueness-certificate"},
                   "--generate writes a problem and solves none");
    }
    if (o->generate == "random")
      refuse_given(*sub, {"--rows", "--cols", "--planted"}, "an option of --generate reduction");
    if (o->generate == "reduction")
      refuse_given(*sub, {"--nc", "--mu-max", "--abar"}, "an option of --generate random");
    action = [o] { return run_ucp(*o); };
  });
}

}  // namespace contactcert::cli
