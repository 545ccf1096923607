#include "solvers/design/problem.h"

#include <nlohmann/json.hpp>

#include "exact/rational_text.h"

namespace contactcert::solvers {

const char* rank_name(Rank r) { return r == Rank::kMargin ? "margin" : "goal-fraction"; }

geometry::PlanarScene placement_scene(const DesignProblem& problem, const Placement& placement) {
  geometry::PlanarScene scene;
  scene.workpiece = problem.workpiece;
  for (int i : placement) {
    const Candidate& c = problem.candidates[static_cast<std::size_t>(i)];
    // An explicit contact (point, normal), as placement_scene_text writes it.
    geometry::Fixel f{{c.point, c.normal, exact::Q(0)}, problem.mu_s, problem.mu_k, std::nullopt};
    scene.fixels.push_back(f);
  }
  return scene;
}

std::string placement_scene_text(const DesignProblem& problem, const Placement& placement, const std::string& name) {
  using nlohmann::ordered_json;
  auto q = [](const exact::Q& x) { return exact::to_string(x); };
  auto pt = [&](const geometry::Point2& p) { return ordered_json::array({q(p.x), q(p.y)}); };
  const auto& w = problem.workpiece;
  ordered_json shape;
  if (const auto* d = std::get_if<geometry::DiskShape>(&w.shape)) {
    shape = {{"type", "disk"}, {"center", pt(d->center)}, {"radius", q(d->radius)}};
  } else {
    ordered_json vertices = ordered_json::array();
    for (const auto& v : std::get<geometry::PolygonShape>(w.shape).vertices) vertices.push_back(pt(v));
    shape = {{"type", "polygon"}, {"vertices", vertices}};
  }
  ordered_json fixels = ordered_json::array();
  for (int i : placement) {
    const Candidate& c = problem.candidates[static_cast<std::size_t>(i)];
    fixels.push_back(
        {{"name", "candidate " + std::to_string(i)}, {"point", pt(c.point)}, {"normal", pt(c.normal)}, {"gap", "0"}});
  }
  ordered_json j = {
      {"kind", "planar"},
      {"name", name},
      {"workpiece", {{"shape", shape}, {"com", pt(w.com)}, {"mass", "1"}, {"inertia", q(w.inertia_per_mass)}}},
      {"fixels", fixels},
      {"mu_s", q(problem.mu_s)},
      {"mu_k", q(problem.mu_k)}};
  return j.dump(1) + "\n";
}

}  // namespace contactcert::solvers
