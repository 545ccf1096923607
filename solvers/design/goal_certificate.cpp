#include "solvers/design/goal_certificate.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "exact/rational_text.h"
#include "solvers/insertion/insertion.h"
#include "solvers/stability/sparse_motzkin.h"
#include "solvers/wrench_cone/cone_form.h"
#include "solvers/wrench_cone/contact_model.h"

namespace contactcert::solvers {

using exact::Q;
using exact::Vec;

exact::StrictSystem<Q> wrench_cone_membership(const geometry::PlanarScene& scene, const ModeString& mode,
                                              const Vec<Q>& g) {
  const ConeForm<Q> f = cone_form<Q>(scene, contact_model<Q>(scene), mode);
  exact::StrictSystem<Q> s;
  s.A = f.K;
  s.b = f.P * g;
  s.is_free.assign(static_cast<std::size_t>(f.K.cols()), false);
  s.strict = f.strict;
  return s;
}

std::string goal_certificate(const std::string& scene_text, const geometry::PlanarScene& scene, const Vec<Q>& g,
                             const std::optional<geometry::Point2>& push) {
  auto strings = [](const Vec<Q>& v) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(exact::to_string(v(i)));
    return a;
  };
  nlohmann::ordered_json outside = nlohmann::ordered_json::array();
  for (const InsertionSet& set : insertion_sets(scene.fixels.size())) {
    const exact::StrictSystem<Q> s = wrench_cone_membership(scene_in_state(scene, set.state), set.mode, g);
    const exact::StrictFeasibility<Q> r = exact::strict_feasibility<Q>(s);
    if (r.status != exact::StrictStatus::kInfeasible)
      throw std::logic_error("goal certificate: the witness lies in G_" + set.mode.text() + " of state " +
                             set.state_text());
    outside.push_back(
        {{"state", set.state_text()}, {"mode", set.mode.text()}, {"motzkin", sparse_motzkin_json(r.motzkin)}});
  }
  nlohmann::ordered_json j;
  j["kind"] = "goal_nonempty";
  j["problem_sha256"] = exact::JsonInput::parse(scene_text, "scene").canonical_sha256();
  j["wrench"] = strings(g);
  if (push) j["push"] = {exact::to_string(push->x), exact::to_string(push->y)};
  j["outside"] = outside;
  j["scene"] = scene_text;
  return j.dump(1) + "\n";
}

}  // namespace contactcert::solvers
