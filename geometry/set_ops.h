// Set tools on (not necessarily closed) face cones: intersection, containment, equality.
#pragma once

#include "geometry/nnc_cone.h"

namespace contactcert::geometry {

/// a intersected with b (rows stacked; not minimal: pass through nnc_form for that).
template <class T>
FaceCone<T> intersection(const FaceCone<T>& a, const FaceCone<T>& b);

enum class ContainmentStatus { kContained, kNotContained };

/// Is inner a subset of outer? kNotContained comes with a witness: a point of inner not in outer.
template <class T>
struct Containment {
  ContainmentStatus status = ContainmentStatus::kContained;
  Vec<T> witness;
};

/// inner subset of outer, decided exactly for T = Q (strict rows included).
template <class T>
Containment<T> contains(const FaceCone<T>& outer, const FaceCone<T>& inner, const DdBudget& budget = {});

/// The same with inner's form given (inner_form = nnc_form(inner)): one conversion for many outer cones.
template <class T>
Containment<T> contains(const FaceCone<T>& outer, const FaceCone<T>& inner, const NncForm<T>& inner_form);

/// a == b as sets (canonical forms compared).
template <class T>
bool equal(const FaceCone<T>& a, const FaceCone<T>& b, const DdBudget& budget = {});

#define CONTACTCERT_SETOPS_EXTERN(T)                                                                     \
  extern template FaceCone<T> intersection<T>(const FaceCone<T>&, const FaceCone<T>&);                   \
  extern template Containment<T> contains<T>(const FaceCone<T>&, const FaceCone<T>&, const DdBudget&);   \
  extern template Containment<T> contains<T>(const FaceCone<T>&, const FaceCone<T>&, const NncForm<T>&); \
  extern template bool equal<T>(const FaceCone<T>&, const FaceCone<T>&, const DdBudget&);
CONTACTCERT_SETOPS_EXTERN(double)
CONTACTCERT_SETOPS_EXTERN(Q)
#undef CONTACTCERT_SETOPS_EXTERN

}  // namespace contactcert::geometry
