// `contactcert modes FILE`: every kinematically feasible augmented contact mode of a planar scene from rest
// (wrench cone paper, Table 2), each with a witness, found by the prefix tree of solvers/stability/mode_tree.h,
// and with --certificate the tree as a completeness proof for `contactcert check`.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <limits>
#include <map>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/results.h"
#include "cli/snap_option.h"
#include "exact/json_input.h"
#include "geometry/scene_json.h"
#include "queries/json_out.h"
#include "solvers/stability/contact_modes.h"

namespace contactcert::cli {
namespace {

using exact::Q;

struct ModesOptions {
  CommonOptions common;
  std::string file;
  std::string snap;  ///< --snap TOL ("" = none)
  bool kinematic = false;
  bool unions = false;
  std::string table2 = "strict";
  long max_nodes = 1L << 22;
  long max_modes = solvers::ModeTreeOptions{}.max_modes;
  std::string certificate;
};

}  // namespace

json modes_json(const solvers::ContactModes& m, bool kinematic, const std::string& certificate) {
  const std::vector<bool>& touching = m.alphabet.rules.touching;
  const auto& tree = m.tree;
  std::map<std::string, long> groups;
  for (const auto& mode : tree.modes) ++groups[solvers::mode_group(mode, touching)];
  json modes = json::array();
  for (std::size_t i = 0; i < tree.modes.size(); ++i) {
    json e{{"mode", tree.modes[i].text()},
           {"group", solvers::mode_group(tree.modes[i], touching)},
           {"acceleration", exact_json(tree.accelerations[i])}};
    if (!kinematic) {
      e["wrench"] = exact_json(m.wrench(i));
      e["forces"] = exact_json(exact::Vec<Q>(exact::Vec<Q>::Zero(2 * static_cast<Eigen::Index>(touching.size()))));
    }
    modes.push_back(e);
  }
  json j;
  j["fixels"] = touching.size();
  j["touching"] = std::count(touching.begin(), touching.end(), true);
  j["table2"] = m.alphabet.rules.printed_separation ? "printed" : "strict";
  j["list"] = kinematic ? "kinematic" : "dynamic";
  j["modes"] = modes;
  j["counts"] = groups;
  j["tree"] = {{"nodes", tree.nodes}, {"dead_prefixes", tree.dead.size()}, {"lps", tree.lps}};
  if (!certificate.empty()) j["certificate"] = certificate;
  return j;
}

solvers::ContactModes modes_of(const geometry::PlanarScene& scene, const std::string& arith, const std::string& table2,
                               bool unions, long max_nodes, double time_limit, long max_modes) {
  if (exact::parse_arith(arith) == exact::Arith::kFloat)
    throw exact::InputError("command line", "--arith", "modes are enumerated exactly (use exact or verified)");
  solvers::ContactModeOptions options;
  options.printed_separation = table2 == "printed";
  options.unions = unions;
  // Overlapping letters (the unions, a printed `s`) can list exponentially many modes: a default time budget.
  const bool overlapping = unions || options.printed_separation;
  if (overlapping && time_limit == 0) time_limit = kModesDefaultSeconds;
  options.tree = {exact::parse_arith(arith), max_nodes, max_modes, exact::Deadline::after(time_limit)};
  return solvers::contact_modes(scene, options);
}

namespace {

int report(const ModesOptions& o, const solvers::ContactModes& m) {
  if (o.common.json) {
    std::cout << modes_json(m, o.kinematic, o.certificate).dump() << "\n";
    return 0;
  }
  const std::vector<bool>& touching = m.alphabet.rules.touching;
  const auto& tree = m.tree;
  std::map<std::string, long> groups;
  for (const auto& mode : tree.modes) ++groups[solvers::mode_group(mode, touching)];
  const long k = static_cast<long>(touching.size()), t = std::count(touching.begin(), touching.end(), true);
  std::cout << "contact modes of " << o.file << ": " << tree.modes.size() << " feasible modes of " << k << " fixels ("
            << t << " touching, " << k - t << " with a gap), from rest, s "
            << (o.table2 == "printed" ? "as Table 2 prints it (a_n >= 0)" : "strictly separating (a_n > 0)") << "\n"
            << "  prefix tree: " << tree.nodes << " prefixes visited, " << tree.dead.size() << " proven infeasible, "
            << tree.lps << " LPs (of 4^" << t << " x 2^" << k - t << " mode strings)\n";
  if (!o.kinematic)
    std::cout << "  each mode's wrench cone contains M vdot (all contact forces zero fit every letter), so the\n"
                 "  dynamic list equals the kinematic one\n";
  for (const auto& [group, count] : groups) {
    std::cout << "  " << group << " (" << count << "):\n";
    for (std::size_t i = 0; i < tree.modes.size(); ++i) {
      if (solvers::mode_group(tree.modes[i], touching) != group) continue;
      std::cout << "    " << tree.modes[i].text() << "  vdot = " << tuple_text(tree.accelerations[i]);
      if (!o.kinematic) std::cout << ", wrench " << tuple_text(m.wrench(i));
      std::cout << "\n";
    }
  }
  if (tree.modes.empty()) std::cout << "  none\n";
  if (!o.certificate.empty()) std::cout << "  certificate written to " << o.certificate << "\n";
  return 0;
}

int run_modes(const ModesOptions& o) {
  // The default time budget of the enumerations that can be exponential (modes_of) has the watchdog of an explicit
  // --time-limit too: a single LP over thousands of rows is not interrupted by the tree's deadline.
  if ((o.unions || o.table2 == "printed") && o.common.time_limit == 0)
    start_watchdog("modes (the default budget of --unions and --table2 printed; --time-limit sets another)",
                   kModesDefaultSeconds);
  const std::string text = read_scene_text(o.file, o.snap);
  const geometry::PlanarScene scene = geometry::read_planar_scene(exact::JsonInput::parse(text, o.file));
  const solvers::ContactModes m =
      modes_of(scene, o.common.arith, o.table2, o.unions, o.max_nodes, o.common.time_limit, o.max_modes);
  if (!o.certificate.empty()) {
    // A certificate that `check` could not read is not written: check reads at most kMaxInputBytes.
    const std::string certificate = solvers::modes_certificate(text, m);
    if (certificate.size() > exact::kMaxInputBytes)
      throw exact::BudgetExceeded("modes --certificate: the certificate would take " +
                                      std::to_string(certificate.size()) + " bytes, more than the " +
                                      std::to_string(exact::kMaxInputBytes >> 20) + " MiB that check reads",
                                  std::to_string(m.tree.modes.size()) + " feasible modes found, " +
                                      std::to_string(m.tree.dead.size()) + " dead prefixes; no certificate written");
    write_text_file(o.certificate, certificate);
  }
  return report(o, m);
}

}  // namespace

void register_modes(CLI::App& app, Action& action) {
  auto o = std::make_shared<ModesOptions>();
  CLI::App* sub = app.add_subcommand("modes", "Every kinematically feasible contact mode of a scene, with a proof");
  add_snap_option(*sub, o->snap);
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Planar scene file (docs/formats.md)")->required();
  sub->add_flag("--kinematic", o->kinematic, "List the modes with their accelerations only (no witness wrench)");
  sub->add_flag("--unions", o->unions, "Also the letters m (l, r or n) and u (s or a), whose modes overlap");
  sub->add_option(
         "--table2", o->table2,
         "strict: s at a touching fixel is a_n > 0 (the physical modes); printed: a_n >= 0 as Table 2 prints it")
      ->check(CLI::IsMember({"strict", "printed"}))
      ->default_str("strict");
  sub->add_option("--max-nodes", o->max_nodes, "Budget on the prefixes the tree visits (exit 3 beyond it)")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->default_str("4194304");
  sub->add_option("--max-modes", o->max_modes,
                  "Budget on the modes listed (exit 3 beyond it; with --unions or --table2 printed the list can be "
                  "exponential in the fixels)")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->default_str(std::to_string(o->max_modes));
  sub->add_option("--certificate", o->certificate, "Write the completeness proof for `contactcert check` here");
  sub->callback([o, &action] { action = [o] { return run_modes(*o); }; });
}

}  // namespace contactcert::cli
