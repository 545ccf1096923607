// A JSON value of the query layer as the Python objects that json.loads builds from its text (dict in the same key
// order, list, str, int, float, bool, None), without the text: for results that cross in bulk.
#pragma once

#include <pybind11/pybind11.h>

#include "queries/json_out.h"

namespace contactcert::python {

/// What json.loads(j.dump()) returns (a non-finite double, which dump() writes as null, is None). Needs the GIL.
pybind11::object json_objects(const queries::json& j);

}  // namespace contactcert::python
