#include "queries/ucp_query.h"

#include <chrono>
#include <optional>
#include <random>

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "queries/ucp_forces.h"
#include "solvers/ucp/generate.h"
#include "solvers/ucp/scene_builder.h"

namespace contactcert::queries {

namespace ucp = solvers::ucp;
using exact::Q;

UcpInput parse_ucp(const std::string& text, const std::string& name) {
  const auto start = std::chrono::steady_clock::now();
  UcpInput out{name, text, {}, {}, {}, 0};
  std::optional<exact::JsonInput> in;
  {
    const ucp::PhaseTimer t(out.setup.parse);
    in = exact::JsonInput::parse(text, name);
  }
  out.problem = ucp::read_ucp_problem(*in, &out.setup);
  {
    const ucp::PhaseTimer t(out.setup.parse);
    if (in->at("kind").string() == "quasistatic_scene") out.frames = ucp::quasistatic_scene_frames(*in);
  }
  out.seconds = seconds_since(start);
  return out;
}

UcpInput load_ucp(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  double parse = 0;
  std::string text;
  {
    const ucp::PhaseTimer t(parse);
    text = exact::JsonInput::read_text(path);
  }
  UcpInput out = parse_ucp(text, path);
  out.setup.parse += parse;
  out.seconds = seconds_since(start);
  return out;
}

ucp::Method parse_method(const std::string& text, const std::string& field) {
  for (const ucp::Method m :
       {ucp::Method::kPaper, ucp::Method::kModified, ucp::Method::kComplete, ucp::Method::kEnumerate})
    if (text == ucp::method_name(m)) return m;
  throw exact::InputError("command line", field,
                          "paper, modified, complete or enumerate, found " + exact::quoted_excerpt(text));
}

void check_ucp_options(const UcpQueryOptions& o) {
  const std::string method = ucp::method_name(o.method);
  if (o.max_nodes && o.method != ucp::Method::kComplete)
    throw exact::InputError(
        "command line", "--max-nodes",
        "the node budget of --method complete's search; --method " + method + " has no search tree");
  if (o.max_bases && o.method == ucp::Method::kEnumerate)
    throw exact::InputError("command line", "--max-bases",
                            "the basis budget of Step 3; --method enumerate has no Step 3");
  if (!o.certificate.empty() && o.common.arith == exact::Arith::kFloat)
    throw exact::InputError("command line", "--certificate", "a certificate needs --arith exact or verified");
  if (!o.certificate.empty() && o.method == ucp::Method::kEnumerate)
    throw exact::InputError("command line", "--certificate",
                            "--method enumerate writes no certificate (its jammed verdict has no proof tree); use "
                            "--method complete");
  check_uniqueness_options(o.uniqueness, o.common.arith);
}

namespace {

Limited<UcpAnswer> ucp_answer(const UcpInput& in, const UcpQueryOptions& o) {
  check_ucp_options(o);
  if (o.uniqueness.all && !in.problem.quasistatic)
    throw exact::InputError(in.name, "kind",
                            "--all asks whether the body velocity q_dot is unique: a quasistatic problem, not a plain "
                            "UCP one");
  const auto start = std::chrono::steady_clock::now();
  ucp::UcpOptions opts;
  opts.method = o.method;
  opts.arith = o.common.arith;
  opts.seed = o.seed;
  opts.max_nodes = o.max_nodes.value_or(opts.max_nodes);
  opts.max_bases = o.max_bases.value_or(opts.max_bases);
  opts.time_limit = o.common.time_limit;
  opts.progress = o.progress;
  UcpAnswer a{ucp::solve_ucp(in.problem, opts), {}, {}, in.frames, {}};
  ucp::UcpReport& r = a.report;
  r.phases.parse = in.setup.parse;
  r.phases.build = in.setup.build;
  if (!o.certificate.empty()) {
    const ucp::PhaseTimer t(r.phases.certificate);
    a.certificate_text = ucp::certificate_text(in.problem, r);
    if (!a.certificate_text.empty()) {
      write_certificate_file("ucp", o.certificate, a.certificate_text,
                             std::string("the problem is ") + ucp::status_name(r.status));
      a.certificate = o.certificate;
    }
  }
  Limited<std::optional<UniquenessAnswer>> u =
      decide_uniqueness(in.problem, r, o.uniqueness, o.common.arith, "ucp " + in.name);
  if (!u) return u.limit();
  a.uniqueness = *std::move(u);
  r.seconds = in.seconds + seconds_since(start);
  return a;
}

}  // namespace

Limited<UcpAnswer> run_ucp(const UcpInput& in, const UcpQueryOptions& o) {
  return with_limits(o.common.arith, [&] { return ucp_answer(in, o); });
}

std::optional<Limit> limit_of(const ucp::UcpReport& r) {
  if (!r.limited) return std::nullopt;
  const std::string nodes = r.method == ucp::Method::kComplete ? std::to_string(r.nodes) + " nodes, " : "";
  return Limit{r.reason, nodes + std::to_string(r.pairs) + " pairs, " + std::to_string(r.lps) + " lps"};
}

json report_head_json(const ucp::UcpReport& r, bool with_method) {
  json j;
  j["status"] = ucp::status_name(r.status);
  j["reason"] = r.reason;
  if (with_method) j["method"] = ucp::method_name(r.method);
  j["arith"] = exact::arith_name(r.arith);
  return j;
}

json to_json(const UcpAnswer& a) {
  const ucp::UcpReport& r = a.report;
  json j = report_head_json(r, true);
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
    if (!a.frames.empty()) j["physical"]["contacts"] = ucp_forces_json(a.frames, s.c_n.to_q(), s.c_t.to_q());
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
  if (!a.certificate.empty()) j["certificate"] = a.certificate;
  if (a.uniqueness) j["uniqueness"] = to_json(*a.uniqueness);
  j["seconds"] = r.seconds;
  const ucp::UcpPhases& t = r.phases;
  j["phases"] = {{"parse", t.parse},     {"build", t.build}, {"solve", t.solve},
                 {"recover", t.recover}, {"check", t.check}, {"certificate", t.certificate}};
  return j;
}

UcpGenerator parse_generator(const std::string& text, const std::string& field) {
  if (text == "random") return UcpGenerator::kRandom;
  if (text == "reduction") return UcpGenerator::kReduction;
  throw exact::InputError("command line", field, "random or reduction, found " + exact::quoted_excerpt(text));
}

exact::Q parse_exact_option(const std::string& text, const std::string& field) {
  try {
    return exact::parse_rational(text);
  } catch (const exact::NumberSyntaxError& e) {
    throw exact::InputError("command line", field, e.what());
  }
}

ucp::UcpProblem generate_ucp(const UcpGenerateOptions& o) {
  std::mt19937_64 rng(o.seed);
  ucp::UcpProblem p;
  if (o.generator == UcpGenerator::kRandom) {
    if (o.nc < 1 || o.abar < 0 || o.abar > 2 * o.nc || sgn(o.mu_max) <= 0)
      throw exact::InputError("command line", "--nc/--abar/--mu-max", "expected nc >= 1, 0 <= abar <= 2nc, mu-max > 0");
    ucp::RandomProblemOptions r;
    r.nc = o.nc;
    r.abar_size = o.abar;
    r.mu_max = o.mu_max;
    p = ucp::generate_random_problem(r, rng);
  } else {
    if (o.rows < 1 || o.cols < 1 || o.cols > 60)
      throw exact::InputError("command line", "--rows/--cols", "expected rows >= 1 and 1 <= cols <= 60");
    const ucp::ZeroOneProblem zo = ucp::random_zero_one(o.rows, o.cols, o.planted, rng);
    p = ucp::reduction_problem(zo);
    // Deciding the 0-1 problem by brute force is cheap up to 2^20 assignments: the expected verdict, stated.
    if (o.cols <= 20)
      p.source += ucp::zero_one_feasible(zo) ? " (0-1 feasible: solvable)" : " (0-1 infeasible: jammed)";
  }
  p.source += ", seed " + std::to_string(o.seed);
  return p;
}

}  // namespace contactcert::queries
