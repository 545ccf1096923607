#include "solvers/stability/world_forces.h"

#include "exact/rational_text.h"
#include "geometry/snap.h"
#include "solvers/wrench_cone/contact_model.h"

namespace contactcert::solvers {

geometry::Point2 reported_normal(const geometry::Fixel& f) {
  const geometry::Point2& n = f.frame.normal;
  if (!f.position) return n;  // an explicit contact: its normal as the file writes it
  bool rational = false;
  const Q length = geometry::rational_length(norm2(n), &rational);
  if (rational) return {n.x / length, n.y / length};
  const std::vector<exact::Z> d = exact::primitive(std::vector<Q>{n.x, n.y});
  return {Q(d[0]), Q(d[1])};
}

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
    // f_i and its torque from the model's frame; then f_i = c_n n + c_t t in the reported frame (n, t = perp(n)),
    // so c_n = f_i . n / |n|^2 and c_t = f_i . t / |n|^2.
    w.force = c(i) * J.col(i).head(2) + c(k + i) * J.col(k + i).head(2);
    w.torque = c(i) * J(2, i) + c(k + i) * J(2, k + i);
    const geometry::Point2 n = reported_normal(kept.fixels[static_cast<std::size_t>(i)]);
    w.normal = Vec<T>(2);
    w.normal << from_exact<T>(n.x), from_exact<T>(n.y);
    w.tangent = Vec<T>(2);
    w.tangent << -w.normal(1), w.normal(0);
    const T n2 = from_exact<T>(norm2(n));
    w.c_n = w.force.dot(w.normal) / n2;
    w.c_t = w.force.dot(w.tangent) / n2;
    out.push_back(std::move(w));
  }
  return out;
}

template std::vector<WorldForce<double>> world_forces<double>(const geometry::PlanarScene&,
                                                              const std::vector<Eigen::Index>&, const Vec<double>&);
template std::vector<WorldForce<Q>> world_forces<Q>(const geometry::PlanarScene&, const std::vector<Eigen::Index>&,
                                                    const Vec<Q>&);

}  // namespace contactcert::solvers
