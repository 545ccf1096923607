#include "queries/assembly_modes_query.h"

#include <map>

#include "exact/json_input.h"
#include "queries/modes_query.h"
#include "solvers/stability/contact_modes.h"

namespace contactcert::queries {
namespace {

namespace sa = solvers::assembly;

/// The group of each mode (solvers::mode_group; every contact touches), in the list's order.
std::vector<std::string> groups(const AssemblyModesAnswer& a) {
  const std::vector<bool> touching(a.contacts, true);
  std::vector<std::string> out;
  for (const auto& m : a.modes.tree.modes) out.emplace_back(solvers::mode_group(m, touching));
  return out;
}

AssemblyModesAnswer assembly_modes_answer(const AssemblyInput& in, const AssemblyModesOptions& options) {
  refuse_float(options.common.arith, "modes are enumerated exactly (use exact or verified)");
  solvers::ModeTreeOptions tree{scene_arith(options.common.arith), options.max_nodes, options.max_modes,
                                options.common.deadline()};
  AssemblyModesAnswer a{sa::assembly_modes(in.assembly, tree),
                        in.assembly.bodies.size(),
                        in.assembly.contacts.size(),
                        options.certificate,
                        {}};
  if (!options.certificate.empty())
    a.certificate_text = write_modes_certificate(options.certificate, sa::assembly_modes_certificate(in.text, a.modes),
                                                 a.modes.tree.modes.size(), a.modes.tree.dead.size());
  return a;
}

}  // namespace

Limited<AssemblyModesAnswer> run_assembly_modes(const AssemblyInput& in, const AssemblyModesOptions& options) {
  return with_limits(options.common.arith, [&] { return assembly_modes_answer(in, options); });
}

json to_json(const AssemblyModesAnswer& a) {
  const auto& tree = a.modes.tree;
  const std::vector<std::string> group = groups(a);
  json modes = json::array();
  std::map<std::string, long> counts;
  for (std::size_t i = 0; i < tree.modes.size(); ++i) {
    modes.push_back(
        {{"mode", tree.modes[i].text()}, {"group", group[i]}, {"acceleration", exact_json(tree.accelerations[i])}});
    ++counts[group[i]];
  }
  json j;
  j["bodies"] = a.bodies;
  j["contacts"] = a.contacts;
  j["table2"] = "strict";
  j["list"] = "kinematic";
  j["modes"] = modes;
  j["counts"] = counts;
  j["tree"] = {{"nodes", tree.nodes}, {"dead_prefixes", tree.dead.size()}, {"lps", tree.lps}};
  if (!a.certificate.empty()) j["certificate"] = a.certificate;
  return j;
}

std::string to_text(const AssemblyModesAnswer& a, const std::string& name) {
  const auto& tree = a.modes.tree;
  const std::vector<std::string> group = groups(a);
  std::map<std::string, long> counts;
  for (const std::string& g : group) ++counts[g];
  std::string s =
      "contact modes of " + name + ": " + std::to_string(tree.modes.size()) + " feasible modes of " +
      std::to_string(a.contacts) + " contacts between " + std::to_string(a.bodies) +
      (a.bodies == 1 ? " body" : " bodies") +
      " and what they touch, from rest, s strictly separating (a_n > 0)\n  prefix tree: " + std::to_string(tree.nodes) +
      " prefixes visited, " + std::to_string(tree.dead.size()) + " proven infeasible, " + std::to_string(tree.lps) +
      " LPs (of 4^" + std::to_string(a.contacts) + " mode strings)\n";
  for (const auto& [g, count] : counts) {
    s += "  " + g + " (" + std::to_string(count) + "):\n";
    for (std::size_t i = 0; i < tree.modes.size(); ++i)
      if (group[i] == g)
        s += "    " + tree.modes[i].text() + "  vdot = " + tuple_text(tree.accelerations[i]) +
             " (a_x, a_y, alpha of each com)\n";
  }
  if (tree.modes.empty()) s += "  none\n";
  if (!a.certificate.empty()) s += "  certificate written to " + a.certificate + "\n";
  return s;
}

}  // namespace contactcert::queries
