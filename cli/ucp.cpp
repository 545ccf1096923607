// `contactcert ucp FILE`: does the quasistatic contact problem (Pang, Trinkle, Lo) have a solution?
// `contactcert ucp --generate random|reduction`: writes problem files (section 5 generator, Proposition 2).
#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/progress_line.h"
#include "cli/results.h"
#include "exact/arith.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "queries/json_out.h"
#include "queries/ucp_forces.h"
#include "solvers/ucp/generate.h"
#include "solvers/ucp/solve.h"

namespace contactcert::cli {
namespace {

namespace ucp = solvers::ucp;
using exact::Q;
using exact::Vec;

}  // namespace

ucp::UcpProblem generated_problem(const std::string& kind, std::uint64_t seed, int nc, const std::string& mu_max,
                                  int abar, int rows, int cols, bool planted) {
  std::mt19937_64 rng(seed);
  ucp::UcpProblem p;
  if (kind == "random") {
    ucp::RandomProblemOptions r;
    r.nc = nc;
    r.abar_size = abar;
    try {
      r.mu_max = exact::parse_rational(mu_max);
    } catch (const exact::NumberSyntaxError& e) {
      throw exact::InputError("command line", "--mu-max", e.what());
    }
    if (nc < 1 || abar < 0 || abar > 2 * nc || sgn(r.mu_max) <= 0)
      throw exact::InputError("command line", "--nc/--abar/--mu-max", "expected nc >= 1, 0 <= abar <= 2nc, mu-max > 0");
    p = ucp::generate_random_problem(r, rng);
  } else {
    if (rows < 1 || cols < 1 || cols > 60)
      throw exact::InputError("command line", "--rows/--cols", "expected rows >= 1 and 1 <= cols <= 60");
    const ucp::ZeroOneProblem zo = ucp::random_zero_one(rows, cols, planted, rng);
    p = ucp::reduction_problem(zo);
    if (cols <= 20) p.source += ucp::zero_one_feasible(zo) ? " (0-1 feasible: solvable)" : " (0-1 infeasible: jammed)";
  }
  p.source += ", seed " + std::to_string(seed);
  return p;
}

void refuse_ignored_budgets(const std::string& method, bool max_nodes_given, bool max_bases_given) {
  if (max_nodes_given && method != "complete")
    throw exact::InputError(
        "command line", "--max-nodes",
        "the node budget of --method complete's search; --method " + method + " has no search tree");
  if (max_bases_given && method == "enumerate")
    throw exact::InputError("command line", "--max-bases",
                            "the basis budget of Step 3; --method enumerate has no Step 3");
}

json ucp_json(const ucp::UcpReport& r, const std::string& certificate) {
  json j;
  j["status"] = ucp::status_name(r.status);
  j["reason"] = r.reason;
  j["method"] = ucp::method_name(r.method);
  j["arith"] = exact::arith_name(r.arith);
  if (!r.decided_by.empty()) j["decided_by"] = r.decided_by;
  if (r.x) {
    const exact::Vec<Q> x = r.x->to_q(), y = r.y->to_q();
    j["x"] = exact_json(x);
    j["y"] = exact_json(y);
    j["xTy"] = exact::to_string(Q(x.dot(y)));
  } else if (r.x_approx.size() > 0) {
    j["x_approx"] = approx_json(r.x_approx);
    j["y_approx"] = approx_json(r.y_approx);
  }
  if (r.best_xTy)
    j["best_xTy"] = exact::to_string(*r.best_xTy);
  else if (r.arith == exact::Arith::kFloat)
    j["best_xTy_approx"] = r.best_xTy_approx;
  if (r.physical) {
    const ucp::PhysicalSolution& s = *r.physical;
    j["physical"] = {{"c_n", exact_json(s.c_n.to_q())},     {"c_t", exact_json(s.c_t.to_q())},
                     {"v_n", exact_json(s.v_n.to_q())},     {"v_t", exact_json(s.v_t.to_q())},
                     {"q_dot", exact_json(s.q_dot.to_q())}, {"theta_dot", exact_json(s.theta_dot.to_q())},
                     {"tau", exact_json(s.tau.to_q())}};
    j["physical"]["tau_is"] = "tau - g_man (joint efforts net of gravity loads), all joints";
  }
  if (r.conditions) {
    j["conditions_2_to_10"] = {{"satisfied", r.conditions->status == ucp::ConditionsStatus::kSatisfied},
                               {"violations", r.conditions->violations}};
  }
  j["pairs"] = r.pairs;
  j["lps"] = r.lps;
  if (r.incomplete_adjacencies > 0) j["incomplete_adjacencies"] = r.incomplete_adjacencies;
  if (r.method == ucp::Method::kComplete) {
    j["nodes"] = r.nodes;
    j["learned_prunes"] = r.learned_prunes;
  }
  if (const ucp::LeafProofs& l = r.leaves; l.total() > 0)
    j["leaf_proofs"] = {{"leaves", l.total()},
                        {"reused", l.reused},
                        {"rounded", l.rounded},
                        {"basis", l.basis},
                        {"lp", l.lp},
                        {"repaired", l.repaired},
                        {"rounded_share", static_cast<double>(l.rounded) / static_cast<double>(l.total())}};
  if (r.solutions >= 0) {
    j["solutions"] = r.solutions;
    j["solution_modes"] = r.solution_modes;
  }
  if (!certificate.empty()) j["certificate"] = certificate;
  j["seconds"] = r.seconds;
  const ucp::UcpPhases& t = r.phases;
  j["phases"] = {{"parse", t.parse},     {"build", t.build}, {"solve", t.solve},
                 {"recover", t.recover}, {"check", t.check}, {"certificate", t.certificate}};
  return j;
}

namespace {

struct UcpCliOptions {
  CommonOptions common;
  std::string file;
  std::string method = "complete";
  std::uint64_t seed = 1;
  std::string certificate;
  long max_nodes = 200000;
  long max_bases = 100000;
  // --generate
  std::string generate;
  std::string out = "-";
  int nc = 3;
  std::string mu_max = "1";
  int abar = 0;
  int rows = 2, cols = 6;
  bool planted = false;
};

int run_generate(const UcpCliOptions& o) {
  write_text_file(o.out, ucp::to_json_text(
                             generated_problem(o.generate, o.seed, o.nc, o.mu_max, o.abar, o.rows, o.cols, o.planted)));
  return 0;
}

/// The options of solve_ucp from the command line's.
ucp::UcpOptions solve_options(const UcpCliOptions& o) {
  ucp::UcpOptions opts;
  opts.method = ucp::parse_method(o.method);
  opts.arith = exact::parse_arith(o.common.arith);
  opts.seed = o.seed;
  opts.max_nodes = o.max_nodes;
  opts.max_bases = o.max_bases;
  opts.time_limit = o.common.time_limit;
  if (!o.certificate.empty() && opts.arith == exact::Arith::kFloat)
    throw exact::InputError("command line", "--certificate", "a certificate needs --arith exact or verified");
  if (!o.certificate.empty() && opts.method == ucp::Method::kEnumerate)
    throw exact::InputError("command line", "--certificate",
                            "--method enumerate writes no certificate (its jammed verdict has no proof tree); use "
                            "--method complete");
  return opts;
}

void print_vector(const char* name, const Vec<Q>& v) {
  std::cout << "  " << name << " =";
  for (Eigen::Index i = 0; i < v.size(); ++i) std::cout << " " << exact::to_string(v(i));
  std::cout << "\n";
}

/// The text report of `ucp FILE` (without --json), from the same report as ucp_json.
void print_ucp_text(const UcpCliOptions& o, const ucp::UcpReport& r, bool certificate_written,
                    const std::vector<geometry::ContactFrame>& frames) {
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
    std::cout << ucp_forces_text(frames, s.c_n.to_q(), s.c_t.to_q());
  }
  if (r.conditions)
    std::cout << "  conditions (2)-(10): "
              << (r.conditions->status == ucp::ConditionsStatus::kSatisfied ? "satisfied exactly" : "VIOLATED") << "\n";
  if (r.solutions >= 0) std::cout << "  solution modes: " << r.solutions << "\n";
  if (certificate_written) std::cout << "  certificate written to " << o.certificate << "\n";
  if (!o.certificate.empty() && !certificate_written) std::cout << "  no certificate written: the verdict is unknown\n";
}

int run_ucp(const UcpCliOptions& o) {
  if (!o.generate.empty()) return run_generate(o);
  if (o.file.empty()) throw exact::InputError("command line", "FILE", "expected a problem file (or --generate)");
  const auto start = std::chrono::steady_clock::now();
  ucp::UcpOptions opts = solve_options(o);
  ucp::UcpPhases setup;
  const UcpFile file = load_ucp_file(o.file, &setup);
  const ucp::UcpProblem& problem = file.problem;
  ProgressLine progress("ucp " + o.file);
  if (progress.enabled())
    opts.progress = [&progress, &opts](long units, long lps) {
      progress.update(opts.method == ucp::Method::kEnumerate
                          ? std::to_string(units) + " modes tested"
                          : std::to_string(units) + " nodes, " + std::to_string(lps) + " LPs");
    };
  ucp::UcpReport r = ucp::solve_ucp(problem, opts);
  progress.finish();
  r.phases.parse = setup.parse;
  r.phases.build = setup.build;

  std::string cert_text;
  if (!o.certificate.empty()) {
    const ucp::PhaseTimer t(r.phases.certificate);
    cert_text = ucp::certificate_text(problem, r);
    if (!cert_text.empty()) write_text_file(o.certificate, cert_text);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (o.common.json) {
    json j = ucp_json(r, cert_text.empty() ? "" : o.certificate);
    if (r.physical && !file.frames.empty())
      j["physical"]["contacts"] = ucp_forces_json(file.frames, r.physical->c_n.to_q(), r.physical->c_t.to_q());
    std::cout << exact::json_text(j) << "\n";
  } else {
    print_ucp_text(o, r, !cert_text.empty(), file.frames);
  }
  return r.status == ucp::UcpStatus::kUnknown ? 3 : 0;
}

}  // namespace

void register_ucp(CLI::App& app, Action& action) {
  auto o = std::make_shared<UcpCliOptions>();
  CLI::App* sub =
      app.add_subcommand("ucp", "Solve the quasistatic contact problem (Pang, Trinkle, Lo) or prove it jammed");
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Problem file (format: docs/formats.md, section 2)");
  sub->add_option("--method", o->method, "paper | modified | complete | enumerate")
      ->check(CLI::IsMember({"paper", "modified", "complete", "enumerate"}))
      ->capture_default_str();
  sub->add_option("--seed", o->seed, "Seed of the random choices (Step 3) and of generators")
      ->check(whole_number<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()))
      ->capture_default_str();
  sub->add_option("--certificate", o->certificate, "Write the certificate of the verdict to this file");
  sub->add_option("--max-nodes", o->max_nodes, "Node budget of the complete search")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->capture_default_str();
  sub->add_option("--max-bases", o->max_bases, "Step 3: bases explored per degenerate vertex")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->capture_default_str();
  sub->add_option("--generate", o->generate, "Write a problem instead: random (section 5) | reduction (Proposition 2)")
      ->check(CLI::IsMember({"random", "reduction"}));
  sub->add_option("--out", o->out, "Generated problem file (- = stdout)")->capture_default_str();
  sub->add_option("--nc", o->nc, "random: number of contacts")->check(whole_number(1, 1000))->capture_default_str();
  sub->add_option("--mu-max", o->mu_max, "random: friction coefficients in (0, mu-max)")->capture_default_str();
  sub->add_option("--abar", o->abar, "random: |abar|, effort-controlled joints")
      ->check(whole_number(0, 2000))
      ->capture_default_str();
  sub->add_option("--rows", o->rows, "reduction: rows of the 0-1 problem")
      ->check(whole_number(1, 1000))
      ->capture_default_str();
  sub->add_option("--cols", o->cols, "reduction: columns of the 0-1 problem")
      ->check(whole_number(1, 60))
      ->capture_default_str();
  sub->add_flag("--planted", o->planted, "reduction: plant a 0-1 solution (solvable)");
  sub->callback([o, sub, &action] {
    // Options the chosen run would ignore are refused rather than dropped silently.
    if (o->generate.empty()) {
      refuse_given(*sub, {"--out", "--nc", "--mu-max", "--abar", "--rows", "--cols", "--planted"},
                   "an option of --generate (without it, ucp solves FILE and writes no problem)");
      refuse_ignored_budgets(o->method, sub->count("--max-nodes") > 0, sub->count("--max-bases") > 0);
    } else {
      refuse_given(*sub, {"file", "--certificate", "--method", "--max-nodes", "--max-bases", "--arith", "--json"},
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
