#include "solvers/stability/contact_modes.h"

#include <nlohmann/json.hpp>

#include "exact/rational_text.h"
#include "solvers/stability/sparse_motzkin.h"

namespace contactcert::solvers {

using json = nlohmann::ordered_json;
using Index = Eigen::Index;

namespace {

std::vector<bool> touching_flags(const geometry::PlanarScene& scene) {
  std::vector<bool> t;
  for (const geometry::Fixel& f : scene.fixels) t.push_back(f.frame.touching());
  return t;
}

ModeAlphabet alphabet_of(const geometry::PlanarScene& scene, bool printed_separation, bool unions) {
  return ModeAlphabet{{touching_flags(scene), printed_separation}, unions};
}

json strings(const Vec<Q>& v) {
  json a = json::array();
  for (Index i = 0; i < v.size(); ++i) a.push_back(exact::to_string(v(i)));
  return a;
}

}  // namespace

Vec<Q> ContactModes::wrench(std::size_t i) const {
  Vec<Q> g = tree.accelerations[i];
  g(2) *= model.inertia_per_mass;  // M = diag(1, 1, I/m) per unit mass, as in motion_system.h
  return g;
}

ContactModes contact_modes(const geometry::PlanarScene& scene, const ContactModeOptions& options) {
  ContactModes out{alphabet_of(scene, options.printed_separation, options.unions), motion_model<Q>(scene), {}};
  out.tree = walk_modes_by_cones(out.model, out.alphabet, options.tree);
  return out;
}

const char* mode_group(const ModeString& mode, const std::vector<bool>& touching) {
  bool separates = false, slides = false, rolls = false;
  for (std::size_t i = 0; i < mode.letters.size(); ++i) {
    if (!touching[i]) continue;
    const Interaction L = mode.letters[i];
    separates = separates || L == Interaction::kSeparate;
    slides = slides || L == Interaction::kSlideLeft || L == Interaction::kSlideRight;
    rolls = rolls || L == Interaction::kRoll || L == Interaction::kMaintain;
  }
  const int kinds = separates + slides + rolls;
  if (kinds == 0) return "free";
  if (kinds > 1) return "mixed";
  return separates ? "separating" : slides ? "sliding" : "rolling";
}

std::string modes_certificate(const std::string& scene_text, const ContactModes& m) {
  json j;
  j["kind"] = "modes";
  j["scene"] = scene_text;
  j["problem_sha256"] = exact::JsonInput::parse(scene_text, "scene").canonical_sha256();
  j["table2"] = m.alphabet.rules.printed_separation ? "printed" : "strict";
  j["unions"] = m.alphabet.unions;
  add_mode_tree(j, m.tree);
  return j.dump(1) + "\n";
}

void add_mode_tree(json& j, const ModeTree<Q>& tree) {
  json modes = json::array();
  for (std::size_t i = 0; i < tree.modes.size(); ++i)
    modes.push_back({{"mode", tree.modes[i].text()}, {"acceleration", strings(tree.accelerations[i])}});
  j["modes"] = modes;
  json dead = json::array();
  for (const DeadPrefix<Q>& d : tree.dead)
    dead.push_back({{"prefix", d.prefix.text()}, {"motzkin", sparse_motzkin_json(d.motzkin)}});
  j["dead"] = dead;
}

}  // namespace contactcert::solvers
