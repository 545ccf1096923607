// Seeded random and degenerate cones for the geometry tests.
#pragma once

#include <random>

#include "geometry/face_cone.h"
#include "geometry/span_cone.h"

namespace contactcert::geometry::testing {

/// A random span cone in R^dim: `rays` generators with entries in [-range, range], `lines` lines;
/// with `on_facet` > 0, that many generators lie on the hyperplane h . g = 0 and the rest on h . g < 0.
inline SpanCone<Q> random_span(std::mt19937_64& rng, Eigen::Index dim, Eigen::Index rays, Eigen::Index lines,
                               Eigen::Index on_facet = 0, long range = 5) {
  std::uniform_int_distribution<long> u(-range, range);
  Vec<Q> h(dim);
  for (Eigen::Index j = 0; j < dim; ++j) h(j) = Q(u(rng));
  if (h.isZero()) h(0) = 1;
  SpanCone<Q> c;
  c.dim = dim;
  c.rays = Mat<Q>(rays, dim);
  c.lines = Mat<Q>(lines, dim);
  for (Eigen::Index i = 0; i < rays; ++i) {
    for (;;) {
      for (Eigen::Index j = 0; j < dim; ++j) c.rays(i, j) = Q(u(rng));
      const Q s = c.rays.row(i).dot(h.transpose());
      if (on_facet == 0) break;
      if (i < on_facet) {
        // Project onto h . g = 0 (rational), keep integers by scaling.
        Vec<Q> r = c.rays.row(i).transpose();
        r = r * h.squaredNorm() - h * s;
        c.rays.row(i) = r.transpose();
        break;
      }
      if (s < 0) break;
    }
  }
  for (Eigen::Index i = 0; i < lines; ++i)
    for (Eigen::Index j = 0; j < dim; ++j) c.lines(i, j) = Q(u(rng));
  return c;
}

/// A random face cone: `rows` inequalities, `eqs` equalities, `strict` strict rows.
inline FaceCone<Q> random_face(std::mt19937_64& rng, Eigen::Index dim, Eigen::Index rows, Eigen::Index eqs,
                               Eigen::Index strict, long range = 5) {
  std::uniform_int_distribution<long> u(-range, range);
  FaceCone<Q> c;
  c.dim = dim;
  c.inequalities = Mat<Q>(rows, dim);
  c.equalities = Mat<Q>(eqs, dim);
  c.strict = Mat<Q>(strict, dim);
  for (Mat<Q>* M : {&c.inequalities, &c.equalities, &c.strict})
    for (Eigen::Index i = 0; i < M->rows(); ++i)
      for (Eigen::Index j = 0; j < dim; ++j) (*M)(i, j) = Q(u(rng));
  return c;
}

}  // namespace contactcert::geometry::testing
