#include "checker/world_forces.h"

#include "checker/table2_rows.h"

namespace contactcert::checker {

using exact::Q;
using exact::Vec;

std::vector<solvers::WorldForce<Q>> checked_world_forces(const geometry::PlanarScene& scene,
                                                         const std::vector<Eigen::Index>& touching, const Vec<Q>& c) {
  const table2_check::CheckedScene model = table2_check::checked_scene(scene, /*touching_only=*/false);
  const auto k = static_cast<Eigen::Index>(touching.size());
  std::vector<solvers::WorldForce<Q>> out;
  for (Eigen::Index i = 0; i < k; ++i) {
    const auto fixel = static_cast<std::size_t>(touching[static_cast<std::size_t>(i)]);
    const table2_check::CheckedFixel& w = model.fixels[fixel];
    solvers::WorldForce<Q> f;
    f.fixel = touching[static_cast<std::size_t>(i)];
    f.point = Vec<Q>(2);
    f.point << scene.fixels[fixel].frame.point.x, scene.fixels[fixel].frame.point.y;
    f.force = Vec<Q>(2);
    f.force << c(i) * w.w_n[0] + c(k + i) * w.w_t[0], c(i) * w.w_n[1] + c(k + i) * w.w_t[1];
    f.torque = c(i) * w.w_n[2] + c(k + i) * w.w_t[2];
    const geometry::Point2 n = solvers::reported_normal(scene.fixels[fixel]);
    f.normal = Vec<Q>(2);
    f.normal << n.x, n.y;
    f.tangent = Vec<Q>(2);
    f.tangent << -n.y, n.x;
    const Q n2 = n.x * n.x + n.y * n.y;
    f.c_n = f.force.dot(f.normal) / n2;
    f.c_t = f.force.dot(f.tangent) / n2;
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace contactcert::checker
