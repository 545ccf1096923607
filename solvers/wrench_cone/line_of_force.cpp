#include "solvers/wrench_cone/line_of_force.h"

namespace contactcert::solvers {

LineOfForce line_of_force(const exact::Vec<exact::Q>& g, const geometry::Point2& com) {
  LineOfForce l;
  l.direction = {g(0), g(1)};
  l.torque = g(2);
  const exact::Q f2 = geometry::norm2(l.direction);
  if (sgn(f2) == 0) {
    l.kind = sgn(l.torque) == 0 ? LineOfForce::Kind::kZero : LineOfForce::Kind::kPureMoment;
    l.through = com;
    return l;
  }
  // r x f = torque with r = torque / |f|^2 * (f_y, -f_x), the foot of the perpendicular from the com.
  l.kind = LineOfForce::Kind::kForce;
  const exact::Q s = l.torque / f2;
  l.through = com + geometry::Point2{s * l.direction.y, -s * l.direction.x};
  return l;
}

}  // namespace contactcert::solvers
