#include "solvers/stability/margin.h"

#include "exact/linalg.h"
#include "geometry/double_description.h"

namespace contactcert::solvers {

using Index = Eigen::Index;

namespace {

// Projection of g onto span(B) with the coefficients of the ray columns (the first `rays` columns)
// non-negative; nullopt when B is dependent or a ray coefficient is negative.
template <class T>
std::optional<T> face_distance(const Vec<T>& g, const Mat<T>& B, Index rays) {
  const Mat<T> BtB = B.transpose() * B;
  const auto inv = exact::inverse<T>(BtB);
  if (!inv) return std::nullopt;
  const Vec<T> coef = *inv * (B.transpose() * g);
  for (Index i = 0; i < rays; ++i)
    if (exact::is_negative(coef(i))) return std::nullopt;
  const Vec<T> r = g - B * coef;
  return T(r.dot(r));
}

}  // namespace

template <class T>
T squared_distance(const Vec<T>& g, const geometry::SpanCone<T>& cone) {
  const Index R = cone.rays.rows(), L = cone.lines.rows();
  T best = T(g.dot(g));  // the apex (or the lineality space, refined below)
  auto consider = [&](const std::vector<Index>& S) {
    Mat<T> B(3, static_cast<Index>(S.size()) + L);
    for (std::size_t i = 0; i < S.size(); ++i) B.col(static_cast<Index>(i)) = cone.rays.row(S[i]).transpose();
    for (Index l = 0; l < L; ++l) B.col(static_cast<Index>(S.size()) + l) = cone.lines.row(l).transpose();
    if (B.cols() == 0) return;
    if (const auto d = face_distance<T>(g, B, static_cast<Index>(S.size())); d && *d < best) best = *d;
  };
  consider({});
  for (Index a = 0; a < R; ++a) {
    consider({a});
    for (Index b = a + 1; b < R; ++b) {
      consider({a, b});
      for (Index c = b + 1; c < R; ++c) consider({a, b, c});
    }
  }
  return best;
}

template <class T>
Margin<T> stability_margin(const StableRegion<T>& region, const Vec<T>& g) {
  Margin<T> m;
  if (region.label(g) != StabilityVerdict::kStronglyStable) return m;
  // Inside the weak cone: distance to its boundary is the least (f . g)^2 / |f|^2 over its facets.
  bool first = true;
  if (region.weak.equalities.rows() > 0) return m;  // a flat weak cone has no interior
  for (Index r = 0; r < region.weak.inequalities.rows(); ++r) {
    const Vec<T> f = region.weak.inequalities.row(r).transpose();
    const T d = T(f.dot(g) * f.dot(g) / f.dot(f));
    if (first || d < m.squared_radius) {
      m.squared_radius = d;
      m.nearest = "weak";
      first = false;
    }
  }
  for (std::size_t i = 0; i < region.cones.size(); ++i) {
    const T d = squared_distance<T>(g, geometry::to_span<T>(region.cones[i]));
    if (first || d < m.squared_radius) {
      m.squared_radius = d;
      m.nearest = region.modes[i].text();
      first = false;
    }
  }
  return m;
}

template Q squared_distance<Q>(const Vec<Q>&, const geometry::SpanCone<Q>&);
template double squared_distance<double>(const Vec<double>&, const geometry::SpanCone<double>&);
template Margin<Q> stability_margin<Q>(const StableRegion<Q>&, const Vec<Q>&);
template Margin<double> stability_margin<double>(const StableRegion<double>&, const Vec<double>&);

}  // namespace contactcert::solvers
