#include "queries/ucp_forces.h"

#include "queries/contact_forces.h"

namespace contactcert::queries {

using exact::Q;
using exact::Vec;

std::vector<solvers::WorldForce<Q>> scene_world_forces(const std::vector<geometry::ContactFrame>& frames,
                                                       const Vec<Q>& c_n, const Vec<Q>& c_t) {
  std::vector<solvers::WorldForce<Q>> out;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const geometry::ContactFrame& f = frames[i];
    const geometry::Point2 t = f.tangent();
    solvers::WorldForce<Q> w;
    w.fixel = static_cast<Eigen::Index>(i);
    w.point = Vec<Q>(2);
    w.point << f.point.x, f.point.y;
    w.normal = Vec<Q>(2);
    w.normal << f.normal.x, f.normal.y;
    w.tangent = Vec<Q>(2);
    w.tangent << t.x, t.y;
    w.c_n = c_n(w.fixel);
    w.c_t = c_t(w.fixel);
    w.force = w.c_n * w.normal + w.c_t * w.tangent;
    w.torque = geometry::cross(f.point, geometry::Point2{w.force(0), w.force(1)});
    out.push_back(std::move(w));
  }
  return out;
}

json ucp_forces_json(const std::vector<geometry::ContactFrame>& frames, const Vec<Q>& c_n, const Vec<Q>& c_t) {
  return forces_json(scene_world_forces(frames, c_n, c_t), "contact");
}

std::string ucp_forces_text(const std::vector<geometry::ContactFrame>& frames, const Vec<Q>& c_n, const Vec<Q>& c_t) {
  if (frames.empty())
    return "  c_n, c_t are against the problem's own contact frames (the rows of W^T in P and of J_n, J_t, of the "
           "length written, not unit); the problem states no geometry, so no world vectors are printed\n";
  return "  contact forces (world coordinates; torque about the world origin; n_i as written, t_i = (-n_iy, "
         "n_ix)):\n" +
         forces_text(scene_world_forces(frames, c_n, c_t), "contact", "    ");
}

}  // namespace contactcert::queries
