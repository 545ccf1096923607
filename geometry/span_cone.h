// Span form of a polyhedral convex cone (wrench cone paper, eq. 11): pos(rays) + span(lines).
#pragma once

#include <utility>

#include "exact/number.h"
#include "geometry/number_names.h"

namespace contactcert::geometry {

using exact::Z;

/// The cone { sum_i a_i r_i + sum_j b_j l_j : a >= 0 } in R^dim. Generators are stored as ROWS
/// (SPEC section 4 lists them that way); the paper's G has them as columns, see from_columns.
template <class T>
struct SpanCone {
  Eigen::Index dim = 0;
  Mat<T> rays = Mat<T>(0, 0);   ///< k x dim, one generator per row
  Mat<T> lines = Mat<T>(0, 0);  ///< l x dim, one line direction per row (both signs are in the cone)

  /// pos(G) of eq. (11): the generators are the columns of G.
  static SpanCone from_columns(const Mat<T>& G) {
    SpanCone c;
    c.dim = G.rows();
    c.rays = G.transpose();
    c.lines = Mat<T>(0, G.rows());
    return c;
  }
  /// pos(rays) + span(lines), generators as rows.
  /// (a matrix with 0 rows may have any column count; taken by value: a temporary is moved in, not copied).
  static SpanCone from_rows(Eigen::Index dim, Mat<T> rays, Mat<T> lines) {
    SpanCone c;
    c.dim = dim;
    c.rays = rays.rows() == 0 ? Mat<T>(0, dim) : std::move(rays);
    c.lines = lines.rows() == 0 ? Mat<T>(0, dim) : std::move(lines);
    return c;
  }
};

}  // namespace contactcert::geometry
