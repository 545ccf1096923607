// Extreme rays of the cone {w in R^p : w >= 0, G w <= 0}, by the one double description engine
// (double_description.h) in the ring of T. This is the tangent cone of a degenerate vertex in the non-basic
// coordinates of one of its bases (adjacent_vertices.h).
#pragma once

#include <optional>
#include <vector>

#include "exact/number.h"

namespace contactcert::exact {

/// The extreme rays of {w >= 0 : G w <= 0} (G is k x p; a pointed cone), each scaled so that its first non-zero
/// entry is 1, in the order of the double description on the orthant's rays e_1, ..., e_p with the rows of G added
/// in order. Budget: at most max_rays rays held at once (DdBudget::max_rays), else nullopt (the budget ran out).
template <class T>
std::optional<std::vector<Vec<T>>> orthant_cone_rays(const Mat<T>& G, long max_rays);

extern template std::optional<std::vector<Vec<double>>> orthant_cone_rays<double>(const Mat<double>&, long);
extern template std::optional<std::vector<Vec<Q>>> orthant_cone_rays<Q>(const Mat<Q>&, long);

}  // namespace contactcert::exact
