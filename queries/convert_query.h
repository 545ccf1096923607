// `convert`: span <-> face conversion of a cone (SPEC sections 4 and 6). Span in: the minimal face form out (and
// the minimal span form). Face in (strict rows allowed): the closure's generators out, with the open faces, and
// the minimal face form of the cone itself. The exact path also answers `verified` (the conversion is exact and
// cheap in R^d: there is nothing for a float answer to propose).
#pragma once

#include <optional>

#include "exact/json_input.h"
#include "geometry/cone_json.h"
#include "geometry/nnc_cone.h"
#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"

namespace contactcert::queries {

struct ConvertOptions {
  CommonOptions common;
};

struct ConvertAnswer {
  geometry::ConeInput::Form input = geometry::ConeInput::Form::kSpan;
  std::optional<geometry::NncForm<exact::Q>> exact;        ///< exact and verified
  std::optional<geometry::FaceCone<double>> float_face;    ///< float, span input: the face form
  std::optional<geometry::NncForm<double>> float_closure;  ///< float, face input: the closure and open faces
};

/// The conversion of the cone file `file` (docs/formats.md section 4); the time limit stops the double
/// description (a Limit).
Limited<ConvertAnswer> run_convert(const exact::JsonInput& file, const ConvertOptions& o);

/// `convert --json` (its keys in sorted order, as the cone formats of geometry/cone_json.h).
nlohmann::json to_json(const ConvertAnswer& a);

}  // namespace contactcert::queries
