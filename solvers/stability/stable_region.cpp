#include "solvers/stability/stable_region.h"

#include "exact/input_error.h"
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

namespace {

// The rows of one face cone inside the arrangement's normals: F, E, S from `at` on.
struct RowBlock {
  Index at, inequalities, equalities, strict;
};

// Whether every point of a cell lies in the cone of `rows`, read off the cell's sign vector: the sign of
// row r . g on the cell is row_orientation[r] * signs[row_plane[r]] (0 for a zero row).
template <class T>
bool cell_in_cone(const geometry::SphereArrangement<T>& arr, const std::vector<int>& signs, const RowBlock& rows) {
  auto sign_of_row = [&](Index r) {
    const Index j = arr.row_plane[static_cast<std::size_t>(r)];
    return j < 0 ? 0 : arr.row_orientation[static_cast<std::size_t>(r)] * signs[static_cast<std::size_t>(j)];
  };
  Index r = rows.at;
  for (Index i = 0; i < rows.inequalities; ++i)
    if (sign_of_row(r++) > 0) return false;
  for (Index i = 0; i < rows.equalities; ++i)
    if (sign_of_row(r++) != 0) return false;
  for (Index i = 0; i < rows.strict; ++i)
    if (sign_of_row(r++) >= 0) return false;
  return true;
}

}  // namespace

template <class T>
StableRegion<T> mode_cones(const geometry::PlanarScene& full, const ModeTree<T>& tree, Route route,
                           const exact::Deadline& deadline) {
  StableRegion<T> out;
  const geometry::PlanarScene scene = touching_scene(full, &out.touching);
  out.weak = weakly_stable_cone<T>(scene);
  const ContactModel<T> model = contact_model<T>(scene);
  const std::size_t k = scene.fixels.size();
  out.tree_nodes = tree.nodes;
  geometry::DdBudget cone_budget;
  cone_budget.deadline = deadline;
  std::size_t done = 0;
  for (const ModeString& m : tree.modes) {
    if (deadline.expired())
      throw exact::BudgetExceeded("wrench cones of the moving modes: " + deadline.reached_text(),
                                  std::to_string(done) + " of " + std::to_string(tree.modes.size()) +
                                      " kinematically feasible modes' cones computed");
    ++done;
    if (m.text() == std::string(k, 'n')) continue;  // n..n is not a moving mode (strong_stability.h)
    geometry::FaceCone<T> c = wrench_cone_face<T>(scene, model, m, route, cone_budget);
    if (is_empty_cone<T>(c)) continue;
    out.modes.push_back(m);
    out.cones.push_back(std::move(c));
  }
  return out;
}

template <class T>
StableRegion<T> mode_cones(const geometry::PlanarScene& full, Route route, const ModeTreeOptions& tree_options) {
  const geometry::PlanarScene scene = touching_scene(full, nullptr);
  const ModeTree<T> tree = walk_modes(motion_model<T>(scene), moving_alphabet(scene.fixels.size()), tree_options);
  return mode_cones<T>(full, tree, route, tree_options.deadline);
}

template <class T>
StableRegion<T> stable_region(const geometry::PlanarScene& full, Route route, const ModeTreeOptions& tree_options) {
  StableRegion<T> out = mode_cones<T>(full, route, tree_options);
  std::vector<Mat<T>> rows;
  std::vector<RowBlock> blocks;  // the weak cone, then each moving mode's cone
  Index total = 0;
  auto add_rows = [&](const geometry::FaceCone<T>& c) {
    blocks.push_back({total, c.inequalities.rows(), c.equalities.rows(), c.strict.rows()});
    for (const Mat<T>* m : {&c.inequalities, &c.equalities, &c.strict}) {
      rows.push_back(*m);
      total += m->rows();
    }
  };
  add_rows(out.weak);
  for (const auto& c : out.cones) add_rows(c);
  Mat<T> normals(total, 3);
  Index at = 0;
  for (const auto& r : rows) {
    if (r.rows()) normals.middleRows(at, r.rows()) = r;
    at += r.rows();
  }
  const geometry::SphereArrangement<T> arr =
      geometry::sphere_arrangement<T>(normals, geometry::ArrangementBudget{tree_options.deadline});
  out.planes = arr.planes;
  // Each cell's label as label() gives it, from its sign vector (no dot products).
  for (const auto& c : arr.cells) {
    StabilityVerdict v = StabilityVerdict::kUnstable;
    if (cell_in_cone(arr, c.signs, blocks.front())) {
      v = StabilityVerdict::kStronglyStable;
      for (std::size_t i = 1; i < blocks.size() && v == StabilityVerdict::kStronglyStable; ++i)
        if (cell_in_cone(arr, c.signs, blocks[i])) v = StabilityVerdict::kWeaklyStable;
    }
    out.cells.push_back({c.dimension, c.point, v});
  }
  return out;
}

#define CONTACTCERT_STABLE_REGION_INSTANTIATE(T)                                                       \
  template struct StableRegion<T>;                                                                     \
  template geometry::FaceCone<T> weakly_stable_cone<T>(const geometry::PlanarScene&);                  \
  template StableRegion<T> mode_cones<T>(const geometry::PlanarScene&, Route, const ModeTreeOptions&); \
  template StableRegion<T> mode_cones<T>(const geometry::PlanarScene&, const ModeTree<T>&, Route,      \
                                         const exact::Deadline&);                                      \
  template StableRegion<T> stable_region<T>(const geometry::PlanarScene&, Route, const ModeTreeOptions&);
CONTACTCERT_STABLE_REGION_INSTANTIATE(double)
CONTACTCERT_STABLE_REGION_INSTANTIATE(Q)

}  // namespace contactcert::solvers
