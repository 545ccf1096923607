#include "solvers/assembly/assembly_modes.h"

#include <nlohmann/json.hpp>

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
  nlohmann::ordered_json j;
  j["kind"] = "assembly_modes";
  j["scene"] = scene_text;
  j["problem_sha256"] = exact::JsonInput::parse(scene_text, "scene").canonical_sha256();
  add_mode_tree(j, m.tree);
  return j.dump(1) + "\n";
}

}  // namespace contactcert::solvers::assembly
