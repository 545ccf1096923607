// The ring operations of exact/fraction_free.h for every float number type (double, MPFR floats, double
// intervals): the ring of such a field F is F itself. One template for all of them; the types differ only in
// their sign test (a tolerance for double and MPFR, a proof or UncertainSign for intervals) and in how a
// machine number becomes an F. Rows are normalized to max-norm 1 (one representative per direction, up to
// rounding), as the exact rings make them primitive.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "exact/number.h"

namespace contactcert::exact::ring {

using Index = Eigen::Index;

/// A float number type (its traits are not exact): double, exact::Mpfr, exact::Interval.
template <class F>
concept FloatNumber = !NumberTraits<F>::is_exact;

/// A float type whose numbers are enclosures (intervals) rather than points.
template <class F>
concept Enclosure = requires(const F& x) {
  x.inf();
  x.sup();
};

/// A machine number x (long or double) as F at F's working precision: MPFR's default precision (its own
/// constructor would take 64 bits per byte of the source type), the enclosing interval, the double itself.
template <FloatNumber F, class X>
F from_machine(X x) {
  if constexpr (requires { F::get_default_precision(); })
    return F(x, F::get_default_precision());
  else
    return F(x);
}

template <FloatNumber F>
void mul(const F& a, const F& b, F& out) {
  out = a * b;
}
template <FloatNumber F>
void from_integer(const F& x, F& out) {
  out = x;
}
template <FloatNumber F>
F mul(const F& a, const F& b) {
  return a * b;
}
template <FloatNumber F>
F add(const F& a, const F& b) {
  return a + b;
}
template <FloatNumber F>
F sub(const F& a, const F& b) {
  return a - b;
}
template <FloatNumber F>
void from_integer(long x, F& out) {
  out = from_machine<F>(x);
}
/// x rounded (at F's working precision), and 1.
template <FloatNumber F>
void from_rational(const Q& x, F& num, F& den) {
  num = NumberTraits<F>::from_q(x);
  den = from_machine<F>(1L);
}
template <FloatNumber F>
void get(const Mat<F>& M, Index i, Index j, F& out) {
  out = M(i, j);
}
template <FloatNumber F>
int sign(const F& x) {
  return exact::sign(x);
}
template <FloatNumber F>
bool better_pivot(const F& candidate, const F& best) {
  return NumberTraits<F>::better_pivot(candidate, best);
}
template <FloatNumber F>
void dot(const F* a, const F* b, Index k, F& out) {
  out = F(0);
  for (Index i = 0; i < k; ++i) out += a[i] * b[i];
}
/// out does not overlap the inputs (__restrict: ap and am stay in registers across the loop).
template <FloatNumber F>
void combine(const F* rp, const F& ap, const F* rm, const F& am, F* __restrict out, Index k) {
  for (Index i = 0; i < k; ++i) out[i] = ap * rm[i] - am * rp[i];
}
/// Zeroes the entries F skips as zero (rounding noise of a cancellation below the tolerance, the interval
/// [0, 0]: scaling would blow them up), then divides v by its max-norm m, so that parallel rows become equal
/// up to rounding (a power of two would keep rows whose ratio is not one apart). The divisor is a point: the
/// largest entry's magnitude itself, or for an enclosure m read in double, so that every entry stays an
/// enclosure of the same positive multiple of the row.
template <FloatNumber F>
void normalize(F* v, Index k) {
  double m = 0;
  Index at = 0;
  for (Index i = 0; i < k; ++i) {
    if (exact::is_negligible(v[i])) v[i] = F(0);
    const double a = std::abs(NumberTraits<F>::to_double(v[i]));
    if (a > m) m = a, at = i;
  }
  if (!(m > 0) || !std::isfinite(m)) return;
  F norm;
  if constexpr (Enclosure<F>)
    norm = from_machine<F>(m);
  else
    norm = v[at] < 0 ? F(-v[at]) : v[at];
  for (Index i = 0; i < k; ++i) v[i] /= norm;
}
template <FloatNumber F>
void to_ring(const F* row, Index k, F* out) {
  std::copy(row, row + k, out);
  normalize(out, k);
}
template <class T, FloatNumber F>
T to_field(const F& x) {
  return T(x);
}

}  // namespace contactcert::exact::ring
