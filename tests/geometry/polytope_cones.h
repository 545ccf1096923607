// Cones over the n-cube and the n-cross-polytope (x_0 = 1 slices), in R^(n+1), in both forms: the
// highly degenerate families of the conversion tests and benchmarks.
#pragma once

#include "geometry/face_cone.h"
#include "geometry/span_cone.h"

namespace contactcert::geometry::testing {

/// Rows (x0, +-e_i): the generators of the cone over the cross-polytope (2n rows), or with x0 = -1 the
/// facets of the cone over the cube (|x_i| <= x_0).
inline Mat<Q> signed_unit_rows(Eigen::Index n, long x0) {
  Mat<Q> M = Mat<Q>::Zero(2 * n, n + 1);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index s = 0; s < 2; ++s) {
      M(2 * i + s, 0) = x0;
      M(2 * i + s, i + 1) = s == 0 ? 1 : -1;
    }
  return M;
}

/// Rows (x0, +-1, ..., +-1): the 2^n vertices of the cube (x0 = 1), or the facets of the cone over the
/// cross-polytope (x0 = -1: sum |x_i| <= x_0).
inline Mat<Q> sign_vector_rows(Eigen::Index n, long x0) {
  const Eigen::Index m = Eigen::Index{1} << n;
  Mat<Q> M(m, n + 1);
  for (Eigen::Index r = 0; r < m; ++r) {
    M(r, 0) = x0;
    for (Eigen::Index i = 0; i < n; ++i) M(r, i + 1) = (r >> i) & 1 ? -1 : 1;
  }
  return M;
}

inline SpanCone<Q> cross_polytope_span(Eigen::Index n) {
  return SpanCone<Q>::from_rows(n + 1, signed_unit_rows(n, 1), Mat<Q>(0, n + 1));
}
inline FaceCone<Q> cube_face(Eigen::Index n) {
  return FaceCone<Q>::from_rows(n + 1, signed_unit_rows(n, -1), Mat<Q>(0, n + 1), Mat<Q>(0, n + 1));
}
inline SpanCone<Q> cube_span(Eigen::Index n) {
  return SpanCone<Q>::from_rows(n + 1, sign_vector_rows(n, 1), Mat<Q>(0, n + 1));
}
inline FaceCone<Q> cross_polytope_face(Eigen::Index n) {
  return FaceCone<Q>::from_rows(n + 1, sign_vector_rows(n, -1), Mat<Q>(0, n + 1), Mat<Q>(0, n + 1));
}

}  // namespace contactcert::geometry::testing
