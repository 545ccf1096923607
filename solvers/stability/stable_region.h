// The strongly stable set of a fixture, exactly (wrench cone paper, section 7, eq. 19): wrench space is
// cut by the planes of the weakly stable cone and of every moving mode's wrench cone into relatively
// open cells (geometry/sphere_arrangement.h); on each cell the verdict of strong_stability is constant,
// so each cell gets one label.
#pragma once

#include <vector>

#include "geometry/face_cone.h"
#include "geometry/sphere_arrangement.h"
#include "solvers/stability/strong_stability.h"
#include "solvers/wrench_cone/wrench_cone.h"

namespace contactcert::solvers {

template <class T>
struct LabelledCell {
  int dimension = 3;
  Vec<T> point;  ///< representative wrench of the cell
  StabilityVerdict label = StabilityVerdict::kUnstable;
};

template <class T>
struct StableRegion {
  std::vector<Eigen::Index> touching;        ///< the touching fixels the analysis uses
  geometry::FaceCone<T> weak;                ///< wrenches with a resting solution: -pos(friction cone edges)
  std::vector<ModeString> modes;             ///< the moving modes with a non-empty wrench cone, in mode tree order
  long tree_nodes = 0;                       ///< prefixes the mode tree visited to find them
  std::vector<geometry::FaceCone<T>> cones;  ///< their wrench cones
  Mat<T> planes;                             ///< the arrangement's planes
  std::vector<LabelledCell<T>> cells;
  /// The label of wrench g from the cones (the same verdict strong_stability gives, without LPs).
  StabilityVerdict label(const Vec<T>& g) const;
};

/// The weakly stable cone {g : J c + g = 0 for some c in the static friction cones}: -pos of the edges
/// J_n,i +- mu_s J_t,i of the touching fixels' friction cones, as a minimal face cone.
template <class T>
geometry::FaceCone<T> weakly_stable_cone(const geometry::PlanarScene& touching_scene);

/// The weak cone and the non-empty wrench cones of the moving modes of the touching fixels (a StableRegion without
/// its arrangement: planes and cells empty), from the mode tree as stable_region.
template <class T>
StableRegion<T> mode_cones(const geometry::PlanarScene& scene, Route route = Route::kPaper,
                           const ModeTreeOptions& tree = {});

/// The same from the modes of a tree already walked over the scene's touching fixels with moving_alphabet (a
/// StabilityOracle's mode_tree()), in that tree's order, without walking it again; tree_nodes is that tree's.
template <class T>
StableRegion<T> mode_cones(const geometry::PlanarScene& scene, const ModeTree<T>& tree, Route route = Route::kPaper,
                           const exact::Deadline& deadline = {});

/// The wrench cones of every moving mode of the touching fixels and the labelled cells of wrench space. Only
/// the kinematically feasible modes (mode_tree.h) have a non-empty cone (forces c = 0 put M vdot in it), so
/// only theirs are computed. The tree options' deadline also bounds the cones (their conversions' loops test it) and
/// the arrangement (its loops test it, geometry::ArrangementBudget); past it, or past the arrangement's sign budget:
/// exact::BudgetExceeded.
template <class T>
StableRegion<T> stable_region(const geometry::PlanarScene& scene, Route route = Route::kPaper,
                              const ModeTreeOptions& tree = {});

#define CONTACTCERT_STABLE_REGION_EXTERN(T)                                                                   \
  extern template struct StableRegion<T>;                                                                     \
  extern template geometry::FaceCone<T> weakly_stable_cone<T>(const geometry::PlanarScene&);                  \
  extern template StableRegion<T> mode_cones<T>(const geometry::PlanarScene&, Route, const ModeTreeOptions&); \
  extern template StableRegion<T> mode_cones<T>(const geometry::PlanarScene&, const ModeTree<T>&, Route,      \
                                                const exact::Deadline&);                                      \
  extern template StableRegion<T> stable_region<T>(const geometry::PlanarScene&, Route, const ModeTreeOptions&);
CONTACTCERT_STABLE_REGION_EXTERN(double)
CONTACTCERT_STABLE_REGION_EXTERN(Q)
#undef CONTACTCERT_STABLE_REGION_EXTERN

}  // namespace contactcert::solvers
