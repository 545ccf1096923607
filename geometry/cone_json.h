// SPEC section 4 cone files: reading (exact, via JsonInput) and writing (canonical, strings).
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "exact/json_input.h"
#include "geometry/face_cone.h"
#include "geometry/nnc_cone.h"
#include "geometry/span_cone.h"

namespace contactcert::geometry {

/// A cone read from a file: span form ("rays"/"lines") or face form ("inequalities"/"strict"/"equalities").
struct ConeInput {
  enum class Form { kSpan, kFace } form = Form::kSpan;
  SpanCone<Q> span;
  FaceCone<Q> face;
};

/// Reads { "dim": d, ... } (SPEC section 4). Throws exact::InputError on ragged rows, dim < 1,
/// non-numbers, unknown keys or a mix of both forms.
ConeInput read_cone(const exact::JsonInput& node);

/// { "dim", "rays", "lines" } with primitive integer rows as strings.
nlohmann::json span_to_json(const SpanCone<Q>& cone);
/// { "dim", "inequalities", "strict", "equalities" } (or "empty": true for an empty cone).
nlohmann::json face_to_json(const FaceCone<Q>& cone);
/// An NNC cone: "face" (the cone), "span" (closure generators), "open_faces" (ray index lists), "empty".
nlohmann::json nnc_to_json(const NncForm<Q>& form);

}  // namespace contactcert::geometry
