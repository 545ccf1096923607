#include "solvers/assembly/assembly_modes.h"

#include <nlohmann/json.hpp>

#include "exact/rational_text.h"
#include "solvers/stability/sparse_motzkin.h"

namespace contactcert::solvers::assembly {

using Index = Eigen::Index;

MotionModel<Q> assembly_motion_model(const AssemblyModel& model) {
  const auto k = static_cast<Index>(model.contacts.size());
  MotionModel<Q> m;
  m.J = exact::Mat<Q>::Zero(static_cast<Index>(3 * model.bodies()), 2 * k);
  m.inertia_per_mass = Q(1);  // not read by the tree
  for (Index i = 0; i < k; ++i) {
    const ContactJacobian& c = model.contacts[static_cast<std::size_t>(i)];
    for (const ContactJacobian::Side& s : c.sides) {
      if (s.body < 0) continue;
      for (std::size_t d = 0; d < 3; ++d) {
        m.J(3 * s.body + static_cast<Index>(d), i) += s.w_n[d];
        m.J(3 * s.body + static_cast<Index>(d), k + i) += s.w_t[d];
      }
    }
    m.mu_s.push_back(c.mu_s);
    m.mu_k.push_back(c.mu_k);
  }
  return m;
}

AssemblyModes assembly_modes(const geometry::Assembly& a, const ModeTreeOptions& options) {
  AssemblyModes out{ModeAlphabet{}, assembly_motion_model(assembly_model(a)), {}};
  out.tree = walk_modes(out.model, out.alphabet, options);
  return out;
}

std::string assembly_modes_certificate(const std::string& scene_text, const AssemblyModes& m) {
  using json = nlohmann::ordered_json;
  const auto strings = [](const Vec<Q>& v) {
    json s = json::array();
    for (const Q& x : v) s.push_back(exact::to_string(x));
    return s;
  };
  json j;
  j["kind"] = "assembly_modes";
  j["scene"] = scene_text;
  j["problem_sha256"] = exact::JsonInput::parse(scene_text, "scene").canonical_sha256();
  json modes = json::array();
  for (std::size_t i = 0; i < m.tree.modes.size(); ++i)
    modes.push_back({{"mode", m.tree.modes[i].text()}, {"acceleration", strings(m.tree.accelerations[i])}});
  j["modes"] = modes;
  json dead = json::array();
  for (const DeadPrefix<Q>& d : m.tree.dead)
    dead.push_back({{"prefix", d.prefix.text()}, {"motzkin", sparse_motzkin_json(d.motzkin)}});
  j["dead"] = dead;
  return j.dump(1) + "\n";
}

}  // namespace contactcert::solvers::assembly
