// The scene algorithms (strong stability, the wrench cone by either route, and the cone geometry under
// them) for the float number types of the precision ladder besides double: MPFR floats and double intervals
// (docs/precision.md). The instantiations are compiled once, beside the double and Q ones, in geometry/ and
// solvers/; this header declares them `extern`. A run in exact::Mpfr converts the scene at MPFR's default
// precision: hold an exact::MpfrPrecision for the rung's bits around it. A run in exact::Interval either
// takes every decision as the exact run would, or throws exact::UncertainSign (undecided, never a guess).
//
// Pulls in CGAL: include it only where these number types are used.
#pragma once

#include "exact/ladder_numbers.h"
#include "exact/strict_feasibility.h"
#include "geometry/canonical.h"
#include "geometry/double_description.h"
#include "geometry/nnc_cone.h"
#include "geometry/projection.h"
#include "solvers/stability/mode_tree.h"
#include "solvers/stability/motion_system.h"
#include "solvers/stability/strong_stability.h"
#include "solvers/wrench_cone/cone_form.h"
#include "solvers/wrench_cone/wrench_cone.h"

#define CONTACTCERT_SCENE_LADDER_EXTERN(T)                                                                           \
  namespace contactcert::exact {                                                                                     \
  extern template struct SparseStrictSystem<T>;                                                                      \
  extern template class StrictSolver<T>;                                                                             \
  extern template StrictFeasibility<T> strict_feasibility<T>(const SparseStrictSystem<T>&, Arith);                   \
  }                                                                                                                  \
  namespace contactcert::geometry {                                                                                  \
  extern template FaceCone<T> to_face<T>(const SpanCone<T>&, const DdBudget&);                                       \
  extern template SpanCone<T> to_span<T>(const FaceCone<T>&, const DdBudget&);                                       \
  extern template ConePair<T> both_forms<T>(const SpanCone<T>&, const DdBudget&);                                    \
  extern template ConePair<T> both_forms<T>(const FaceCone<T>&, const DdBudget&);                                    \
  extern template bool identical<T>(const FaceCone<T>&, const FaceCone<T>&);                                         \
  extern template bool identical<T>(const SpanCone<T>&, const SpanCone<T>&);                                         \
  extern template bool contains_point<T>(const FaceCone<T>&, const Vec<T>&);                                         \
  extern template PointPosition<T> locate<T>(const FaceCone<T>&, const Vec<T>&);                                     \
  extern template AffineFace<T> theorem1<T>(const Mat<T>&, const Mat<T>&, const Vec<T>&, const DdBudget&);           \
  extern template SpanCone<T> canonical<T>(const SpanCone<T>&);                                                      \
  extern template FaceCone<T> canonical<T>(const FaceCone<T>&);                                                      \
  extern template struct NncForm<T>;                                                                                 \
  extern template NncForm<T> nnc_form<T>(const FaceCone<T>&, const DdBudget&);                                       \
  extern template FaceCone<T> project_by_polar<T>(const ProjectionProblem<T>&, const DdBudget&);                     \
  extern template FaceCone<T> project_by_lp<T>(const ProjectionProblem<T>&, const DdBudget&);                        \
  }                                                                                                                  \
  namespace contactcert::solvers {                                                                                   \
  extern template ContactModel<T> contact_model<T>(const geometry::PlanarScene&);                                    \
  extern template ModeMatrices<T> mode_matrices<T>(const geometry::PlanarScene&, const ModeString&);                 \
  extern template ConeForm<T> cone_form<T>(const geometry::PlanarScene&, const ContactModel<T>&, const ModeString&); \
  extern template geometry::FaceCone<T> wrench_cone_face<T>(const geometry::PlanarScene&, const ContactModel<T>&,    \
                                                            const ModeString&, Route, const geometry::DdBudget&,     \
                                                            Preconditioning);                                        \
  extern template bool is_empty_cone<T>(const geometry::FaceCone<T>&);                                               \
  extern template geometry::AffineFace<T> wrench_set_with_minimum_acceleration<T>(const geometry::PlanarScene&,      \
                                                                                  const ModeString&, const Q&,       \
                                                                                  const geometry::DdBudget&);        \
  extern template MotionModel<T> motion_model<T>(const geometry::PlanarScene&);                                      \
  extern template exact::SparseStrictSystem<T> kinematic_system<T>(const MotionModel<T>&, const ModeString&,         \
                                                                   const KinematicRules&);                           \
  extern template struct MotionSystem<T>;                                                                            \
  extern template ModeTree<T> walk_modes<T>(const MotionModel<T>&, const ModeAlphabet&, const ModeTreeOptions&,      \
                                            const OnMode<T>&);                                                       \
  extern template bool realises<T>(const MotionModel<T>&, const KinematicRules&, const Vec<T>&, const ModeString&);  \
  extern template WrenchCone<T> wrench_cone<T>(const geometry::PlanarScene&, const ModeString&, Route,               \
                                               const geometry::DdBudget&, Preconditioning);                          \
  extern template MotionSystem<T> motion_system<T>(const MotionModel<T>&, const ModeString&, bool);                  \
  extern template class StabilityOracle<T>;                                                                          \
  extern template StabilityResult<T> strong_stability<T>(const geometry::PlanarScene&, const Vec<T>&,                \
                                                         const StabilityOptions&);                                   \
  }
CONTACTCERT_SCENE_LADDER_EXTERN(contactcert::exact::Mpfr)
CONTACTCERT_SCENE_LADDER_EXTERN(contactcert::exact::Interval)
#undef CONTACTCERT_SCENE_LADDER_EXTERN
