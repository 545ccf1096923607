#include "queries/modes_query.h"

#include <algorithm>

#include "exact/input_error.h"
#include "exact/json_input.h"

namespace contactcert::queries {

using exact::Q;

bool ModesOptions::default_time_budget() const {
  return (unions || table2 == Table2::kPrinted) && common.time_limit == 0;
}

double ModesOptions::time_budget() const { return default_time_budget() ? kModesDefaultSeconds : common.time_limit; }

namespace {

ModesAnswer modes_answer(const SceneInput& input, const ModesOptions& options) {
  refuse_float(options.common.arith, "modes are enumerated exactly (use exact or verified)");
  solvers::ContactModeOptions tree;
  tree.printed_separation = options.table2 == Table2::kPrinted;
  tree.unions = options.unions;
  tree.tree = {options.common.arith, options.max_nodes, options.max_modes,
               exact::Deadline::after(options.time_budget())};
  ModesAnswer a{options, solvers::contact_modes(input.scene, tree), {}};
  if (!options.certificate.empty())
    a.certificate_text = write_modes_certificate(options.certificate, solvers::modes_certificate(input.text, a.modes),
                                                 a.modes.tree.modes.size(), a.modes.tree.dead.size());
  return a;
}

}  // namespace

Limited<ModesAnswer> run_modes(const SceneInput& input, const ModesOptions& options) {
  return with_limits(options.common.arith, [&] { return modes_answer(input, options); });
}

std::string write_modes_certificate(const std::string& file, std::string text, std::size_t modes, std::size_t dead) {
  write_certificate_file("modes", file, text,
                         std::to_string(modes) + " feasible modes found, " + std::to_string(dead) + " dead prefixes");
  return text;
}

std::map<std::string, long> mode_counts(const solvers::ContactModes& modes) {
  std::map<std::string, long> groups;
  for (const auto& mode : modes.tree.modes) ++groups[solvers::mode_group(mode, modes.alphabet.rules.touching)];
  return groups;
}

json to_json(const ModesAnswer& answer) {
  const solvers::ContactModes& m = answer.modes;
  const bool kinematic = answer.options.kinematic;
  const std::vector<bool>& touching = m.alphabet.rules.touching;
  const auto& tree = m.tree;
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
  j["counts"] = mode_counts(m);
  j["tree"] = {{"nodes", tree.nodes}, {"dead_prefixes", tree.dead.size()}, {"lps", tree.lps}};
  if (!answer.options.certificate.empty()) j["certificate"] = answer.options.certificate;
  return j;
}

}  // namespace contactcert::queries
