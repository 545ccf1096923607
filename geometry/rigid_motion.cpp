#include "geometry/rigid_motion.h"

#include <cmath>

namespace contactcert::geometry {

double turned_angle(const Pose<double>& p) { return std::atan2(p.s, p.c); }

Pose<double> to_double(const Pose<exact::Q>& p) { return {p.c.get_d(), p.s.get_d(), {p.t.x.get_d(), p.t.y.get_d()}}; }

}  // namespace contactcert::geometry
