// A quasistatic scene to simulate over time (docs/formats.md, "Motion"): a `"kind": "quasistatic_scene"` whose
// contacts are not listed but found from geometry at every step: one movable convex polygonal workpiece (or several
// movable convex polygonal bodies), fixed convex polygonal obstacles, point fingers with piecewise-constant velocity or
// force schedules (world axes), and the step size and count.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "exact/json_input.h"
#include "geometry/workpiece.h"

namespace contactcert::solvers::motion {

using exact::Q;
using geometry::Point2;

/// A fixed convex obstacle (counter-clockwise vertices) and the friction coefficient of its contacts.
struct Obstacle {
  std::string name;
  std::vector<Point2> vertices;
  Q mu;
};

/// One piece of a finger's schedule: for `duration` (nullopt: for ever) the finger's velocity, or the force it
/// applies, in world axes.
struct ScheduleSegment {
  std::optional<Q> duration;
  bool force = false;
  Point2 value;
};

/// A point finger: its tip at time 0, the friction coefficient of its contact, its schedule.
struct Finger {
  std::string name;
  Point2 tip;
  Q mu;
  std::vector<ScheduleSegment> schedule;
};

/// A movable body: its name ("body" for a scene's one `workpiece`), its shape and com at time 0 (its body frame is
/// the world frame then), its weight m g (a force at the com), and the friction coefficient of a contact on one of
/// its edges made by another body's vertex.
struct MovingBody {
  std::string name;
  geometry::Workpiece workpiece;  ///< a convex polygon
  Point2 weight{Q(0), Q(0)};
  Q mu;
};

/// The whole scene: one body (`workpiece`) or several (`bodies`), in the order of their q_dot blocks.
struct MotionScene {
  std::vector<MovingBody> bodies;
  std::vector<Obstacle> obstacles;
  std::vector<Finger> fingers;
  Q dt;        ///< step size H > 0
  long steps;  ///< step count N >= 1
  std::string file;
};

/// The segment of a schedule in force at time t and the time at which it ends (nullopt: never).
struct ScheduleAt {
  const ScheduleSegment* segment;
  std::optional<Q> ends;
};
ScheduleAt schedule_at(const Finger& f, const Q& t);

/// Reads a motion scene; throws exact::InputError naming the field (a non-convex polygon, an empty schedule, a
/// step size <= 0, ...).
MotionScene read_motion_scene(const exact::JsonInput& root);

/// True if `root` is a motion scene (a quasistatic_scene with "motion").
bool is_motion_scene(const exact::JsonInput& root);

}  // namespace contactcert::solvers::motion
