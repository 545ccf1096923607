// `contactcert stability SPATIAL --wrench fx,fy,fz,tx,ty,tz`: is a body in space strongly stable, only weakly stable
// or unstable under the external wrench g (issue 34; solvers/spatial/spatial_stability.h)? With its witnesses (the
// pyramid weights and world contact forces that balance g, a moving mode that admits it) and the
// "spatial_stability" certificate `contactcert check` verifies.
#pragma once

#include <string>

#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "queries/spatial_modes_query.h"
#include "solvers/spatial/spatial_stability.h"

namespace contactcert::queries {

struct SpatialStabilityOptions {
  CommonOptions common;                                               ///< exact or verified (float is refused)
  exact::Vec<exact::Q> wrench = exact::Vec<exact::Q>::Zero(6);        ///< g = (f, torque about the com)
  long max_nodes = solvers::spatial::SpatialModeOptions{}.max_nodes;  ///< the mode tree's prefixes at most
  std::string certificate;                                            ///< the certificate's file ("" = none)
};

struct SpatialStabilityAnswer {
  geometry::SpatialScene scene;  ///< for the world contact forces
  exact::Vec<exact::Q> wrench;
  solvers::spatial::SpatialStability result;
  std::string certificate;       ///< the file written ("" = none)
  std::string certificate_text;  ///< its text ("" = none)
};

/// The verdict for options.wrench (InputError for --arith float or a wrench without 6 entries; a Limit past the
/// node budget or the time limit), the certificate written where asked.
Limited<SpatialStabilityAnswer> run_spatial_stability(const SpatialInput& in, const SpatialStabilityOptions& options);

/// {"kind": "spatial", "verdict", "wrench", "contacts", "witness": {"resting_weights", "resting_forces",
/// "moving": {"mode", "acceleration", "weights", "forces"}}, "lps", "modes_checked", "modes_kinematically_feasible",
/// "mode_tree": {"nodes", "dead_prefixes"}, "certificate"}.
json to_json(const SpatialStabilityAnswer& answer);
/// The text `stability SPATIAL` prints.
std::string to_text(const SpatialStabilityAnswer& answer, const std::string& name);

}  // namespace contactcert::queries
