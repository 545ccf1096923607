#include "solvers/stability/world_forces.h"

#include "solvers/wrench_cone/contact_model.h"

namespace contactcert::solvers {

template <class T>
std::vector<WorldForce<T>> world_forces(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                                        const Vec<T>& c) {
  geometry::PlanarScene kept{scene.workpiece, {}};
  for (Eigen::Index i : touching) kept.fixels.push_back(scene.fixels[static_cast<std::size_t>(i)]);
  // Column i of J is the wrench of the model's n_i at p_i, column k + i that of its t_i (eq. 4).
  const Mat<T> J = from_exact<T>(jacobian(kept));
  const auto k = static_cast<Eigen::Index>(touching.size());
  std::vector<WorldForce<T>> out;
  for (Eigen::Index i = 0; i < k; ++i) {
    WorldForce<T> w;
    w.fixel = touching[static_cast<std::size_t>(i)];
    const auto& p = kept.fixels[static_cast<std::size_t>(i)].frame.point;
    w.point = Vec<T>(2);
    w.point << from_exact<T>(p.x), from_exact<T>(p.y);
    w.normal = J.col(i).head(2);
    w.tangent = J.col(k + i).head(2);
    w.c_n = c(i);
    w.c_t = c(k + i);
    w.force = w.c_n * w.normal + w.c_t * w.tangent;
    w.torque = w.c_n * J(2, i) + w.c_t * J(2, k + i);
    out.push_back(std::move(w));
  }
  return out;
}

template std::vector<WorldForce<double>> world_forces<double>(const geometry::PlanarScene&,
                                                              const std::vector<Eigen::Index>&, const Vec<double>&);
template std::vector<WorldForce<Q>> world_forces<Q>(const geometry::PlanarScene&, const std::vector<Eigen::Index>&,
                                                    const Vec<Q>&);

}  // namespace contactcert::solvers
