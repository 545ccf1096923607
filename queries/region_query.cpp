#include "queries/region_query.h"

#include "queries/region_data.h"
#include "queries/stability_svg.h"

namespace contactcert::queries {

using exact::Q;

namespace {

RegionAnswer region_answer(const SceneInput& input, const RegionOptions& options) {
  refuse_float(options.common.arith, "--region is computed exactly (use exact or verified)");
  solvers::ModeTreeOptions tree;  // the mode tree's default arithmetic and budget, the run's deadline
  tree.deadline = options.common.deadline();
  RegionAnswer a{solvers::stable_region<Q>(input.scene, solvers::Route::kPaper, tree), options.wrench, std::nullopt,
                 options.svg};
  if (a.wrench) a.wrench_label = a.region.label(*a.wrench);
  if (!a.svg.empty()) write_text_file(a.svg, region_svg(a));
  return a;
}

}  // namespace

Limited<RegionAnswer> run_region(const SceneInput& input, const RegionOptions& options) {
  return with_limits(options.common.arith, [&] { return region_answer(input, options); });
}

json to_json(const RegionAnswer& answer) {
  json modes = json::array();
  for (const auto& m : answer.region.modes) modes.push_back(m.text());
  json j;
  j["region"] = region_data_json(answer.region);
  j["region"]["nonempty_moving_modes"] = modes;
  if (answer.wrench)
    j["region"]["wrench"] = {{"g", exact_json(*answer.wrench)}, {"label", solvers::verdict_name(*answer.wrench_label)}};
  return j;
}

std::string region_svg(const RegionAnswer& answer) { return stability_sphere_svg(answer.region, answer.wrench); }

}  // namespace contactcert::queries
