// The query of `contactcert stability FILE --wrench fx,fy,tz`: is the workpiece strongly stable, only weakly stable
// or unstable under the external wrench g (wrench cone paper, section 7; SPEC sections 6-7)? With its witnesses (the
// contact forces that balance g, a moving mode that admits it), the certificate `contactcert check` verifies, and the
// margin of section 8 (the squared radius of the largest strongly stable ball around g, eq. 19).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <variant>

#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "queries/scene_input.h"
#include "solvers/stability/margin.h"
#include "solvers/stability/strong_stability.h"
#include "solvers/stability/world_forces.h"

namespace contactcert::queries {

struct StabilityQueryOptions {
  CommonOptions common;  ///< adaptive runs as verified (scene_arith); one deadline for the verdict and the margin
  exact::Vec<exact::Q> wrench = exact::Vec<exact::Q>::Zero(3);  ///< g = (fx, fy, tz), tz about the centre of mass
  bool margin = false;                                          ///< the margin of a strongly stable g
  std::string certificate;                                      ///< the file the evidence is written to ("" = none)
};

/// A verdict in the run's number type: exact rationals on the exact and verified paths, doubles with --arith float.
using StabilityOutcome = std::variant<solvers::StabilityResult<exact::Q>, solvers::StabilityResult<double>>;

struct StabilityAnswer {
  geometry::PlanarScene scene;                   ///< for the witnesses' contact forces in world coordinates
  exact::Vec<exact::Q> wrench;                   ///< g as given
  exact::Arith arith = exact::Arith::kVerified;  ///< as run (never adaptive)
  StabilityOutcome outcome;
  std::optional<solvers::Margin<exact::Q>> margin;  ///< asked for and g strongly stable
  std::string certificate;                          ///< the file written ("" = none)
  std::string certificate_text;                     ///< its text ("" = none)
  /// The scene's force frames when a batch prepared them once (StabilityVerdicts), else null: built per answer.
  std::shared_ptr<const solvers::ForceFrames> frames;
};

/// The solver's options of a run: its arithmetic (as scene_arith runs it), the default node budget and `deadline`.
solvers::StabilityOptions stability_options(exact::Arith arith, const exact::Deadline& deadline);

/// The verdict for options.wrench, its certificate written where asked, then its margin where asked.
/// InputError naming --certificate or --margin for either on the float path; a Limit past the time limit.
Limited<StabilityAnswer> run_stability(const SceneInput& input, const StabilityQueryOptions& options);

/// The counts of a verdict's search, planar or spatial: `lps`, `modes_checked`, `modes_kinematically_feasible`,
/// `mode_tree` (`nodes`, `dead_prefixes`).
template <class Result>
void put_search_counts(json& j, const Result& r) {
  j["lps"] = r.lps;
  j["modes_checked"] = r.modes_checked;
  j["modes_kinematically_feasible"] = r.modes_kinematically_feasible;
  j["mode_tree"] = {{"nodes", r.tree_nodes}, {"dead_prefixes", r.dead_prefixes}};
}

/// The object `stability --wrench --json` prints.
json to_json(const StabilityAnswer& answer);

}  // namespace contactcert::queries
