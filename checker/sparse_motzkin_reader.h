// The checker's reader of Motzkin vectors as certificates write them (docs/formats.md, section 5;
// solvers/stability/sparse_motzkin.h writes them): the weighted rows as pairs [row, "weight"], rows strictly
// increasing, weights the non-zero entries of the vector's primitive integer multiple (its one spelling).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "exact/json_input.h"
#include "exact/number.h"

namespace contactcert::checker {

/// The vector of `rows` entries that a list written by solvers::sparse_motzkin_json stands for. Throws InputError
/// naming the entry for an empty list, an entry that is not a pair, a row that is not an integer in [0, rows), a row
/// not above the one before (repeated or out of order), a weight that is zero or not an integer, and weights with a
/// common factor (not primitive).
exact::Vec<exact::Q> read_sparse_motzkin(const exact::JsonInput& list, std::size_t rows);

/// The same list as its (row, weight) pairs, rows ascending, without a vector of `rows` entries (a deep prefix's
/// certificate weighs a handful of its rows).
std::vector<std::pair<std::size_t, exact::Q>> read_sparse_motzkin_pairs(const exact::JsonInput& list, std::size_t rows);

}  // namespace contactcert::checker
