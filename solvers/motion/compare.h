// The float run against the exact one, step by step: the first step where they differ (verdict, a contact missed
// or phantom, a contact's mode, the float pose overlapping a shape when its own numbers are checked exactly, the
// run's end) and how far apart the poses are then.
#pragma once

#include <string>
#include <vector>

#include "solvers/motion/simulate.h"

namespace contactcert::solvers::motion {

/// The first step at which the float run differs from the exact one in one way (`kind`): "verdict", "contacts" (a
/// contact missed or phantom), "mode", "penetration" (the float pose, its doubles checked exactly, overlaps a
/// shape), "run_end" (a different status or step count).
struct Divergence {
  long step = -1;
  std::string kind;
  std::string what;          ///< e.g. "phantom contact: body vertex 2 on ceiling edge 3"
  double pose_distance = 0;  ///< max over bodies' vertices of |p_exact - p_float| after that step (or at the end)
  double time_exact = 0, time_float = 0;  ///< the step's start times
};

/// Compares the exact (or verified) run with the float run of the same scene: the first divergence of each kind, in
/// step order (empty: the runs agree on every verdict, contact and mode, and no float pose overlaps).
std::vector<Divergence> compare_runs(const MotionScene& scene, const Trajectory<Q>& exact_run,
                                     const Trajectory<double>& float_run);

/// max over the bodies' vertices of the distance between their positions under the two poses of their body.
double pose_distance(const MotionScene& scene, const Poses<Q>& a, const Poses<double>& b);

}  // namespace contactcert::solvers::motion
