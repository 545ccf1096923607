// `contactcert cone SPATIAL --mode LETTERS`: the wrench cone of a contact mode of a body in space (issue 34;
// solvers/spatial/spatial_cone.h), 6-D (force, torque about the com), in both forms with its strict rows and open
// faces, as the planar wrench cones are given (docs/formats.md section 4); with its "spatial_cone" certificate
// (solvers/spatial/spatial_cone_certificate.h) for `contactcert check`.
#pragma once

#include <string>

#include "geometry/nnc_cone.h"
#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "queries/spatial_modes_query.h"

namespace contactcert::queries {

struct SpatialConeOptions {
  CommonOptions common;       ///< exact or verified (float is refused)
  std::string mode;           ///< one letter per contact: s, f or a sliding letter of its pyramid
  std::string certificate{};  ///< the certificate's file ("" = none)
};

struct SpatialConeAnswer {
  std::string mode;
  geometry::NncForm<exact::Q> cone;
  std::string certificate{};       ///< the file written ("" = none)
  std::string certificate_text{};  ///< its text
};

/// The cone (InputError naming --mode for a mode that is not one letter of its alphabet per contact, or --arith
/// for float; a Limit past the conversion's budget or the time limit, or for a certificate larger than `check`
/// reads), the certificate written where asked.
Limited<SpatialConeAnswer> run_spatial_cone(const SpatialInput& in, const SpatialConeOptions& options);

/// {"kind": "spatial", "mode", "cone": the cone in both forms (section 4), "certificate" where written}.
json to_json(const SpatialConeAnswer& answer);
/// The text `cone SPATIAL --mode M` prints: the face form's rows and the closure's generators.
std::string to_text(const SpatialConeAnswer& answer, const std::string& name);

}  // namespace contactcert::queries
