// The stable region as data a program can use (`stability --region --json`): the arrangement's planes, each
// cell's sign vector and a small-integer representative, and the strongly stable set as a union of merged cones
// in face form.
#pragma once

#include <vector>

#include "queries/json_out.h"
#include "solvers/stability/stable_region.h"

namespace contactcert::queries {

/// Per cell of the region, in order: an integer vector of the cell with smallest max-norm up to 24 where one
/// exists, else the primitive integer multiple of the cell's exact point.
std::vector<exact::Vec<exact::Q>> cell_representatives(const solvers::StableRegion<exact::Q>& region);

/// The "region" object: `planes` (primitive integer rows), `cells` (dimension, sign vector, a representative
/// of smallest max-norm found among integer vectors with entries in [-24, 24], else the primitive exact point;
/// label) and `strongly_stable_cones`: the strongly stable set as maximal sign cones (solvers/stability/
/// strong_cones.h), each in face form. g is strongly stable iff it lies in one of them.
json region_data_json(const solvers::StableRegion<exact::Q>& region);

}  // namespace contactcert::queries
