// A planar scene extruded into space (the tests' planar consistency, issue 34): each fixel twice, at z = +1 and
// z = -1, its normal in the plane, frame (t, z) with t the planar tangent (-n_y, n_x) and t2 = (0, 0, |n|^2), a
// square pyramid of half-width mu along t1 and t2; a body of mass 1 with I = diag(1, 1, I/m) about the planar com.
#pragma once

#include "geometry/planar_scene.h"
#include "geometry/spatial_scene.h"

namespace contactcert::solvers::spatial {

inline geometry::SpatialScene extruded(const geometry::PlanarScene& ps, bool mu_of_fixels) {
  using exact::Q;
  geometry::SpatialScene s;
  s.body.mass = 1;
  s.body.inertia = {{{Q(1), Q(0), Q(0)}, {Q(0), Q(1), Q(0)}, {Q(0), Q(0), ps.workpiece.inertia_per_mass}}};
  s.body.com = {ps.workpiece.com.x, ps.workpiece.com.y, Q(0)};
  for (const geometry::Fixel& f : ps.fixels)
    for (const int z : {1, -1}) {
      geometry::SpatialContact c;
      const geometry::Point2 p = f.frame.point, n = f.frame.normal;
      c.point = {p.x, p.y, Q(z)};
      c.normal = {n.x, n.y, Q(0)};
      c.t1 = {-n.y, n.x, Q(0)};
      c.t2 = {Q(0), Q(0), n.x * n.x + n.y * n.y};
      const Q mu = mu_of_fixels ? f.mu_s : Q(1);
      c.edges = {{mu, 0}, {0, mu}, {-mu, 0}, {0, -mu}};
      s.contacts.push_back(std::move(c));
    }
  return s;
}

}  // namespace contactcert::solvers::spatial
