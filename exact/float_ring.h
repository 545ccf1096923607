// The ring operations of exact/fraction_free.h for the float number types of the precision ladder (double,
// MPFR floats, double intervals): the ring of such a field T is T itself. Signs are T's (a tolerance for
// double and MPFR, a proof or UncertainSign for intervals); rows are scaled by powers of two, which is exact
// in every one of them, so that a positive multiple of a row never costs a rounding.
#pragma once

#include <algorithm>
#include <cmath>

#include "exact/number.h"

namespace contactcert::exact::ring {

using Index = Eigen::Index;

/// A float number type (its traits are not exact).
template <class F>
concept Float = !NumberTraits<F>::is_exact;

template <Float F>
void mul(const F& a, const F& b, F& out) {
  out = a * b;
}
template <Float F>
void from_integer(const F& x, F& out) {
  out = x;
}
template <Float F>
F mul(const F& a, const F& b) {
  return a * b;
}
template <Float F>
F add(const F& a, const F& b) {
  return a + b;
}
template <Float F>
F sub(const F& a, const F& b) {
  return a - b;
}
template <Float F>
void from_integer(long x, F& out) {
  out = NumberTraits<F>::from_q(Q(x));  // at F's working precision (see exact/mpfr_number.h)
}
/// x rounded, and 1.
template <Float F>
void from_rational(const Q& x, F& num, F& den) {
  num = NumberTraits<F>::from_q(x);
  den = NumberTraits<F>::from_q(Q(1));
}
template <Float F>
void get(const Mat<F>& M, Index i, Index j, F& out) {
  out = M(i, j);
}
template <Float F>
int sign(const F& x) {
  return exact::sign(x);
}
template <Float F>
bool better_pivot(const F& candidate, const F& best) {
  return NumberTraits<F>::better_pivot(candidate, best);
}
template <Float F>
void dot(const F* a, const F* b, Index k, F& out) {
  out = F(0);
  for (Index i = 0; i < k; ++i) out += a[i] * b[i];
}
template <Float F>
void combine(const F* rp, const F& ap, const F* rm, const F& am, F* out, Index k) {
  for (Index i = 0; i < k; ++i) out[i] = ap * rm[i] - am * rp[i];
}
/// Zeroes the entries T skips as zero (below the tolerance of double or MPFR: rounding noise of a
/// cancellation, which scaling would blow up; the interval [0, 0]), then scales v by the power of two that
/// brings its largest entry (read in double) into [1, 2). The scaling is exact: the row keeps its direction
/// bit for bit, and a row whose largest entry is a power of two ends with largest entry 1.
template <Float F>
void normalize(F* v, Index k) {
  double m = 0;
  for (Index i = 0; i < k; ++i) {
    if (exact::is_negligible(v[i])) v[i] = F(0);
    m = std::max(m, std::abs(NumberTraits<F>::to_double(v[i])));
  }
  if (!(m > 0) || !std::isfinite(m)) return;
  int e = 0;
  std::frexp(m, &e);                                                   // m = f 2^e, 1/2 <= f < 1
  const F scale = NumberTraits<F>::from_q(Q(std::ldexp(1.0, 1 - e)));  // exact, at T's working precision
  for (Index i = 0; i < k; ++i) v[i] *= scale;
}
template <Float F>
void to_ring(const F* row, Index k, F* out) {
  std::copy(row, row + k, out);
  normalize(out, k);
}
template <class T, Float F>
T to_field(const F& x) {
  return T(x);
}

}  // namespace contactcert::exact::ring
