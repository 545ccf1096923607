#include "solvers/stability/margin.h"

#include <type_traits>

#include "exact/linalg.h"
#include "geometry/double_description.h"

namespace contactcert::solvers {

using Index = Eigen::Index;

namespace {

// face_distance below for exact numbers in R^3, without the inverse: the Gram matrix G = B^T B is singular exactly
// when B's columns are dependent (always for more than three); one column b: |g|^2 - (b.g)^2 / |b|^2; two columns:
// |g|^2 - (B^T g) . G^-1 B^T g with the 2 x 2 adjugate; three independent columns span R^3 (distance 0), with the ray
// coefficients det(B with column i replaced by g) / det B by Cramer's rule.
Q det3(const Mat<Q>& M) {
  return Q(M(0, 0) * (M(1, 1) * M(2, 2) - M(1, 2) * M(2, 1)) - M(0, 1) * (M(1, 0) * M(2, 2) - M(1, 2) * M(2, 0)) +
           M(0, 2) * (M(1, 0) * M(2, 1) - M(1, 1) * M(2, 0)));
}

std::optional<Q> face_distance_exact(const Vec<Q>& g, const Mat<Q>& B, Index rays) {
  const Index m = B.cols();
  if (m > 3) return std::nullopt;
  if (m == 3) {
    const Q d = det3(B);
    if (sgn(d) == 0) return std::nullopt;
    for (Index i = 0; i < rays; ++i) {
      Mat<Q> Bi = B;
      Bi.col(i) = g;
      if (sgn(det3(Bi)) * sgn(d) < 0) return std::nullopt;
    }
    return Q(0);
  }
  const Q gg = g.dot(g);
  if (m == 1) {
    const Q bb = B.col(0).dot(B.col(0)), bg = B.col(0).dot(g);
    if (sgn(bb) == 0 || (rays > 0 && sgn(bg) < 0)) return std::nullopt;
    return Q(gg - bg * bg / bb);
  }
  const Q aa = B.col(0).dot(B.col(0)), ab = B.col(0).dot(B.col(1)), bb = B.col(1).dot(B.col(1));
  const Q det = aa * bb - ab * ab;
  if (sgn(det) == 0) return std::nullopt;
  const Q ag = B.col(0).dot(g), bg = B.col(1).dot(g);
  const Q ca = (bb * ag - ab * bg) / det, cb = (aa * bg - ab * ag) / det;  // G^-1 B^T g
  if ((rays > 0 && sgn(ca) < 0) || (rays > 1 && sgn(cb) < 0)) return std::nullopt;
  return Q(gg - ca * ag - cb * bg);
}

// Projection of g onto span(B) with the coefficients of the ray columns (the first `rays` columns)
// non-negative; nullopt when B is dependent or a ray coefficient is negative.
template <class T>
std::optional<T> face_distance(const Vec<T>& g, const Mat<T>& B, Index rays) {
  if constexpr (std::is_same_v<T, Q>)
    if (B.rows() == 3) return face_distance_exact(g, B, rays);
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
