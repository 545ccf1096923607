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

namespace {

// An exact vector in T: itself for Q (no copy), else rounded entry by entry.
template <class T>
decltype(auto) vector_in(const Vec<Q>& v) {
  if constexpr (std::is_same_v<T, Q>) {
    return (v);
  } else {
    return Vec<T>(v.unaryExpr([](const Q& x) { return from_exact<T>(x); }));
  }
}

}  // namespace

ForceFrames::ForceFrames(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& fixels)
    : by_fixel_(scene.fixels.size()) {
  geometry::PlanarScene kept{scene.workpiece, {}};
  for (Eigen::Index i : fixels) kept.fixels.push_back(scene.fixels[static_cast<std::size_t>(i)]);
  // Column i of J is the wrench of the model's n_i at p_i, column k + i that of its t_i (eq. 4).
  const Mat<Q> J = jacobian(kept);
  const auto k = static_cast<Eigen::Index>(fixels.size());
  for (Eigen::Index i = 0; i < k; ++i) {
    const geometry::Fixel& f = kept.fixels[static_cast<std::size_t>(i)];
    Frame frame;
    frame.point = Vec<Q>(2);
    frame.point << f.frame.point.x, f.frame.point.y;
    const geometry::Point2 n = reported_normal(f);
    frame.normal = Vec<Q>(2);
    frame.normal << n.x, n.y;
    frame.normal_squared = norm2(n);
    frame.normal_wrench = J.col(i);
    frame.tangent_wrench = J.col(k + i);
    by_fixel_[static_cast<std::size_t>(fixels[static_cast<std::size_t>(i)])] = std::move(frame);
  }
}

template <class T>
std::vector<WorldForce<T>> ForceFrames::forces(const std::vector<Eigen::Index>& touching, const Vec<T>& c) const {
  const auto k = static_cast<Eigen::Index>(touching.size());
  std::vector<WorldForce<T>> out;
  for (Eigen::Index i = 0; i < k; ++i) {
    WorldForce<T> w;
    w.fixel = touching[static_cast<std::size_t>(i)];
    const Frame& f = *by_fixel_.at(static_cast<std::size_t>(w.fixel));
    w.point = vector_in<T>(f.point);
    // f_i and its torque from the model's frame; then f_i = c_n n + c_t t in the reported frame (n, t = perp(n)),
    // so c_n = f_i . n / |n|^2 and c_t = f_i . t / |n|^2.
    const auto& jn = vector_in<T>(f.normal_wrench);
    const auto& jt = vector_in<T>(f.tangent_wrench);
    w.force = c(i) * jn.head(2) + c(k + i) * jt.head(2);
    w.torque = c(i) * jn(2) + c(k + i) * jt(2);
    w.normal = vector_in<T>(f.normal);
    w.tangent = Vec<T>(2);
    w.tangent << -w.normal(1), w.normal(0);
    const T n2 = from_exact<T>(f.normal_squared);
    w.c_n = w.force.dot(w.normal) / n2;
    w.c_t = w.force.dot(w.tangent) / n2;
    out.push_back(std::move(w));
  }
  return out;
}

template <class T>
std::vector<WorldForce<T>> world_forces(const geometry::PlanarScene& scene, const std::vector<Eigen::Index>& touching,
                                        const Vec<T>& c) {
  return ForceFrames(scene, touching).forces<T>(touching, c);
}

template std::vector<WorldForce<double>> ForceFrames::forces<double>(const std::vector<Eigen::Index>&,
                                                                     const Vec<double>&) const;
template std::vector<WorldForce<Q>> ForceFrames::forces<Q>(const std::vector<Eigen::Index>&, const Vec<Q>&) const;
template std::vector<WorldForce<double>> world_forces<double>(const geometry::PlanarScene&,
                                                              const std::vector<Eigen::Index>&, const Vec<double>&);
template std::vector<WorldForce<Q>> world_forces<Q>(const geometry::PlanarScene&, const std::vector<Eigen::Index>&,
                                                    const Vec<Q>&);

}  // namespace contactcert::solvers
