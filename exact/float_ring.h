// The ring operations of exact/fraction_free.h for the other float number types of the precision ladder
// (MPFR floats, double intervals): the ring of such a field T is T itself, as for double. Signs are T's
// (a tolerance for MPFR, a proof or UncertainSign for intervals); rows are scaled by powers of two, which
// is exact in both types, so that a positive multiple of a row never costs a rounding.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "exact/number.h"

namespace contactcert::exact::ring {

using Index = Eigen::Index;

/// A float number type other than double (its traits are not exact).
template <class F>
concept OtherFloat = !std::is_same_v<F, double> && !NumberTraits<F>::is_exact;

template <OtherFloat F>
void mul(const F& a, const F& b, F& out) {
  out = a * b;
}
template <OtherFloat F>
void from_integer(const F& x, F& out) {
  out = x;
}
template <OtherFloat F>
F mul(const F& a, const F& b) {
  return a * b;
}
template <OtherFloat F>
F add(const F& a, const F& b) {
  return a + b;
}
template <OtherFloat F>
F sub(const F& a, const F& b) {
  return a - b;
}
template <OtherFloat F>
void from_integer(long x, F& out) {
  out = NumberTraits<F>::from_q(Q(x));  // at F's working precision (see exact/mpfr_number.h)
}
/// As for double: x rounded, and 1.
template <OtherFloat F>
void from_rational(const Q& x, F& num, F& den) {
  num = NumberTraits<F>::from_q(x);
  den = NumberTraits<F>::from_q(Q(1));
}
template <OtherFloat F>
void get(const Mat<F>& M, Index i, Index j, F& out) {
  out = M(i, j);
}
template <OtherFloat F>
int sign(const F& x) {
  return exact::sign(x);
}
template <OtherFloat F>
bool better_pivot(const F& candidate, const F& best) {
  return NumberTraits<F>::better_pivot(candidate, best);
}
template <OtherFloat F>
void dot(const F* a, const F* b, Index k, F& out) {
  out = F(0);
  for (Index i = 0; i < k; ++i) out += a[i] * b[i];
}
template <OtherFloat F>
void combine(const F* rp, const F& ap, const F* rm, const F& am, F* out, Index k) {
  for (Index i = 0; i < k; ++i) out[i] = ap * rm[i] - am * rp[i];
}
/// Zeroes the entries T skips as zero (a sub-tolerance MPFR float, the interval [0, 0]), then scales v by
/// the power of two that brings its largest entry (read in double) into [1/2, 1).
template <OtherFloat F>
void normalize(F* v, Index k) {
  double m = 0;
  for (Index i = 0; i < k; ++i) {
    if (exact::is_negligible(v[i])) v[i] = F(0);
    m = std::max(m, std::abs(NumberTraits<F>::to_double(v[i])));
  }
  if (!(m > 0) || !std::isfinite(m)) return;
  int e = 0;
  std::frexp(m, &e);
  const F scale = NumberTraits<F>::from_q(Q(std::ldexp(1.0, -e)));  // exact, at T's working precision
  for (Index i = 0; i < k; ++i) v[i] *= scale;
}
template <OtherFloat F>
void to_ring(const F* row, Index k, F* out) {
  std::copy(row, row + k, out);
  normalize(out, k);
}
template <class T, OtherFloat F>
T to_field(const F& x) {
  return T(x);
}

}  // namespace contactcert::exact::ring
