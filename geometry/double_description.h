// Conversion between span and face forms by the double description method (Motzkin et al.; the
// Fukuda-Prodon variant with the combinatorial adjacency test). One algorithm for both directions:
// the facets of C are the extreme rays of its polar {f : f . g <= 0 for all g in C}. The iteration
// starts from the whole space (lines only) and removes a line per independent row, so equalities,
// lineality and a lower dimension are found exactly on the way, in the original coordinates.
// Exact path (T = Q): the iteration runs on primitive integer rows (fraction-free), in checked 64-bit
// integers and again in GMP integers if a number outgrows them (exact/fraction_free.h); float path
// (T = double): the same code on doubles with the tolerance sign test of NumberTraits<double>.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "exact/deadline.h"
#include "geometry/face_cone.h"
#include "geometry/span_cone.h"

namespace contactcert::geometry {

/// Work limits of one conversion, checked inside the iteration where rays and work grow; exceeding
/// one throws exact::BudgetExceeded (exit 3), saying how many rows were processed.
struct DdBudget {
  /// The largest number of intermediate rays.
  std::size_t max_rays = 2'000'000;
  /// The largest adjacency work: candidate (plus, minus) pairs tested plus rays scanned by the
  /// combinatorial test, summed over the run (some 10^8 per second: 2^33 is about half a minute).
  std::uint64_t max_work = std::uint64_t{1} << 33;
  /// Wall clock (--time-limit).
  exact::Deadline deadline;
};

/// F^F of the paper's notation: a minimal face form of pos(rays) + span(lines). Each inequality row is
/// a facet normal (f . g <= 0 on the cone, eq. 10); equalities span the orthogonal complement of the
/// cone's linear hull. No strict rows. Not canonical: apply canonical() for that (exact path).
template <class T>
FaceCone<T> to_face(const SpanCone<T>& cone, const DdBudget& budget = {});

/// A minimal span form of { F g <= 0, E g = 0 }: extreme rays (modulo the lineality space) and a
/// basis of the lineality space. Strict rows are read as non-strict, so the result is the closure
/// of the cone when the cone is not empty (see nnc_cone.h for strict cones).
template <class T>
SpanCone<T> to_span(const FaceCone<T>& cone, const DdBudget& budget = {});

/// Both minimal forms of a closed cone from one conversion: for a span cone its face form by the
/// double description and its minimal generators picked from the given ones by their zero sets on the
/// facets; for a face cone (strict rows read as non-strict) its span form and its facets and implicit
/// equalities picked from the given rows. Not canonical.
template <class T>
struct ConePair {
  FaceCone<T> face;
  SpanCone<T> span;
};
template <class T>
ConePair<T> both_forms(const SpanCone<T>& cone, const DdBudget& budget = {});
template <class T>
ConePair<T> both_forms(const FaceCone<T>& cone, const DdBudget& budget = {});

/// Extreme rays (one per ray modulo the lineality space) and a basis of the lineality space of a cone,
/// as rows in a ring R of exact/fraction_free.h (std::int64_t, Z or a float type): primitive integers
/// (unit max-norm in double).
template <class R>
struct RingGenerators {
  std::vector<std::vector<R>> rays;
  std::vector<std::vector<R>> lines;
};

/// The generators of { y in R^k : a . y <= 0 for every row a of A, e . y = 0 for every row e of E } for
/// rows in R, by one double description run in R (no change of coordinates, no rationals): the engine
/// of to_face, to_span and both_forms. std::int64_t throws RingOverflow.
template <class R>
RingGenerators<R> cone_generators(std::vector<std::vector<R>> A, std::vector<std::vector<R>> E, Eigen::Index k,
                                  const DdBudget& budget = {});

/// The extreme rays of { y in R^k : a . y <= 0 for every row a } (cone_generators without equalities);
/// nullopt when the rows have rank < k (the cone is not pointed).
template <class R>
std::optional<std::vector<std::vector<R>>> pointed_cone_rays(std::vector<std::vector<R>> rows, Eigen::Index k,
                                                             const DdBudget& budget = {});

#define CONTACTCERT_DD_RING_EXTERN(R)                                                                            \
  extern template RingGenerators<R> cone_generators<R>(std::vector<std::vector<R>>, std::vector<std::vector<R>>, \
                                                       Eigen::Index, const DdBudget&);                           \
  extern template std::optional<std::vector<std::vector<R>>> pointed_cone_rays<R>(std::vector<std::vector<R>>,   \
                                                                                  Eigen::Index, const DdBudget&);
CONTACTCERT_DD_RING_EXTERN(double)
CONTACTCERT_DD_RING_EXTERN(std::int64_t)
CONTACTCERT_DD_RING_EXTERN(Z)
#undef CONTACTCERT_DD_RING_EXTERN

extern template FaceCone<double> to_face<double>(const SpanCone<double>&, const DdBudget&);
extern template FaceCone<Q> to_face<Q>(const SpanCone<Q>&, const DdBudget&);
extern template SpanCone<double> to_span<double>(const FaceCone<double>&, const DdBudget&);
extern template SpanCone<Q> to_span<Q>(const FaceCone<Q>&, const DdBudget&);
extern template ConePair<double> both_forms<double>(const SpanCone<double>&, const DdBudget&);
extern template ConePair<Q> both_forms<Q>(const SpanCone<Q>&, const DdBudget&);
extern template ConePair<double> both_forms<double>(const FaceCone<double>&, const DdBudget&);
extern template ConePair<Q> both_forms<Q>(const FaceCone<Q>&, const DdBudget&);

}  // namespace contactcert::geometry
