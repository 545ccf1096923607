// A batch's stability results as Python objects, built from the verdicts themselves: the objects that
// json.loads(queries::to_json(answer).dump()) builds, without the JSON tree or its text in between (stability_many
// builds one per result read).
#pragma once

#include <pybind11/pybind11.h>

#include <memory>

#include "queries/wrenches_query.h"

namespace contactcert::python {

/// The `stability --wrench --json` object of the answer StabilityVerdicts::answer(g, verdict) gives (no margin, no
/// certificate), as Python objects (dict in the same key order, list, str, int, float). Needs the GIL.
pybind11::object stability_object(const queries::StabilityVerdicts& oracle, const exact::Vec<exact::Q>& g,
                                  const queries::StabilityOutcome& verdict);

}  // namespace contactcert::python
