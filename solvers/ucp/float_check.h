// Exact checks of UCP verdicts found in floating point (the rungs of --arith adaptive below exact). A float
// complementary pair is trusted only through its zero pattern and a float search tree only through its
// shape: the numbers that prove the verdict are recomputed in exact arithmetic, so a verdict that passes
// is the exact one (SPEC section 7).
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "solvers/ucp/search.h"

namespace contactcert::solvers::ucp {

/// An exact complementary pair with the zero pattern of a float one (x_approx, y_approx): x in X with x_i = 0
/// where x_zero[i], y in Y with y_i = 0 where y_zero[i]. Every index must be in one pattern (then x^T y = 0).
/// Each side is first the float point rounded to fractions and checked in integers, else an exact face LP.
/// nullopt if one of the two faces is empty in exact arithmetic.
std::optional<std::pair<Vec<Q>, Vec<Q>>> exact_pair(const UcpInstance<Q>& ucp, const Vec<double>& x_approx,
                                                    const Vec<double>& y_approx, const std::vector<bool>& x_zero,
                                                    const std::vector<bool>& y_zero, LpCounters& count);

/// Turns the shape of a float search tree (branches, children, the side of each leaf) into an exact proof:
/// every leaf gets an exact Farkas vector for the face its path fixes on its side, an earlier leaf's vector
/// if it covers the fixings (as the search's learning does), else that of an exact face LP. false if some
/// leaf's face is not empty in exact arithmetic.
bool prove_leaves(const UcpInstance<Q>& ucp, std::vector<SearchNode<Q>>& tree, LpCounters& count);

}  // namespace contactcert::solvers::ucp
