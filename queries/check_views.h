// The views of a valid certificate's evidence that `check` shows a person: the world forces of a stability
// certificate's resting and moving witnesses, and the witness of a "cone_nonempty" certificate, recomputed from the
// raw vectors the checker verified. A certificate's own readable copy of them ("contacts", "acceleration"), if any,
// must be exactly these, else the view sets the verdict INVALID: it would show numbers that were not checked.
#pragma once

#include <vector>

#include "exact/json_input.h"
#include "exact/number.h"
#include "queries/check.h"

namespace contactcert::queries {

/// The wrench and the world forces of a valid stability certificate's witnesses, in c.details and c.text; `scene`
/// is its embedded scene.
void stability_view(const exact::JsonInput& cert, const exact::JsonInput& scene, CheckResult& c);

/// The witness of a valid "cone_nonempty" certificate (world forces, acceleration) from the contact forces `forces`
/// of the fixels `touching` that the checker derived from its z, in c.details["witness"] and c.text.
void cone_view(const exact::JsonInput& cert, const exact::JsonInput& scene, const std::vector<Eigen::Index>& touching,
               const exact::Vec<exact::Q>& forces, CheckResult& c);

}  // namespace contactcert::queries
