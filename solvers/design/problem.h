// A fixture design problem (wrench cone paper, sections 7-10): a workpiece, its friction, candidate fixel
// positions, how many fixels to place, and what a placement must achieve: strong stability under a set of
// external wrenches (section 7, eq. 19) and/or a non-empty G_goal for sensorless insertion (sections 8-9).
#pragma once

#include <string>
#include <vector>

#include "geometry/planar_scene.h"
#include "solvers/design/candidates.h"

namespace contactcert::solvers {

/// The wrenches a placement must hold strongly stable: a finite list, or the polyhedral cone pos(rows).
struct WrenchSet {
  enum class Kind { kNone, kList, kCone } kind = Kind::kNone;
  exact::Mat<exact::Q> rows = exact::Mat<exact::Q>(0, 3);  ///< the wrenches, or the cone's generators
};

/// The objective: margin = min over the set's wrenches (generators) of the squared stability margin
/// (section 8, eq. 19's ball); goal_fraction = the fraction of the push points (DesignProblem::pushes) at which a
/// frictionless push along the inward normal lies in G_goal (exact: a count).
enum class Rank { kMargin, kGoalFraction };
const char* rank_name(Rank r);

struct DesignProblem {
  geometry::Workpiece workpiece;
  exact::Q mu_s, mu_k;
  std::vector<Candidate> candidates;
  std::vector<Candidate> pushes;  ///< the boundary points whose frictionless pushes the goal fraction counts
  int fixels = 3;                 ///< 2 or 3
  WrenchSet wrenches;
  bool insertable = false;           ///< require G_goal != {} (eq. 21 for 2 fixels, Table 5 for 3)
  exact::Vec<exact::Q> goal_wrench;  ///< if not empty: G_goal must contain this wrench (insertable implied)
  bool goal_push = false;  ///< G_goal must contain the frictionless push at some push point (insertable implied)
  Rank rank = Rank::kMargin;
};

/// A placement: `fixels` increasing candidate indices.
using Placement = std::vector<int>;

/// The scene of a placement: the workpiece with a touching fixel at each chosen candidate (explicit contact
/// frame: the candidate point and its inward normal, gap 0), in the order of the placement.
geometry::PlanarScene placement_scene(const DesignProblem& problem, const Placement& placement);

/// The same scene as a scene file's text (SPEC section 3), exact numbers as strings: what certificates embed
/// and `contactcert stability` / `insert` read back.
std::string placement_scene_text(const DesignProblem& problem, const Placement& placement, const std::string& name);

}  // namespace contactcert::solvers
