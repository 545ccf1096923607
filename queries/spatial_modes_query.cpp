#include "queries/spatial_modes_query.h"

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "queries/modes_query.h"
#include "queries/spatial_svg.h"
#include "solvers/spatial/spatial_modes_certificate.h"

namespace contactcert::queries {
namespace {

namespace sp = solvers::spatial;

SpatialModesAnswer spatial_modes_answer(const SpatialInput& in, const SpatialModesOptions& options) {
  refuse_float(options.common.arith, "modes are enumerated exactly (use exact or verified)");
  sp::SpatialModeOptions tree;
  tree.arith = scene_arith(options.common.arith);
  tree.max_nodes = options.max_nodes;
  tree.max_modes = options.max_modes;
  tree.deadline = options.common.deadline();
  SpatialModesAnswer a{sp::spatial_modes(sp::spatial_model(in.scene), tree), {}, options.certificate, {}, {}};
  for (const geometry::SpatialContact& c : in.scene.contacts) a.letters.push_back(sp::letters(c.edges.size()));
  if (!options.certificate.empty())
    a.certificate_text = write_modes_certificate(options.certificate, sp::spatial_modes_certificate(in.text, a.tree),
                                                 a.tree.modes.size(), a.tree.dead.size());
  if (!options.svg.empty()) {
    write_text_file(options.svg, spatial_svg(in.scene, in.name + ": " + std::to_string(a.tree.modes.size()) +
                                                           " contact modes from rest"));
    a.svg = options.svg;
  }
  return a;
}

// The modes in which every contact separates, and those in which none does.
std::pair<long, long> extreme_counts(const sp::SpatialModeTree& tree) {
  long separating = 0, touching = 0;
  for (const std::string& m : tree.modes) {
    separating += m.find_first_not_of('s') == std::string::npos;
    touching += m.find('s') == std::string::npos;
  }
  return {separating, touching};
}

}  // namespace

SpatialInput parse_spatial(const std::string& text, const std::string& name) {
  return {name, text, geometry::read_spatial_scene(exact::JsonInput::parse(text, name))};
}

Limited<SpatialModesAnswer> run_spatial_modes(const SpatialInput& in, const SpatialModesOptions& options) {
  return with_limits(options.common.arith, [&] { return spatial_modes_answer(in, options); });
}

json to_json(const SpatialModesAnswer& a) {
  json modes = json::array();
  for (std::size_t i = 0; i < a.tree.modes.size(); ++i)
    modes.push_back({{"mode", a.tree.modes[i]}, {"acceleration", exact_json(a.tree.accelerations[i])}});
  const auto [separating, touching] = extreme_counts(a.tree);
  json j;
  j["kind"] = "spatial";
  j["contacts"] = a.letters.size();
  j["letters"] = a.letters;
  j["list"] = "kinematic";
  j["modes"] = modes;
  j["counts"] = {{"modes", a.tree.modes.size()}, {"all_separating", separating}, {"all_touching", touching}};
  j["tree"] = {{"nodes", a.tree.nodes}, {"dead_prefixes", a.tree.dead.size()}, {"lps", a.tree.lps}};
  if (!a.certificate.empty()) j["certificate"] = a.certificate;
  if (!a.svg.empty()) j["svg"] = a.svg;
  return j;
}

std::string to_text(const SpatialModesAnswer& a, const std::string& name) {
  const auto [separating, touching] = extreme_counts(a.tree);
  std::string s = "contact modes of " + name + ": " + std::to_string(a.tree.modes.size()) + " feasible modes of " +
                  std::to_string(a.letters.size()) +
                  " contacts of a body in space, from rest (s separating, f sticking, A.. sliding: friction on "
                  "pyramid edge 0, face 0-1, edge 1, ...)\n  " +
                  std::to_string(touching) + " keep every contact, " + std::to_string(separating) +
                  " separate every contact\n  prefix tree: " + std::to_string(a.tree.nodes) + " prefixes visited, " +
                  std::to_string(a.tree.dead.size()) + " proven infeasible, " + std::to_string(a.tree.lps) + " LPs\n";
  for (std::size_t i = 0; i < a.tree.modes.size(); ++i)
    s += "    " + a.tree.modes[i] + "  vdot = " + tuple_text(a.tree.accelerations[i]) + " (a of the com, alpha)\n";
  if (a.tree.modes.empty()) s += "  none\n";
  if (!a.certificate.empty()) s += "  certificate written to " + a.certificate + "\n";
  if (!a.svg.empty()) s += "  picture: " + a.svg + "\n";
  return s;
}

}  // namespace contactcert::queries
