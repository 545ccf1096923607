// The query of `contactcert stability FILE --region`: the whole strongly stable set, as the cells of wrench space cut
// by the planes of the moving modes' wrench cones, each labelled strongly stable, weakly stable or unstable (wrench
// cone paper, section 7, Figure 5); with a wrench g labelled and marked, and the picture of the sphere of wrench
// directions.
#pragma once

#include <optional>
#include <string>

#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "queries/scene_input.h"
#include "solvers/stability/stable_region.h"

namespace contactcert::queries {

struct RegionOptions {
  CommonOptions common;                        ///< exact or verified (the region is computed exactly)
  std::optional<exact::Vec<exact::Q>> wrench;  ///< g to label (and mark in the picture)
  std::string svg;                             ///< the file the picture is written to ("" = none)
};

struct RegionAnswer {
  solvers::StableRegion<exact::Q> region;
  std::optional<exact::Vec<exact::Q>> wrench;             ///< g as given
  std::optional<solvers::StabilityVerdict> wrench_label;  ///< the label of g's cell
  std::string svg;                                        ///< the picture's file ("" = none)
};

/// The labelled cells of the scene's wrench space under the time limit (a Limit past it), the picture written
/// where asked. InputError naming --arith on the float path.
Limited<RegionAnswer> run_region(const SceneInput& input, const RegionOptions& options);

/// The object `stability --region --json` prints: the region's data, its moving modes with non-empty wrench cones,
/// and g with its label.
json to_json(const RegionAnswer& answer);

/// The sphere of wrench directions coloured by label, with g marked (queries/stability_svg.h).
std::string region_svg(const RegionAnswer& answer);

}  // namespace contactcert::queries
