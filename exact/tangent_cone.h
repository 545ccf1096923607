// Extreme rays of the cone {w in R^p : w >= 0, G w <= 0}, by the one double description engine
// (double_description.h) in the ring of T. This is the tangent cone of a degenerate vertex in the non-basic
// coordinates of one of its bases (adjacent_vertices.h).
#pragma once

#include <vector>

#include "exact/number.h"

namespace contactcert::exact {

enum class ConeStatus { kComplete, kBudgetExceeded };

template <class T>
struct OrthantConeRays {
  ConeStatus status = ConeStatus::kComplete;
  std::vector<Vec<T>> rays;  ///< the extreme rays, each scaled so that its first non-zero entry is 1
};

/// The extreme rays of {w >= 0 : G w <= 0} (G is k x p; a pointed cone), in the order of the double
/// description on the orthant's rays e_1, ..., e_p with the rows of G added in order. Budget: at most max_rays
/// rays held at once (DdBudget::max_rays), else status kBudgetExceeded and no rays.
template <class T>
OrthantConeRays<T> orthant_cone_rays(const Mat<T>& G, long max_rays);

extern template OrthantConeRays<double> orthant_cone_rays<double>(const Mat<double>&, long);
extern template OrthantConeRays<Q> orthant_cone_rays<Q>(const Mat<Q>&, long);

}  // namespace contactcert::exact
