// A wrench g = (f_x, f_y, torque about the com) read as a directed line of force (wrench cone
// paper, section 4: "each generator corresponds to a wrench, which we may view as a directed line
// of force"), exactly.
#pragma once

#include "exact/number.h"
#include "geometry/workpiece.h"

namespace contactcert::solvers {

/// The line of force of a wrench, or a pure moment when the force is zero.
struct LineOfForce {
  enum class Kind { kForce, kPureMoment, kZero } kind = Kind::kZero;
  geometry::Point2 direction;  ///< (f_x, f_y)
  geometry::Point2 through;    ///< the point of the line closest to the com (absolute coordinates)
  exact::Q torque;             ///< about the com; its sign is the sense of a pure moment
};

/// The line {through + s * direction} along which force (f_x, f_y) has the torque of g about `com`.
LineOfForce line_of_force(const exact::Vec<exact::Q>& g, const geometry::Point2& com);

}  // namespace contactcert::solvers
