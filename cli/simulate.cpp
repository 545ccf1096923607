// `contactcert simulate SCENE --steps N --dt H`: quasistatic time-stepping of a motion scene (docs/motion.md) over
// the query layer (queries/simulate_query.h): options in, the report or the trajectory's JSON out. Exit 0 for every
// way a run ends (a jamming proof is an answer), 3 when a budget or the time limit stopped it: then only the limit
// and the steps done (stderr).
#include <CLI/CLI.hpp>
#include <iostream>
#include <limits>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "exact/json_input.h"
#include "queries/simulate_query.h"

namespace contactcert::cli {
namespace {

struct SimulateCliOptions {
  CommonOptions common;
  std::string file;
  long steps = 0;  ///< 0: the scene's
  std::string dt;  ///< "": the scene's
  bool compare = false;
  std::string uniqueness = "on";
  long max_modes = queries::SimulateOptions{}.max_modes;
  long max_nodes = queries::SimulateOptions{}.max_nodes;
  std::string certificates, svg;
};

queries::SimulateOptions simulate_query_options(const SimulateCliOptions& o) {
  queries::SimulateOptions q;
  q.common = o.common.query();
  if (o.steps > 0) q.steps = o.steps;
  if (!o.dt.empty()) q.dt = queries::parse_dt(o.dt, "--dt");
  q.compare = o.compare;
  q.uniqueness = o.uniqueness == "on";
  q.max_modes = o.max_modes;
  q.max_nodes = o.max_nodes;
  q.certificates = o.certificates;
  q.svg = o.svg;
  return q;
}

/// An exact value of the trajectory's JSON (a string, or a tuple of strings) if short, else (and on the float path)
/// its float view after "~".
std::string simulate_value(const json& j, const std::string& key) {
  std::string s;
  if (j.contains(key) && !j[key].is_array()) {
    s = j[key].get<std::string>();
  } else if (j.contains(key)) {
    for (std::size_t i = 0; i < j[key].size(); ++i) s += (i ? ", " : "(") + j[key][i].get<std::string>();
    s += ")";
  }
  return !s.empty() && s.size() <= 40 ? s : "~" + j[key + "_approx"].dump();
}

/// The readable report, from the same JSON that --json prints.
void print_simulate_text(const json& j) {
  std::cout << "simulate " << j["file"].get<std::string>() << ": " << j["status"].get<std::string>()
            << (j["reason"].get<std::string>().empty() ? "" : " (" + j["reason"].get<std::string>() + ")") << "\n  "
            << j["steps_done"] << " of " << j["steps_asked"] << " steps of " << j["dt"].get<std::string>() << ", arith "
            << j["arith"].get<std::string>() << ", " << j["seconds"] << " s\n";
  for (const json& s : j["steps"]) {
    std::cout << "  step " << s["index"] << " t = " << simulate_value(s, "time") << " h = " << simulate_value(s, "h")
              << ": " << s["verdict"].get<std::string>();
    if (s.contains("uniqueness")) std::cout << ", " << s["uniqueness"]["status"].get<std::string>();
    if (s["verdict"] == "solvable" && !s.contains("bodies")) std::cout << ", q_dot = " << simulate_value(s, "q_dot");
    if (!s["cut_by"].is_null()) std::cout << ", cut by " << s["cut_by"].get<std::string>();
    if (s["verdict"] == "solvable" && s.contains("bodies")) {
      std::cout << "\n    q_dot:";
      for (const json& b : s["bodies"])
        std::cout << " " << b["name"].get<std::string>() << " " << simulate_value(b, "q_dot") << ";";
    }
    std::cout << "\n    contacts:";
    for (const json& c : s["contacts"])
      std::cout << " [" << c["mode"].get<std::string>() << "] " << c["name"].get<std::string>() << ";";
    for (const char* e : {"made", "broken"}) {
      if (s["events"][e].empty()) continue;
      std::cout << "\n    " << e << ":";
      for (const json& name : s["events"][e]) std::cout << " " << name.get<std::string>() << ";";
    }
    std::cout << "\n";
  }
  const json& f = j["final"];
  std::cout << "  final: t = " << simulate_value(f, "time");
  if (f.contains("pose"))
    std::cout << ", pose t = " << simulate_value(f["pose"], "t") << ", angle ~ " << f["pose"]["angle_approx"] << " rad";
  else
    for (const json& b : f["bodies"])
      std::cout << "\n    " << b["name"].get<std::string>() << ": pose t = " << simulate_value(b["pose"], "t")
                << ", angle ~ " << b["pose"]["angle_approx"] << " rad";
  std::cout << "\n";
  if (j.contains("divergences")) {
    std::cout << "  float run: " << j["float"]["status"].get<std::string>() << " after " << j["float"]["steps_done"]
              << " steps; " << (j["divergences"].empty() ? "it agrees with the exact run at every step" : "it differs:")
              << "\n";
    for (const json& d : j["divergences"])
      std::cout << "    step " << d["step"] << ", " << d["kind"].get<std::string>() << ": "
                << d["what"].get<std::string>() << " (poses " << d["pose_distance"] << " apart)\n";
  }
  std::size_t written = 0, unique = 0;
  for (const json& s : j["steps"]) {
    written += s.contains("certificate") ? 1 : 0;
    unique += s.contains("uniqueness_certificate") ? 1 : 0;
  }
  if (written > 0)
    std::cout << "  certificates: " << written << " files, step-K.json"
              << (unique > 0 ? ", and " + std::to_string(unique) + " of uniqueness, step-K-uniqueness.json" : "")
              << " (check them with `check`)\n";
  if (j.contains("svg")) std::cout << "  picture written to " << j["svg"].get<std::string>() << "\n";
}

int run_simulate_command(const SimulateCliOptions& o) {
  const queries::SimulateOptions q = simulate_query_options(o);
  const queries::Limited<queries::SimulateAnswer> r = queries::run_simulate(queries::load_motion(o.file), q);
  if (!r) return report_limit("simulate", r.limit(), o.common.json);
  const queries::SimulateAnswer& a = *r;
  // A run stopped by a budget or the time limit reports the limit only (what ran out, the steps done), as every
  // command does; Python's BudgetExceeded still carries the steps made.
  if (queries::stopped_by_budget(a))
    return report_limit("simulate",
                        {"simulate: " + queries::run_reason(a), std::to_string(queries::steps_done(a)) + " steps",
                         queries::Limit::Kind::kStopped},
                        o.common.json);
  const json j = queries::to_json(a);
  if (o.common.json)
    std::cout << exact::json_text(j) << "\n";
  else
    print_simulate_text(j);
  return 0;
}

}  // namespace

void register_simulate(CLI::App& app, Action& action) {
  auto o = std::make_shared<SimulateCliOptions>();
  CLI::App* sub = app.add_subcommand(
      "simulate", "Quasistatic time-stepping of a motion scene, exactly, with a certificate for every step");
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Motion scene (docs/formats.md, section 2, \"Motion scenes\")")->required();
  sub->add_option("--steps", o->steps, "Number of steps N (default: the scene's motion.steps)")
      ->check(whole_number<long>(1, 1000000));
  sub->add_option("--dt", o->dt, "Step size H, an exact number > 0 such as 1/10 (default: the scene's motion.dt)");
  sub->add_flag("--compare", o->compare, "Also run the float path and report where it first differs");
  sub->add_option("--uniqueness", o->uniqueness, "Decide at each step whether the motion is unique: on | off")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  sub->add_option("--max-modes", o->max_modes, "Budget of the uniqueness enumeration (4^contacts modes)")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->capture_default_str();
  sub->add_option("--max-nodes", o->max_nodes, "Node budget of each step's complete search")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->capture_default_str();
  sub->add_option("--certificates", o->certificates, "Write each step's certificate to DIR/step-K.json");
  sub->add_option("--svg", o->svg, "Write the animated picture of the trajectory (SVG) to this file");
  sub->callback([o, &action] { action = [o] { return run_simulate_command(*o); }; });
}

}  // namespace contactcert::cli
