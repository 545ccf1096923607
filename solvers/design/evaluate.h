// One placement of a fixture design problem, decided exactly, cheapest necessary tests first:
//   1. a symmetric image of an earlier placement is skipped (symmetry.h);
//   2. every wrench (generator) of the set lies in the weakly stable cone -pos(friction cone edges)
//      (section 7: necessary for any resting solution; a face-form membership test, no LP);
//   3. every wrench (generator) is strongly stable (StabilityOracle: one LP per kinematically feasible mode);
//   4. a cone of wrenches meets no moving mode's wrench cone except at 0 (eq. 19: then the whole cone is in
//      G_strong, given 2-3);
//   5. G_goal != {} (eq. 21 / Table 5): a push point's push or the required wrench lies in it, or else some
//      cell of the arrangement of the insertion cones' planes lies in no cone (read off the cell's signs);
//      G_goal holds the required wrench if one is given, and the frictionless push at some push point if that
//      is required.
// Fixels all touch by construction, so stability considers every fixel of the placement.
#pragma once

#include <vector>

#include "solvers/design/problem.h"
#include "solvers/design/symmetry.h"
#include "solvers/insertion/insertion.h"
#include "solvers/stability/margin.h"
#include "solvers/stability/strong_stability.h"

namespace contactcert::solvers {

enum class PlacementStatus {
  kAccepted,
  kSymmetricDuplicate,
  kNotWeaklyStable,
  kNotStronglyStable,
  kConeMeetsMovingMode,
  kNotInsertable,
  kGoalMissesWrench,
  kNoPushInGoal,
};
constexpr int kPlacementStatusCount = 8;
const char* placement_status_name(PlacementStatus s);

/// The evidence behind an accepted placement's verdicts, for the report and its certificates.
struct PlacementEvidence {
  std::vector<StabilityResult<exact::Q>> stability;  ///< per wrench (generator), with its proofs
  std::vector<Margin<exact::Q>> margins;             ///< per wrench (generator), if ranked by margin
  exact::Vec<exact::Q> goal_witness;                 ///< a wrench in G_goal, if insertable was asked
  long goal_pushes = 0;                              ///< push points whose frictionless push lies in G_goal
  long goal_push_point = -1;                         ///< the push point of goal_witness, if it is a push
};

struct Evaluation {
  PlacementStatus status = PlacementStatus::kAccepted;
  exact::Q figure = 0;  ///< the rank's figure (accepted placements only)
  long lps = 0;         ///< LPs solved for the stability verdicts
};

/// Decides one placement (increasing candidate indices). With `evidence`, an accepted placement's verdicts
/// keep their proofs and witnesses there; with `cones` (one per problem), insertion cones are shared across
/// placements.
Evaluation evaluate_placement(const DesignProblem& problem, const CandidateSymmetry& symmetry,
                              const Placement& placement, PlacementEvidence* evidence = nullptr,
                              InsertionCones<exact::Q>* cones = nullptr);

}  // namespace contactcert::solvers
