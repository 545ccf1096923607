// Not-necessarily-closed cones { F g <= 0, E g = 0, S g < 0 }, decided exactly (no numeric epsilon).
// Method: let K' = { F g <= 0, S g <= 0, E g = 0 } (closed) with extreme rays R. Every strict row s is
// <= 0 on K', so Z_s = { g in K' : s . g = 0 } is a face of K'. The relative interior of a face G of K'
// lies in the cone iff no strict row vanishes on all rays of G; hence the cone is empty iff some Z_s is
// all of K', its closure is K' otherwise, and the faces missing from it ("open faces") are exactly the
// faces inside some Z_s. This is the combinatorial form of the limit k -> 0+ of section 5.6 / Theorem 1.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/double_description.h"

namespace contactcert::geometry {

enum class NncStatus { kEmpty, kNonEmpty };

/// A cone with strict rows, resolved: its closure in both forms and which faces are open.
template <class T>
struct NncForm {
  NncStatus status = NncStatus::kEmpty;
  /// Minimal face form of the cone itself: closure facets that belong to the cone as inequalities,
  /// one strict row per maximal missing face (the facet normal, or the sum of the normals of the
  /// facets through that face), equalities. Empty cone: equalities = identity, strict = one zero row.
  FaceCone<T> face;
  FaceCone<T> closure_face;  ///< minimal face form of the closure (no strict rows)
  SpanCone<T> closure;       ///< minimal span form of the closure
  /// Maximal faces of the closure that are not in the cone, each as indices into closure.rays (with
  /// closure.lines, those rays span the face; an empty list is the lineality space / the origin).
  std::vector<std::vector<Eigen::Index>> open_faces;
  /// open_facets[i]: closure_face.inequalities row i is a strict facet (its face is missing).
  std::vector<bool> open_facets;
  Eigen::Index dimension() const;  ///< dimension of the cone (= of its closure); -1 if empty
};

/// Resolves a face cone with strict rows exactly. For T = Q the result is canonical.
template <class T>
NncForm<T> nnc_form(const FaceCone<T>& cone, const DdBudget& budget = {});

/// The same for a span cone pos(rays) + span(lines) (closed, never empty), from one conversion.
template <class T>
NncForm<T> nnc_form(const SpanCone<T>& cone, const DdBudget& budget = {});

/// nnc_form(...).face of { F g <= 0, S g < 0 } for rows F, S (d columns each) in an exact ring R of
/// exact/fraction_free.h, computed in R and turned into T = Q once, when the closure is pointed and
/// full-dimensional or the cone is empty (the common case of a wrench cone); nullopt otherwise, and
/// then nnc_form decides. std::int64_t throws RingOverflow.
template <class T, class R>
std::optional<FaceCone<T>> pointed_nnc_face(const exact::IntMatrix<R>& F, const exact::IntMatrix<R>& S,
                                            const DdBudget& budget = {});

extern template std::optional<FaceCone<Q>> pointed_nnc_face<Q, std::int64_t>(const exact::IntMatrix<std::int64_t>&,
                                                                             const exact::IntMatrix<std::int64_t>&,
                                                                             const DdBudget&);
extern template std::optional<FaceCone<Q>> pointed_nnc_face<Q, Z>(const exact::IntMatrix<Z>&,
                                                                  const exact::IntMatrix<Z>&, const DdBudget&);

/// a is a subset of b (sets as a bit per element, of one size).
bool is_subset(const std::vector<bool>& a, const std::vector<bool>& b);

/// The maximal faces missing from a cone, given faces of its closure that are missing (each as its set of
/// closure rays, a bit per ray), and the facets through each: the facet itself when the face is a facet
/// (marked in open_facets); the strict row of a missing face is the sum of the normals of its facets.
struct MissingFaces {
  std::vector<std::vector<bool>> maximal;
  std::vector<std::vector<Eigen::Index>> facets;  ///< per maximal face: the facets whose normals sum to its strict row
  std::vector<bool> open_facets;                  ///< per facet: its whole face is missing
};
MissingFaces missing_faces(std::vector<std::vector<bool>> faces, const std::vector<std::vector<bool>>& facet_rays);

/// sign(M.row(r) . g), exactly for T = Q.
template <class T>
int dot_sign(const Mat<T>& M, Eigen::Index r, const Vec<T>& g);

/// Is g in the cone? (F g <= 0, E g = 0, S g < 0, checked row by row.)
template <class T>
bool contains_point(const FaceCone<T>& cone, const Vec<T>& g);

enum class PointLocation { kInterior, kBoundary, kOutside };

/// Where g lies relative to a cone (use a minimal form, e.g. nnc_form(...).face, for the face to be
/// named correctly).
template <class T>
struct PointPosition {
  PointLocation location = PointLocation::kOutside;
  /// kBoundary: the inequality rows tight at g; their common zero set is the face whose relative
  /// interior holds g. kInterior: empty (g in the relative interior).
  std::vector<Eigen::Index> tight;
  /// kOutside: the first violated row and its kind.
  enum class RowKind { kNone, kInequality, kEquality, kStrict } violated_kind = RowKind::kNone;
  Eigen::Index violated_row = -1;
};

/// Interior (relative interior), relative boundary (with the tight facets) or outside.
template <class T>
PointPosition<T> locate(const FaceCone<T>& cone, const Vec<T>& g);

#define CONTACTCERT_NNC_EXTERN(T)                                              \
  extern template struct NncForm<T>;                                           \
  extern template NncForm<T> nnc_form<T>(const FaceCone<T>&, const DdBudget&); \
  extern template NncForm<T> nnc_form<T>(const SpanCone<T>&, const DdBudget&); \
  extern template bool contains_point<T>(const FaceCone<T>&, const Vec<T>&);   \
  extern template int dot_sign<T>(const Mat<T>&, Eigen::Index, const Vec<T>&); \
  extern template PointPosition<T> locate<T>(const FaceCone<T>&, const Vec<T>&);
CONTACTCERT_NNC_EXTERN(double)
CONTACTCERT_NNC_EXTERN(Q)
#undef CONTACTCERT_NNC_EXTERN

}  // namespace contactcert::geometry
