// Canonical forms (SPEC section 4): equal cones print identically.
// Equalities / lines: the reduced row echelon basis of their span, each row scaled to a primitive
// integer vector (leading entry positive). Inequalities / strict rows / rays: reduced modulo that
// basis (zero in its pivot columns), scaled to primitive integers, duplicates removed, sorted
// lexicographically. The float path scales rows to max |entry| = 1 instead of primitive integers.
#pragma once

#include "geometry/face_cone.h"
#include "geometry/span_cone.h"

namespace contactcert::geometry {

/// Canonical form of a MINIMAL span cone (e.g. the output of to_span): normalises, does not remove
/// redundant generators.
template <class T>
SpanCone<T> canonical(const SpanCone<T>& cone);

/// Canonical form of a MINIMAL face cone (e.g. the output of to_face or nnc_form(...).face).
template <class T>
FaceCone<T> canonical(const FaceCone<T>& cone);

/// Same set, same rows? (compares two canonical forms entry by entry).
template <class T>
bool identical(const FaceCone<T>& a, const FaceCone<T>& b);
template <class T>
bool identical(const SpanCone<T>& a, const SpanCone<T>& b);

#define CONTACTCERT_CANONICAL_EXTERN(T)                                      \
  extern template SpanCone<T> canonical<T>(const SpanCone<T>&);              \
  extern template FaceCone<T> canonical<T>(const FaceCone<T>&);              \
  extern template bool identical<T>(const FaceCone<T>&, const FaceCone<T>&); \
  extern template bool identical<T>(const SpanCone<T>&, const SpanCone<T>&);
CONTACTCERT_CANONICAL_EXTERN(double)
CONTACTCERT_CANONICAL_EXTERN(Q)
#undef CONTACTCERT_CANONICAL_EXTERN

}  // namespace contactcert::geometry
