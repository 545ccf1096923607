// Where a frictionless finger pushing along the inward normal of the workpiece boundary gives a strongly
// stable, only weakly stable or unstable wrench (wrench cone paper, section 7, the dark line of Figure 5).
// The push wrench is affine in the position along a polygon edge and linear in the direction on a disk,
// so each cone row changes sign at most once per edge (twice per circle): the labels are constant between
// exactly computed breakpoints.
#pragma once

#include <functional>
#include <vector>

#include "exact/deadline.h"
#include "solvers/stability/stable_region.h"

namespace contactcert::solvers {

/// A maximal piece of one polygon edge with one label: s in (from, to) with the ends included or not.
/// The point at parameter s is v_e + s (v_{e+1} - v_e); vertices (s = 0, 1) are excluded (no normal).
template <class T, class Label>
struct EdgeInterval {
  std::size_t edge = 0;
  T from, to;
  bool from_closed = false, to_closed = false;
  Label label{};
};

/// A maximal arc of a disk with one label, from direction `from` to `to` counter-clockwise (directions
/// from the centre, exact, not normalised); a single point when from == to and both ends are closed, the
/// whole circle when from == to and both ends are open.
template <class T, class Label>
struct ArcInterval {
  Vec<T> from, to;
  bool from_closed = false, to_closed = false;
  Label label{};
};

template <class T, class Label>
struct BoundaryPieces {
  std::vector<EdgeInterval<T, Label>> edges;  ///< polygon workpieces
  std::vector<ArcInterval<T, Label>> arcs;    ///< disk workpieces
};

/// The boundary of the workpiece cut into maximal pieces on which label(push wrench) is constant, given
/// that label only changes where some row f of `rows` has f . g = 0.
template <class T, class Label>
BoundaryPieces<T, Label> boundary_pieces(const geometry::PlanarScene& scene, const std::vector<Vec<T>>& rows,
                                         const std::function<Label(const Vec<T>&)>& label);

/// Every row (inequality, equality, strict) of the given face cones.
template <class T>
std::vector<Vec<T>> cone_rows(const std::vector<const geometry::FaceCone<T>*>& cones);

template <class T>
using FingerPushes = BoundaryPieces<T, StabilityVerdict>;

/// Where a frictionless finger push is strongly stable, weakly stable or unstable, from the region's cones. Throws
/// exact::BudgetExceeded (with the pieces labelled) once `deadline` has passed, tested before each piece's label.
template <class T>
FingerPushes<T> finger_pushes(const geometry::PlanarScene& scene, const StableRegion<T>& region,
                              const exact::Deadline& deadline = {});

/// The wrench of a unit-free frictionless push at boundary point p along inward normal n: (n, (p - com) x n).
template <class T>
Vec<T> push_wrench(const geometry::Point2& com, const Vec<T>& p, const Vec<T>& n);

#define CONTACTCERT_FINGER_EXTERN(T)                                                                        \
  extern template std::vector<Vec<T>> cone_rows<T>(const std::vector<const geometry::FaceCone<T>*>&);       \
  extern template BoundaryPieces<T, StabilityVerdict> boundary_pieces<T, StabilityVerdict>(                 \
      const geometry::PlanarScene&, const std::vector<Vec<T>>&,                                             \
      const std::function<StabilityVerdict(const Vec<T>&)>&);                                               \
  extern template BoundaryPieces<T, bool> boundary_pieces<T, bool>(                                         \
      const geometry::PlanarScene&, const std::vector<Vec<T>>&, const std::function<bool(const Vec<T>&)>&); \
  extern template FingerPushes<T> finger_pushes<T>(const geometry::PlanarScene&, const StableRegion<T>&,    \
                                                   const exact::Deadline&);                                 \
  extern template Vec<T> push_wrench<T>(const geometry::Point2&, const Vec<T>&, const Vec<T>&);
CONTACTCERT_FINGER_EXTERN(double)
CONTACTCERT_FINGER_EXTERN(Q)
#undef CONTACTCERT_FINGER_EXTERN

}  // namespace contactcert::solvers
