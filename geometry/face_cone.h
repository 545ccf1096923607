// Face normal form of a (not necessarily closed) polyhedral cone (wrench cone paper, eq. 10, with the
// paper's sign convention F g <= 0), plus equalities and strict rows.
#pragma once

#include <utility>

#include "exact/number.h"
#include "geometry/number_names.h"

namespace contactcert::geometry {

/// The cone { g in R^dim : F g <= 0, E g = 0, S g < 0 }. Closed when there are no strict rows.
template <class T>
struct FaceCone {
  Eigen::Index dim = 0;
  Mat<T> inequalities = Mat<T>(0, 0);  ///< F: rows f with f . g <= 0 (eq. 10)
  Mat<T> equalities = Mat<T>(0, 0);    ///< E: rows e with e . g = 0
  Mat<T> strict = Mat<T>(0, 0);        ///< S: rows s with s . g < 0

  bool is_closed() const { return strict.rows() == 0; }

  /// polar(F) of eq. (10).
  static FaceCone polar(const Mat<T>& F) { return from_rows(F.cols(), F, Mat<T>(0, 0), Mat<T>(0, 0)); }
  /// { g in R^dim : F g <= 0, E g = 0, S g < 0 }; a matrix with 0 rows may have any column count.
  /// (Taken by value: a temporary matrix is moved in, not copied.)
  static FaceCone from_rows(Eigen::Index dim, Mat<T> F, Mat<T> E, Mat<T> S) {
    FaceCone c;
    c.dim = dim;
    c.inequalities = F.rows() == 0 ? Mat<T>(0, dim) : std::move(F);
    c.equalities = E.rows() == 0 ? Mat<T>(0, dim) : std::move(E);
    c.strict = S.rows() == 0 ? Mat<T>(0, dim) : std::move(S);
    return c;
  }
};

}  // namespace contactcert::geometry
