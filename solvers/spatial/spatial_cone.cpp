#include "solvers/spatial/spatial_cone.h"

#include "solvers/spatial/spatial_stability.h"

namespace contactcert::solvers::spatial {

using Index = Eigen::Index;

geometry::ProjectionProblem<Q> spatial_cone_problem(const geometry::SpatialScene& scene, const std::string& mode) {
  const exact::SparseStrictSystem<Q> sys = spatial_motion_system(scene.body, spatial_model(scene), mode);
  // Columns 0..5 (vdot, free) become v+ (0..5) and v- (6..11); the others follow in order.
  const Index n = sys.cols + 6;
  geometry::ProjectionProblem<Q> p{exact::Mat<Q>::Zero(sys.rows, n), exact::Mat<Q>::Zero(sys.rows, 6),
                                   std::vector<bool>(static_cast<std::size_t>(n), false)};
  for (const auto& e : sys.entries) {
    const Index c = e.col < 6 ? e.col : e.col + 6;
    p.K(e.row, c) += e.value;
    if (e.col < 6) p.K(e.row, e.col + 6) -= e.value;
  }
  for (Index c = 6; c < sys.cols; ++c)
    p.strict[static_cast<std::size_t>(c + 6)] = sys.strict[static_cast<std::size_t>(c)];
  for (Index d = 0; d < 6; ++d) p.P(sys.rows - 6 + d, d) = 1;
  return p;
}

geometry::NncForm<Q> spatial_wrench_cone(const geometry::SpatialScene& scene, const std::string& mode,
                                         const exact::DdBudget& budget) {
  return geometry::nnc_form(geometry::project_by_polar(spatial_cone_problem(scene, mode), budget), budget);
}

}  // namespace contactcert::solvers::spatial
