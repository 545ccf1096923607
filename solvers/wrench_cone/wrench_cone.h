// The wrench cone algorithm (Balkcom, Trinkle 2002, section 5): the set of external wrenches
// g = (f_x, f_y, torque about the com) consistent with an augmented contact mode, exactly, by the
// paper's route (F = K^F P, eq. 18) or by the output-sensitive projection route; strict rows of
// Table 2 as exact limits (section 5.6).
#pragma once

#include "geometry/nnc_cone.h"
#include "geometry/planar_scene.h"
#include "geometry/projection.h"
#include "solvers/wrench_cone/cone_form.h"

namespace contactcert::solvers {

/// Which way F is computed: the paper's (pos(K) converted to K^F, F = K^F P) or the projection
/// route (facets discovered one by one by exact LPs in 3-dimensional wrench space).
enum class Route { kPaper, kProject };

enum class ConeStatus { kEmpty, kNonEmpty };

/// What is done to K z = P g before a route sees it. kRowReduce multiplies both sides by an
/// invertible T with T P = [P1; 0] (row echelon form): the rows 0 = K2 z then constrain z alone and
/// are kept as a basis of their span, so pos(K) is converted in 3 + rank(K2) dimensions instead of
/// 2n (for 'n...n' modes, K2 = 0 and the conversion is 3-dimensional). Same cone, exactly.
enum class Preconditioning { kNone, kRowReduce };

/// The wrench cone of one mode with its evidence.
template <class T>
struct WrenchCone {
  ConeStatus status = ConeStatus::kEmpty;
  ModeString mode;
  Route route = Route::kPaper;
  ConeForm<T> form;           ///< K, P and the strict components of z (eqs. 13-17)
  geometry::NncForm<T> cone;  ///< face form (strict rows = open faces), closure generators, open faces
};

/// The face form of the wrench cone of `mode` (minimal; canonical for T = Q). An empty cone is
/// encoded as in geometry::NncForm (equalities = identity and one zero strict row).
template <class T>
geometry::FaceCone<T> wrench_cone_face(const geometry::PlanarScene& scene, const ContactModel<T>& model,
                                       const ModeString& mode, Route route, const geometry::DdBudget& budget = {},
                                       Preconditioning pre = Preconditioning::kRowReduce);

/// The wrench cone of `mode` in both forms. `mode` must fit the scene (parse_mode).
template <class T>
WrenchCone<T> wrench_cone(const geometry::PlanarScene& scene, const ModeString& mode, Route route,
                          const geometry::DdBudget& budget = {}, Preconditioning pre = Preconditioning::kRowReduce);

/// Is this face form the empty-cone encoding of geometry::NncForm?
template <class T>
bool is_empty_cone(const geometry::FaceCone<T>& face);

/// Theorem 1 with minimum accelerations (section 5.6): the wrenches for which the mode holds with
/// every constrained acceleration component of z at least a_min > 0 (forces still >= 0), as
/// { g : A g <= b, C g = c }. Not a cone when a_min > 0.
template <class T>
geometry::AffineFace<T> wrench_set_with_minimum_acceleration(const geometry::PlanarScene& scene, const ModeString& mode,
                                                             const Q& a_min, const geometry::DdBudget& budget = {});

#define CONTACTCERT_WRENCH_CONE_EXTERN(T)                                                                         \
  extern template geometry::FaceCone<T> wrench_cone_face<T>(const geometry::PlanarScene&, const ContactModel<T>&, \
                                                            const ModeString&, Route, const geometry::DdBudget&,  \
                                                            Preconditioning);                                     \
  extern template WrenchCone<T> wrench_cone<T>(const geometry::PlanarScene&, const ModeString&, Route,            \
                                               const geometry::DdBudget&, Preconditioning);                       \
  extern template bool is_empty_cone<T>(const geometry::FaceCone<T>&);                                            \
  extern template geometry::AffineFace<T> wrench_set_with_minimum_acceleration<T>(                                \
      const geometry::PlanarScene&, const ModeString&, const Q&, const geometry::DdBudget&);
CONTACTCERT_WRENCH_CONE_EXTERN(double)
CONTACTCERT_WRENCH_CONE_EXTERN(Q)
#undef CONTACTCERT_WRENCH_CONE_EXTERN

}  // namespace contactcert::solvers
