// Double intervals (CGAL::Interval_nt) as a number type of the templated algorithms: the filter of the
// precision ladder (docs/precision.md). Every operation rounds outward, so an interval computed from
// intervals that enclose the exact data encloses the exact result; a sign is decided only when the interval
// proves it, and otherwise sign() throws UncertainSign, as CGAL's filtered predicates do. An algorithm run
// over intervals that does not throw has taken every decision as the exact run would have.
//
// Include this header only where intervals are used: it pulls in CGAL.
#pragma once

#include <CGAL/Interval_nt.h>

#include "exact/lp_layer_extern.h"

namespace contactcert::exact {

/// Protected intervals: each operation sets and restores the rounding mode itself (no caller duty).
using Interval = CGAL::Interval_nt<true>;

/// Thrown when an interval sign is uncertain (the interval holds 0 and another number). The same type
/// CGAL throws when an uncertain interval comparison is used as a bool.
using UncertainSign = CGAL::Uncertain_conversion_exception;

/// The smallest double interval that holds q.
Interval to_interval(const Q& q);
/// The smallest double interval that holds z (the one to_interval(Q(z)) gives).
Interval to_interval(const Z& z);

/// Intervals: a sign is -1, 0 (only the point 0) or +1 when the interval proves it; else UncertainSign.
/// Pivot choice as for Q (the first candidate), so that the interval run takes the exact run's decisions.
template <>
struct NumberTraits<Interval> {
  static constexpr bool is_exact = false;
  static constexpr const char* name = "interval";
  static int sign(const Interval& x) {
    if (x.inf() > 0) return 1;
    if (x.sup() < 0) return -1;
    if (x.inf() == 0 && x.sup() == 0) return 0;
    throw UncertainSign("interval sign is uncertain");
  }
  static bool is_negligible(const Interval& x) { return x.inf() == 0 && x.sup() == 0; }
  static double to_double(const Interval& x) { return CGAL::to_double(x); }
  /// The smallest double interval that holds q.
  static Interval from_q(const Q& q) { return to_interval(q); }
  static bool better_pivot(const Interval&, const Interval&) { return false; }
};

/// The sign tests of exact/number.h for Interval as plain functions: unqualified calls in the templated algorithms
/// pick them over CGAL's generic sign / is_zero / ..., which argument-dependent lookup also finds.
inline int sign(const Interval& x) { return NumberTraits<Interval>::sign(x); }
inline bool is_zero(const Interval& x) { return sign(x) == 0; }
inline bool is_positive(const Interval& x) { return sign(x) > 0; }
inline bool is_negative(const Interval& x) { return sign(x) < 0; }
inline bool is_negligible(const Interval& x) { return NumberTraits<Interval>::is_negligible(x); }

/// The midpoint of x as a rational (for error measures, not for proofs).
Q to_rational(const Interval& x);
/// The problem with every number enclosed in an interval.
LpProblem<Interval> to_interval(const LpProblem<Q>& problem);

CONTACTCERT_LP_LAYER_EXTERN(Interval)

}  // namespace contactcert::exact
