// Motzkin vectors as certificates write them (docs/formats.md, section 5): only the weighted rows, as a list of
// pairs [row, "weight"] with the rows (0-based, in the layout of the system the vector refers to) strictly
// increasing and the weights the non-zero entries of the primitive integer multiple of the vector. A positive
// multiple of a Motzkin certificate is one (its conditions are signs of y^T A and y^T b), so the scale carries
// no information and the primitive multiple is the vector's one spelling; a certificate's size is linear in the
// rows it weighs (typically a handful) rather than in the rows of its system.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>

#include "exact/json_input.h"
#include "exact/number.h"

namespace contactcert::solvers {

/// The weighted rows of y, scaled to primitive integers, as [[row, "weight"], ...] (rows ascending).
nlohmann::ordered_json sparse_motzkin_json(const exact::Vec<exact::Q>& y);

/// The vector of `rows` entries that a list written by sparse_motzkin_json stands for. Throws InputError naming the
/// entry for an empty list, an entry that is not a pair, a row that is not an integer in [0, rows), a row not
/// above the one before (repeated or out of order), a weight that is zero or not an integer, and weights with a
/// common factor (not primitive).
exact::Vec<exact::Q> read_sparse_motzkin(const exact::JsonInput& list, std::size_t rows);

}  // namespace contactcert::solvers
