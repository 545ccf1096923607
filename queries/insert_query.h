// The query of `contactcert insert FILE`: the wrenches G_goal that seat the workpiece from any contact state (wrench
// cone paper, sections 8-9: the complement of the union of the cones of eq. 21 for two fixels, Table 5 for three),
// the frictionless finger pushes inside it (Figure 10) and, with a friction sweep, those pushes for every fixel's
// mu_s = mu_k = mu (Figure 11).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "queries/scene_input.h"
#include "solvers/insertion/insertion.h"

namespace contactcert::queries {

struct InsertOptions {
  CommonOptions common;  ///< exact or verified (float is refused); its time limit is tested between units of work
  std::vector<exact::Q> sweep_mu;  ///< the friction values of the sweep (each >= 0; empty = no sweep)
  std::string svg;                 ///< the file the picture is written to ("" = none)
};

/// The pushes of the sweep for one mu.
struct SweepEntry {
  exact::Q mu;
  solvers::BoundaryPieces<exact::Q, bool> pushes;
  double boundary_fraction = 0;  ///< of the boundary on those pushes (queries/boundary_fraction.h)
};

struct InsertAnswer {
  geometry::PlanarScene scene;
  solvers::Insertion<exact::Q> insertion;
  solvers::BoundaryPieces<exact::Q, bool> pushes;
  double boundary_fraction = 0;  ///< of the boundary on `pushes`
  std::vector<SweepEntry> sweep;
};

/// Called before the sweep computes its entry `index` (of `total`), for mu.
using SweepProgress = std::function<void(std::size_t index, std::size_t total, const exact::Q& mu)>;

/// The values of --sweep-mu "a,b,..." (exact numbers; InputError naming `field` unless each is >= 0).
std::vector<exact::Q> parse_sweep_mu(const std::string& text, const std::string& field = "--sweep-mu");

/// G_goal of `scene` (an InputError of a scene unfit for insertion names `file`).
solvers::Insertion<exact::Q> insertion_of(const geometry::PlanarScene& scene, const std::string& file);

/// G_goal, its pushes and the sweep (InputError for --arith float or a scene unfit for insertion), the picture
/// written where asked. Past the time limit it stops before the next unit (G_goal with its pushes, each friction value
/// of the sweep): a kStopped Limit with what was computed, and no picture.
Limited<InsertAnswer> run_insert(const SceneInput& input, const InsertOptions& options,
                                 const SweepProgress& progress = {});

/// The object `insert --json` prints.
json to_json(const InsertAnswer& answer);

/// The picture: the workpiece with the pushes that seat it from any state in green.
std::string insertion_svg(const geometry::PlanarScene& scene, const solvers::BoundaryPieces<exact::Q, bool>& pushes);

}  // namespace contactcert::queries
