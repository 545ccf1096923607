// The stability margin of section 8: for a strongly stable biasing wrench g, the squared radius of the
// largest ball around g inside G_strong (eq. 19), exactly: the least squared distance from g to the
// closure of a moving mode's cone or to the boundary of the weakly stable cone.
#pragma once

#include "geometry/span_cone.h"
#include "solvers/stability/stable_region.h"

namespace contactcert::solvers {

/// min ||g - h||^2 over h in pos(rays) + span(lines), exactly: the nearest point is the projection of g
/// onto the span of some face, so every independent set of at most 3 generators is tried.
template <class T>
T squared_distance(const Vec<T>& g, const geometry::SpanCone<T>& cone);

template <class T>
struct Margin {
  T squared_radius = T(0);  ///< 0 when g is not strongly stable
  /// The nearest obstacle: a moving mode, or "weak" for the boundary of the weakly stable cone.
  std::string nearest;
};

/// The margin of g in the region (0 unless g is strongly stable).
template <class T>
Margin<T> stability_margin(const StableRegion<T>& region, const Vec<T>& g);

extern template Q squared_distance<Q>(const Vec<Q>&, const geometry::SpanCone<Q>&);
extern template double squared_distance<double>(const Vec<double>&, const geometry::SpanCone<double>&);
extern template Margin<Q> stability_margin<Q>(const StableRegion<Q>&, const Vec<Q>&);
extern template Margin<double> stability_margin<double>(const StableRegion<double>&, const Vec<double>&);

}  // namespace contactcert::solvers
