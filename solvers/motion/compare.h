// The float run against the exact one, step by step: the first step where they differ (verdict, a contact missed
// or phantom, a contact's mode, the float pose overlapping a shape when its own numbers are checked exactly, the
// run's end) and how far apart the poses are then.
#pragma once

#include <string>

#include "solvers/motion/simulate.h"

namespace contactcert::solvers::motion {

struct Divergence {
  long step = -1;    ///< first step that differs (-1: none over the common steps and the same end)
  std::string what;  ///< "verdict: solvable vs jammed", "missed contact ...", "phantom contact ...", "mode ...",
                     ///< "penetration: ...", "run end: completed vs overlap"
  double pose_distance = 0;  ///< max over body vertices of |p_exact - p_float| after that step (or at the end)
  double time_exact = 0, time_float = 0;  ///< the step's start times
};

/// Compares the exact (or verified) run with the float run of the same scene.
Divergence compare_runs(const MotionScene& scene, const Trajectory<Q>& exact_run, const Trajectory<double>& float_run);

/// max over the body's vertices of the distance between their positions under the two poses.
double pose_distance(const MotionScene& scene, const Pose<Q>& a, const Pose<double>& b);

}  // namespace contactcert::solvers::motion
