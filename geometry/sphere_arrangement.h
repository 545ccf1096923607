// The arrangement of planes through the origin of R^3 (great circles on the sphere of directions): its
// relatively open cells, each with a representative point and its sign vector. In a central arrangement
// every sign vector class is convex, so cells are identified by their sign vectors.
#pragma once

#include <cstddef>
#include <vector>

#include "exact/deadline.h"
#include "exact/number.h"
#include "geometry/number_names.h"

namespace contactcert::geometry {

/// One relatively open cell: dimension 0 (the origin), 1 (a ray: a vertex on the sphere), 2 (a sector
/// of a plane: an arc) or 3 (an open region).
template <class T>
struct ArrangementCell {
  int dimension = 3;
  Vec<T> point;            ///< a representative point of the cell
  std::vector<int> signs;  ///< sign of n_j . point for each (deduplicated) plane j
};

template <class T>
struct SphereArrangement {
  Mat<T> planes;  ///< deduplicated plane normals, one per row
  std::vector<ArrangementCell<T>> cells;
  /// Per input row r: its plane j = row_plane[r] (-1 for a zero row) and row_orientation[r] = +-1 with
  /// row r = c planes.row(j), sign(c) = row_orientation[r]; so sign(row_r . g) = row_orientation[r] signs[j].
  std::vector<Eigen::Index> row_plane;
  std::vector<int> row_orientation;
};

/// A budget on the arrangement of p planes: it has O(p^2) cells, each with p signs, found in O(p^3) time.
struct ArrangementBudget {
  exact::Deadline deadline{};                    ///< tested per vertex pair and per vertex
  std::size_t max_signs = std::size_t{1} << 26;  ///< cells x planes kept at most (the sign vectors' size)
};

/// Whether the cells carry their representative points (kSigns: sign vectors only, point left empty).
enum class CellPoints { kPoints, kSigns };

/// All cells of the arrangement of the planes {g : n . g = 0} for the rows n of `normals` (zero rows are
/// ignored, parallel rows merged). Representatives are exact for T = Q (computed in integer arithmetic:
/// normals scaled to primitive integer vectors, representatives integer vectors). Throws exact::BudgetExceeded
/// (with the vertices and cells covered) past the budget's deadline or sign count. The cells and their order do
/// not depend on `points`.
template <class T>
SphereArrangement<T> sphere_arrangement(const Mat<T>& normals, const ArrangementBudget& budget = {},
                                        CellPoints points = CellPoints::kPoints);

extern template SphereArrangement<double> sphere_arrangement<double>(const Mat<double>&, const ArrangementBudget&,
                                                                     CellPoints);
extern template SphereArrangement<Q> sphere_arrangement<Q>(const Mat<Q>&, const ArrangementBudget&, CellPoints);

}  // namespace contactcert::geometry
