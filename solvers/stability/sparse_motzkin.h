// Motzkin vectors as certificates write them (docs/formats.md, section 5): only the weighted rows, as a list of
// pairs [row, "weight"] with the rows (0-based, in the layout of the system the vector refers to) strictly
// increasing and the weights the non-zero entries of the primitive integer multiple of the vector. A positive
// multiple of a Motzkin certificate is one (its conditions are signs of y^T A and y^T b), so the scale carries
// no information and the primitive multiple is the vector's one spelling; a certificate's size is linear in the
// rows it weighs (typically a handful) rather than in the rows of its system. The checker reads them
// (checker/sparse_motzkin_reader.h).
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <vector>

#include "exact/number.h"

namespace contactcert::solvers {

/// The weighted rows of y, scaled to primitive integers, as [[row, "weight"], ...] (rows ascending).
nlohmann::ordered_json sparse_motzkin_json(const exact::Vec<exact::Q>& y);

/// The same for a vector given by its non-zero entries: rows ascending and their weights.
nlohmann::ordered_json sparse_motzkin_json(const std::vector<std::size_t>& rows, const std::vector<exact::Q>& weights);

}  // namespace contactcert::solvers
