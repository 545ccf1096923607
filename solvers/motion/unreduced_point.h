// A point's coordinates as unreduced fractions (exact/unreduced.h) over one denominator, so that differences of
// points sharing it, and the products that cross2 and dot2 then subtract or add, meet equal denominators (no cross
// multiplication); the float path's points as they are (one formula serves both paths).
#pragma once

#include "exact/unreduced.h"
#include "geometry/rigid_motion.h"

namespace contactcert::solvers::motion {

using exact::unreduced;

/// p over its coordinates' denominator when they share it, else over the product of theirs.
inline geometry::Vec2<exact::Unreduced> unreduced(const geometry::Vec2<exact::Q>& p) {
  if (mpz_cmp(mpq_denref(p.x.get_mpq_t()), mpq_denref(p.y.get_mpq_t())) == 0)
    return {{p.x.get_num(), p.x.get_den()}, {p.y.get_num(), p.y.get_den()}};
  const exact::Z d = p.x.get_den() * p.y.get_den();
  return {{p.x.get_num() * p.y.get_den(), d}, {p.y.get_num() * p.x.get_den(), d}};
}
inline const geometry::Vec2<double>& unreduced(const geometry::Vec2<double>& p) { return p; }

}  // namespace contactcert::solvers::motion
