// Conversion between span and face forms by the double description method (exact/double_description.h,
// whose engine and budget these names are). One algorithm for both directions: the facets of C are the
// extreme rays of its polar {f : f . g <= 0 for all g in C}.
// Exact path (T = Q): the iteration runs on primitive integer rows (fraction-free), in checked 64-bit
// integers and again in GMP integers if a number outgrows them (exact/fraction_free.h); float path
// (T = double): the same code on doubles with the tolerance sign test of NumberTraits<double>.
#pragma once

#include "exact/double_description.h"
#include "geometry/face_cone.h"
#include "geometry/span_cone.h"

namespace contactcert::geometry {

using exact::cone_generators;
using exact::DdBudget;
using exact::pointed_cone_rays;
using exact::RingGenerators;
using exact::RowOrder;

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

extern template FaceCone<double> to_face<double>(const SpanCone<double>&, const DdBudget&);
extern template FaceCone<Q> to_face<Q>(const SpanCone<Q>&, const DdBudget&);
extern template SpanCone<double> to_span<double>(const FaceCone<double>&, const DdBudget&);
extern template SpanCone<Q> to_span<Q>(const FaceCone<Q>&, const DdBudget&);
extern template ConePair<double> both_forms<double>(const SpanCone<double>&, const DdBudget&);
extern template ConePair<Q> both_forms<Q>(const SpanCone<Q>&, const DdBudget&);
extern template ConePair<double> both_forms<double>(const FaceCone<double>&, const DdBudget&);
extern template ConePair<Q> both_forms<Q>(const FaceCone<Q>&, const DdBudget&);

}  // namespace contactcert::geometry
