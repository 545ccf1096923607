// Rationals left unreduced: a short formula in exact numbers evaluated in integers, without the gcd that every Q
// operation takes, and reduced once (or never, when only its sign or an order is read). unreduced(double) is the
// double itself, so one formula serves both paths and the float path computes exactly what it computed before.
#pragma once

#include "exact/number.h"

namespace contactcert::exact {

/// n / d with d > 0, not necessarily in lowest terms.
struct Unreduced {
  Z n, d;
};

inline Unreduced unreduced(const Q& x) { return {x.get_num(), x.get_den()}; }
inline double unreduced(double x) { return x; }

inline Unreduced operator-(const Unreduced& a) { return {-a.n, a.d}; }
inline Unreduced operator+(const Unreduced& a, const Unreduced& b) {
  if (a.d == b.d) return {a.n + b.n, a.d};
  return {a.n * b.d + b.n * a.d, a.d * b.d};
}
inline Unreduced operator-(const Unreduced& a, const Unreduced& b) {
  if (a.d == b.d) return {a.n - b.n, a.d};
  return {a.n * b.d - b.n * a.d, a.d * b.d};
}
inline Unreduced operator*(const Unreduced& a, const Unreduced& b) { return {a.n * b.n, a.d * b.d}; }
/// a / b for b != 0 (the denominator's sign moved to the numerator).
inline Unreduced operator/(const Unreduced& a, const Unreduced& b) {
  const bool same = a.d == b.d;  // then a / b = a.n / b.n
  Unreduced q = same ? Unreduced{a.n, b.n} : Unreduced{a.n * b.d, a.d * b.n};
  if (sgn(q.d) < 0) q = {-q.n, -q.d};
  return q;
}
/// a < b by cross-multiplication.
inline bool operator<(const Unreduced& a, const Unreduced& b) { return cmp(a.n * b.d, b.n * a.d) < 0; }
inline int sign(const Unreduced& x) { return sgn(x.n); }

/// x in lowest terms: the one gcd.
inline Q reduced(Unreduced x) {
  Q q;
  mpz_swap(mpq_numref(q.get_mpq_t()), x.n.get_mpz_t());
  mpz_swap(mpq_denref(q.get_mpq_t()), x.d.get_mpz_t());
  q.canonicalize();
  return q;
}
inline double reduced(double x) { return x; }

}  // namespace contactcert::exact
