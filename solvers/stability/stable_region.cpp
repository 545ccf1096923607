#include "solvers/stability/stable_region.h"

#include "geometry/canonical.h"
#include "geometry/double_description.h"
#include "geometry/nnc_cone.h"

namespace contactcert::solvers {

using Index = Eigen::Index;

template <class T>
StabilityVerdict StableRegion<T>::label(const Vec<T>& g) const {
  if (!geometry::contains_point<T>(weak, g)) return StabilityVerdict::kUnstable;
  for (const auto& c : cones)
    if (geometry::contains_point<T>(c, g)) return StabilityVerdict::kWeaklyStable;
  return StabilityVerdict::kStronglyStable;
}

template <class T>
geometry::FaceCone<T> weakly_stable_cone(const geometry::PlanarScene& scene) {
  const Mat<T> J = from_exact<T>(jacobian(scene));
  const Index k = J.cols() / 2;
  Mat<T> rays(2 * k, 3);
  for (Index i = 0; i < k; ++i) {
    const T mu = from_exact<T>(scene.fixels[static_cast<size_t>(i)].mu_s);
    // J c + g = 0 with c_i in pos(n_i + mu t_i, n_i - mu t_i): g in -pos(edges).
    rays.row(2 * i) = -(J.col(i) + mu * J.col(k + i)).transpose();
    rays.row(2 * i + 1) = -(J.col(i) - mu * J.col(k + i)).transpose();
  }
  geometry::SpanCone<T> s;
  s.dim = 3;
  s.rays = rays;
  s.lines = Mat<T>(0, 3);
  geometry::FaceCone<T> f = geometry::to_face<T>(s);
  if constexpr (std::is_same_v<T, Q>) f = geometry::canonical<T>(f);
  return f;
}

template <class T>
StableRegion<T> stable_region(const geometry::PlanarScene& full, Route route) {
  StableRegion<T> out;
  const geometry::PlanarScene scene = touching_scene(full, &out.touching);
  out.weak = weakly_stable_cone<T>(scene);
  const ContactModel<T> model = contact_model<T>(scene);
  std::vector<Mat<T>> rows{out.weak.inequalities, out.weak.equalities, out.weak.strict};
  for (const ModeString& m : moving_modes(scene.fixels.size())) {
    geometry::FaceCone<T> c = wrench_cone_face<T>(scene, model, m, route);
    if (is_empty_cone<T>(c)) continue;
    out.modes.push_back(m);
    rows.push_back(c.inequalities);
    rows.push_back(c.equalities);
    rows.push_back(c.strict);
    out.cones.push_back(std::move(c));
  }
  Index total = 0;
  for (const auto& r : rows) total += r.rows();
  Mat<T> normals(total, 3);
  Index at = 0;
  for (const auto& r : rows) {
    if (r.rows()) normals.middleRows(at, r.rows()) = r;
    at += r.rows();
  }
  const geometry::SphereArrangement<T> arr = geometry::sphere_arrangement<T>(normals);
  out.planes = arr.planes;
  for (const auto& c : arr.cells) out.cells.push_back({c.dimension, c.point, out.label(c.point)});
  return out;
}

#define CONTACTCERT_STABLE_REGION_INSTANTIATE(T)                                            \
  template struct StableRegion<T>;                                                          \
  template geometry::FaceCone<T> weakly_stable_cone<T>(const geometry::PlanarScene&);        \
  template StableRegion<T> stable_region<T>(const geometry::PlanarScene&, Route);
CONTACTCERT_STABLE_REGION_INSTANTIATE(double)
CONTACTCERT_STABLE_REGION_INSTANTIATE(Q)

}  // namespace contactcert::solvers
