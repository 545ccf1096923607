// `contactcert modes SPATIAL`: every kinematically feasible contact mode of a spatial scene from rest (issue 34: s, f
// and the 2m sliding letters of each contact's friction pyramid), each with a body acceleration in R^6 that realises
// it, found by the prefix tree of solvers/spatial/spatial_modes.h, and the tree as a completeness proof (the
// "spatial_modes" certificate) for `contactcert check`.
#pragma once

#include <string>

#include "geometry/spatial_scene.h"
#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "solvers/spatial/spatial_modes.h"

namespace contactcert::queries {

/// A spatial scene file as read (docs/formats.md section 3b).
struct SpatialInput {
  std::string name;
  std::string text;
  geometry::SpatialScene scene;
};

/// The spatial scene in `text` named `name`; InputError naming the file and field.
SpatialInput parse_spatial(const std::string& text, const std::string& name);

struct SpatialModesOptions {
  CommonOptions common;                                               ///< exact or verified (float is refused)
  long max_nodes = solvers::spatial::SpatialModeOptions{}.max_nodes;  ///< prefixes visited at most
  long max_modes = solvers::spatial::SpatialModeOptions{}.max_modes;  ///< modes listed at most
  std::string certificate;                                            ///< the certificate's file ("" = none)
  std::string svg;  ///< the picture's file (queries/spatial_svg.h; "" = none)
};

struct SpatialModesAnswer {
  solvers::spatial::SpatialModeTree tree;
  std::vector<std::string> letters;  ///< per contact, its alphabet
  std::string certificate;           ///< the file written ("" = none)
  std::string certificate_text;      ///< its text
  std::string svg;                   ///< the picture written ("" = none)
};

/// The feasible modes (InputError for --arith float; a Limit past a budget or the time limit, or for a certificate
/// larger than `check` reads), the certificate written where asked.
Limited<SpatialModesAnswer> run_spatial_modes(const SpatialInput& in, const SpatialModesOptions& options);

/// {"kind": "spatial", "contacts", "letters", "list": "kinematic", "modes": [{"mode", "acceleration"}],
/// "counts": {"modes", "all_separating", "all_touching"}, "tree": {"nodes", "dead_prefixes", "lps"}, "certificate",
/// "svg"}.
json to_json(const SpatialModesAnswer& answer);
/// The text `modes SPATIAL` prints: the counts, the tree's size, every mode with its (a, alpha).
std::string to_text(const SpatialModesAnswer& answer, const std::string& name);

}  // namespace contactcert::queries
