#include "queries/finger_query.h"

#include <cmath>

#include "queries/boundary_marks.h"
#include "solvers/stability/stable_region.h"

namespace contactcert::queries {
namespace {

using exact::Q;

double signed_degrees(const exact::Vec<Q>& u) { return std::atan2(u(1).get_d(), u(0).get_d()) * 180.0 / M_PI; }

FingerAnswer finger_answer(const SceneInput& input, const FingerOptions& options) {
  refuse_float(options.common.arith, "--finger is computed exactly (use exact or verified)");
  solvers::ModeTreeOptions tree;  // the mode tree's default arithmetic and budget, the run's deadline
  tree.deadline = options.common.deadline();
  const auto region = solvers::stable_region<Q>(input.scene, solvers::Route::kPaper, tree);
  FingerAnswer a{input.scene, solvers::finger_pushes<Q>(input.scene, region, tree.deadline), options.svg};
  if (!a.svg.empty()) write_text_file(a.svg, finger_svg(a));
  return a;
}

}  // namespace

Limited<FingerAnswer> run_finger(const SceneInput& input, const FingerOptions& options) {
  return with_limits(options.common.arith, [&] { return finger_answer(input, options); });
}

json to_json(const FingerAnswer& answer) {
  json edges = json::array(), arcs = json::array();
  for (const auto& p : answer.pushes.edges)
    edges.push_back({{"edge", p.edge},
                     {"from", exact_json(p.from)},
                     {"to", exact_json(p.to)},
                     {"from_closed", p.from_closed},
                     {"to_closed", p.to_closed},
                     {"label", solvers::verdict_name(p.label)}});
  for (const auto& p : answer.pushes.arcs)
    arcs.push_back({{"from_direction", primitive_json(p.from)},
                    {"to_direction", primitive_json(p.to)},
                    {"from_closed", p.from_closed},
                    {"to_closed", p.to_closed},
                    {"from_degrees_approx", signed_degrees(p.from)},
                    {"to_degrees_approx", signed_degrees(p.to)},
                    {"label", solvers::verdict_name(p.label)}});
  json j;
  j["finger"] = {{"edges", edges}, {"arcs", arcs}};
  return j;
}

std::string finger_svg(const FingerAnswer& answer) {
  return wrench_cone_svg(answer.scene, exact::Mat<Q>(0, 3), exact::Mat<Q>(0, 3),
                         "finger pushes: green strongly stable, yellow weakly, red unstable",
                         verdict_marks(answer.scene, answer.pushes));
}

}  // namespace contactcert::queries
