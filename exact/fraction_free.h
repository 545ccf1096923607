// Fraction-free row arithmetic over the ring an exact or float algorithm runs in:
//   std::int64_t  exact, fixed width; every operation checks for overflow and throws RingOverflow,
//   Z             exact, unbounded (GMP),
//   a float F     F itself (double, MPFR, intervals) with F's sign test: exact/float_ring.h.
// Exact callers run in std::int64_t first and restart in Z on overflow (with_exact_ring), so the result
// is exact either way and fixed width is only a speed-up. Rows of a field matrix become primitive
// integer rows (Q) or unit max-norm rows (a float): both are positive multiples of the field row.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

#include "exact/float_ring.h"  // the same operations for every float number type
#include "exact/number.h"

namespace contactcert::exact {

/// Thrown by the std::int64_t ring when a result does not fit; the caller restarts in Z.
struct RingOverflow {};

/// The fixed-width ring of the exact integer checks (rounded_check.h, int_matrix.h, the UCP's physical recovery):
/// exact, every operation overflow-checked (throws RingOverflow). 128 bits, not 64: the paper's data overflow 64 bits
/// in the elimination of IntMatrix::solve.
__extension__ typedef __int128 Int128;

/// The ring an algorithm over the field T runs in when it stays fraction-free: Z for Q, T itself for a float T.
/// (std::int64_t is the fast exact alternative to Z, see with_exact_ring.)
template <class T>
using Ring = std::conditional_t<std::is_same_v<T, Q>, Z, T>;

/// Runs `f.template operator()<R>()` in the ring R of T: for T = Q first in the fixed-width integers Fixed
/// (std::int64_t, or a wider checked type such as exact::Int128) and, on RingOverflow, again in Z; for a float
/// T in T. The answer is the same either way: the fixed width is only a speed-up.
template <class T, class Fixed = std::int64_t, class F>
auto with_exact_ring(F&& f) {
  if constexpr (std::is_same_v<T, Q>) {
    try {
      return f.template operator()<Fixed>();
    } catch (const RingOverflow&) {
      return f.template operator()<Z>();
    }
  } else {
    return f.template operator()<T>();
  }
}

namespace ring {

using Index = Eigen::Index;

// std::int64_t: INT64_MIN is excluded so that negation and |x| never overflow.
inline std::int64_t checked(std::int64_t x) {
  if (x == std::numeric_limits<std::int64_t>::min()) throw RingOverflow{};
  return x;
}
inline std::int64_t mul(std::int64_t a, std::int64_t b) {
  std::int64_t r;
  if (__builtin_mul_overflow(a, b, &r)) throw RingOverflow{};
  return checked(r);
}
inline std::int64_t add(std::int64_t a, std::int64_t b) {
  std::int64_t r;
  if (__builtin_add_overflow(a, b, &r)) throw RingOverflow{};
  return checked(r);
}
inline std::int64_t sub(std::int64_t a, std::int64_t b) {
  std::int64_t r;
  if (__builtin_sub_overflow(a, b, &r)) throw RingOverflow{};
  return checked(r);
}

/// out = a * b.
inline void mul(std::int64_t a, std::int64_t b, std::int64_t& out) { out = mul(a, b); }
inline void mul(const Z& a, const Z& b, Z& out) { mpz_mul(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t()); }

/// An integer-valued element of the field as a ring element (Q: precondition x is an integer;
/// a float: as is).
inline void from_integer(const Z& x, std::int64_t& out);
inline void from_integer(const Q& x, std::int64_t& out) { from_integer(x.get_num(), out); }
inline void from_integer(const Q& x, Z& out) { out = x.get_num(); }

inline int sign(std::int64_t x) { return (x > 0) - (x < 0); }
inline int sign(const Z& x) { return sgn(x); }

/// Pivot choice: the first non-zero entry in the exact rings (a float's own rule: exact/float_ring.h).
inline bool better_pivot(std::int64_t, std::int64_t) { return false; }
inline bool better_pivot(const Z&, const Z&) { return false; }

/// out = a . b over k entries.
inline void dot(const std::int64_t* a, const std::int64_t* b, Index k, std::int64_t& out) {
  out = 0;
  for (Index i = 0; i < k; ++i) out = add(out, mul(a[i], b[i]));
}
inline void dot(const Z* a, const Z* b, Index k, Z& out) {
  out = 0;
  for (Index i = 0; i < k; ++i) mpz_addmul(out.get_mpz_t(), a[i].get_mpz_t(), b[i].get_mpz_t());
}

/// out = ap * rm - am * rp: with a . rp = ap and a . rm = am, a . out = 0 (one elimination step);
/// a positive combination of rp and rm when ap > 0 > am.
inline void combine(const std::int64_t* rp, std::int64_t ap, const std::int64_t* rm, std::int64_t am, std::int64_t* out,
                    Index k) {
  for (Index i = 0; i < k; ++i) out[i] = sub(mul(ap, rm[i]), mul(am, rp[i]));
}
inline void combine(const Z* rp, const Z& ap, const Z* rm, const Z& am, Z* out, Index k) {
  for (Index i = 0; i < k; ++i) {
    mpz_mul(out[i].get_mpz_t(), ap.get_mpz_t(), rm[i].get_mpz_t());
    mpz_submul(out[i].get_mpz_t(), am.get_mpz_t(), rp[i].get_mpz_t());
  }
}

/// Divides v by the positive gcd of its entries (primitive vector; a float: by its max-norm).
inline void normalize(std::int64_t* v, Index k) {
  std::int64_t g = 0;
  for (Index i = 0; i < k && g != 1; ++i) g = std::gcd(g, v[i]);
  if (g > 1)
    for (Index i = 0; i < k; ++i) v[i] /= g;
}
inline void normalize(Z* v, Index k) {
  Z g = 0;
  for (Index i = 0; i < k && g != 1; ++i) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), v[i].get_mpz_t());
  if (g > 1)
    for (Index i = 0; i < k; ++i) mpz_divexact(v[i].get_mpz_t(), v[i].get_mpz_t(), g.get_mpz_t());
}

/// Int128: true if x fits in 64 bits (two instructions, against four 128-bit comparisons).
inline bool fits_int64(Int128 x) { return static_cast<Int128>(static_cast<std::int64_t>(x)) == x; }
/// The checked 128-bit product, out of line so that the common case of mul stays small enough to inline.
[[gnu::noinline]] inline Int128 mul_wide(Int128 a, Int128 b) {
  Int128 r;
  if (__builtin_mul_overflow(a, b, &r)) throw RingOverflow{};
  return r;
}

/// Value-returning ring arithmetic for short formulas (std::int64_t, Int128: checked, see above).
[[gnu::always_inline]] inline Int128 mul(Int128 a, Int128 b) {
  // |a b| <= 2^126: no check, and one 64 x 64 -> 128-bit multiplication (the common case).
  if (fits_int64(a) && fits_int64(b)) return Int128(static_cast<std::int64_t>(a)) * static_cast<std::int64_t>(b);
  return mul_wide(a, b);
}
inline Int128 add(Int128 a, Int128 b) {
  Int128 r;
  if (__builtin_add_overflow(a, b, &r)) throw RingOverflow{};
  return r;
}
inline Int128 sub(Int128 a, Int128 b) {
  Int128 r;
  if (__builtin_sub_overflow(a, b, &r)) throw RingOverflow{};
  return r;
}
inline int sign(Int128 x) { return (x > 0) - (x < 0); }
inline Z mul(const Z& a, const Z& b) { return a * b; }
inline Z add(const Z& a, const Z& b) { return a + b; }
inline Z sub(const Z& a, const Z& b) { return a - b; }

/// The non-negative gcd, and a / b for b dividing a (exact rings).
inline std::int64_t gcd(std::int64_t a, std::int64_t b) { return std::gcd(a, b); }
inline Z gcd(const Z& a, const Z& b) {
  Z g;
  mpz_gcd(g.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return g;
}
inline std::int64_t divexact(std::int64_t a, std::int64_t b) { return a / b; }
/// The least common multiple of positive a and b.
inline std::int64_t lcm(std::int64_t a, std::int64_t b) { return mul(a / std::gcd(a, b), b); }
inline Z divexact(const Z& a, const Z& b) {
  Z q;
  mpz_divexact(q.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return q;
}
/// Int128: the binary gcd, in 64 bits when both fit (the common case of the paper's data).
inline Int128 gcd(Int128 a, Int128 b) {
  __extension__ typedef unsigned __int128 U128;
  U128 u = a < 0 ? -static_cast<U128>(a) : static_cast<U128>(a),
       v = b < 0 ? -static_cast<U128>(b) : static_cast<U128>(b);
  if ((u | v) >> 64 == 0)
    return static_cast<Int128>(std::gcd(static_cast<std::uint64_t>(u), static_cast<std::uint64_t>(v)));
  if (u == 0 || v == 0) {
    const U128 g = u | v;
    if (g >> 127 != 0) throw RingOverflow{};  // |INT128_MIN|
    return static_cast<Int128>(g);
  }
  auto ctz = [](U128 x) {
    const auto lo = static_cast<std::uint64_t>(x);
    return lo != 0 ? __builtin_ctzll(lo) : 64 + __builtin_ctzll(static_cast<std::uint64_t>(x >> 64));
  };
  const int shift = std::min(ctz(u), ctz(v));
  u >>= ctz(u);
  do {
    v >>= ctz(v);
    if (u > v) std::swap(u, v);
    v -= u;
  } while (v != 0);
  u <<= shift;
  if (u >> 127 != 0) throw RingOverflow{};
  return static_cast<Int128>(u);
}
/// Int128: a / b for b dividing a (b != 0), in 64 bits when both fit.
inline Int128 divexact(Int128 a, Int128 b) {
  // INT64_MIN / -1 overflows in 64 bits: that case takes the 128-bit division.
  if (fits_int64(a) && fits_int64(b) && b != -1) return static_cast<std::int64_t>(a) / static_cast<std::int64_t>(b);
  return b == -1 ? sub(0, a) : a / b;
}
/// The least common multiple of positive a and b (without a gcd when one divides the other, the common case
/// of decimal data).
inline Int128 lcm_by_gcd(Int128 a, Int128 b) {
  if ((a | b) >> 63 == 0) {
    const auto u = static_cast<std::uint64_t>(a), v = static_cast<std::uint64_t>(b);
    if (u % v == 0) return a;
    if (v % u == 0) return b;
  }
  return mul(divexact(a, gcd(a, b)), b);
}
inline Int128 lcm(Int128 a, Int128 b) {
  if (a == b || b == 1) return a;
  if (a == 1) return b;
  return lcm_by_gcd(a, b);
}
/// Z: without a gcd when the two are equal or one divides the other (a running lcm of denominators that mostly
/// repeat: the recovery's rows, the vectors over one denominator).
inline Z lcm(const Z& a, const Z& b) {
  if (mpz_cmp(a.get_mpz_t(), b.get_mpz_t()) == 0 || mpz_cmp_ui(b.get_mpz_t(), 1) == 0) return a;
  if (mpz_cmp_ui(a.get_mpz_t(), 1) == 0) return b;
  if (mpz_divisible_p(a.get_mpz_t(), b.get_mpz_t())) return a;
  if (mpz_divisible_p(b.get_mpz_t(), a.get_mpz_t())) return b;
  Z l;
  mpz_lcm(l.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return l;
}

/// In place, for the inner loops of eliminations and dot products: the same values, and in Z no temporary (each
/// GMP temporary is a heap allocation and a free).
/// acc += a b.
inline void add_mul(std::int64_t& acc, std::int64_t a, std::int64_t b) { acc = add(acc, mul(a, b)); }
inline void add_mul(Int128& acc, Int128 a, Int128 b) { acc = add(acc, mul(a, b)); }
inline void add_mul(Z& acc, const Z& a, const Z& b) { mpz_addmul(acc.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t()); }
/// out = a b - c e (out may be b, not c or e).
inline void mul_sub(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t e, std::int64_t& out) {
  out = sub(mul(a, b), mul(c, e));
}
inline void mul_sub(Int128 a, Int128 b, Int128 c, Int128 e, Int128& out) { out = sub(mul(a, b), mul(c, e)); }
inline void mul_sub(const Z& a, const Z& b, const Z& c, const Z& e, Z& out) {
  mpz_mul(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  mpz_submul(out.get_mpz_t(), c.get_mpz_t(), e.get_mpz_t());
}
/// a = a / b for b dividing a.
inline void divexact_by(std::int64_t& a, std::int64_t b) { a = divexact(a, b); }
inline void divexact_by(Int128& a, Int128 b) { a = divexact(a, b); }
inline void divexact_by(Z& a, const Z& b) { mpz_divexact(a.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t()); }

/// An integer as a ring element.
/// std::int64_t: reads GMP's limb (mpz_size, mpz_getlimbn: inline, this runs once per entry when an LP or a
/// system is scaled to integers); |x| >= 2^63 overflows (INT64_MIN too, as in `checked`).
inline void from_integer(const Z& x, std::int64_t& out) {
  mpz_srcptr z = x.get_mpz_t();
  const mp_limb_t magnitude = mpz_getlimbn(z, 0);  // 0 for x = 0
  if (mpz_size(z) > 1 || magnitude > static_cast<mp_limb_t>(std::numeric_limits<std::int64_t>::max()))
    throw RingOverflow{};
  out = mpz_sgn(z) < 0 ? -static_cast<std::int64_t>(magnitude) : static_cast<std::int64_t>(magnitude);
}
inline void from_integer(const Z& x, Z& out) { out = x; }
/// Int128: reads GMP's limbs (mpz_size, mpz_getlimbn: inline, this runs once per rational read by the
/// integer checks).
[[gnu::noinline]] inline void from_two_limbs(mpz_srcptr z, Int128& out) {
  __extension__ typedef unsigned __int128 U128;
  if (mpz_size(z) != 2 || mpz_getlimbn(z, 1) >> 63 != 0) throw RingOverflow{};
  const U128 u = static_cast<U128>(mpz_getlimbn(z, 1)) << 64 | mpz_getlimbn(z, 0);
  out = mpz_sgn(z) < 0 ? -static_cast<Int128>(u) : static_cast<Int128>(u);
}
[[gnu::always_inline]] inline void from_integer(const Z& x, Int128& out) {
  static_assert(sizeof(mp_limb_t) == 8);
  mpz_srcptr z = x.get_mpz_t();
  const std::size_t size = mpz_size(z);
  if (size == 0)
    out = 0;
  else if (size == 1)
    out = mpz_sgn(z) > 0 ? static_cast<Int128>(mpz_getlimbn(z, 0)) : -static_cast<Int128>(mpz_getlimbn(z, 0));
  else
    from_two_limbs(z, out);
}
inline void from_integer(long x, std::int64_t& out) { out = checked(x); }
inline void from_integer(long x, Int128& out) { out = x; }
inline void from_integer(long x, Z& out) { out = x; }

/// A rational x = num / den (den > 0, lowest terms) in an exact ring; in a float, x rounded and 1.
inline void from_rational(const Q& x, std::int64_t& num, std::int64_t& den) {
  from_integer(x.get_num(), num);
  from_integer(x.get_den(), den);
}
inline void from_rational(const Q& x, Int128& num, Int128& den) {
  from_integer(x.get_num(), num);
  from_integer(x.get_den(), den);
}
inline void from_rational(const Q& x, Z& num, Z& den) {
  num = x.get_num();
  den = x.get_den();
}

/// A ring element as an element of the field T.
template <class T>
T to_field(std::int64_t x) {
  return T(static_cast<long>(x));
}
template <class T>
T to_field(const Z& x) {
  return T(x);
}
/// An Int128 as an integer of GMP.
inline Z to_z(Int128 x) {
  if (x >= std::numeric_limits<long>::min() && x <= std::numeric_limits<long>::max()) return Z(static_cast<long>(x));
  __extension__ typedef unsigned __int128 U128;
  const U128 u = x < 0 ? -static_cast<U128>(x) : static_cast<U128>(x);
  Z z = static_cast<unsigned long>(u >> 64);
  mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), 64);
  z += static_cast<unsigned long>(u);
  if (x < 0) mpz_neg(z.get_mpz_t(), z.get_mpz_t());
  return z;
}
template <class T>
T to_field(Int128 x) {
  return T(to_z(x));
}

/// out = num / den (den != 0) in lowest terms, made without rational arithmetic (and without allocating when
/// out's limbs suffice).
inline void to_rational(Int128 num, Int128 den, Q& out) {
  if (num == 0) {
    out = 0;
    return;
  }
  const Int128 g = gcd(num, den);
  num = divexact(num, g), den = divexact(den, g);
  if (den < 0) num = sub(0, num), den = sub(0, den);
  if (num >= std::numeric_limits<long>::min() && num <= std::numeric_limits<long>::max() &&
      den <= std::numeric_limits<long>::max()) {
    mpq_set_si(out.get_mpq_t(), static_cast<long>(num), static_cast<unsigned long>(den));
  } else {
    mpz_set(mpq_numref(out.get_mpq_t()), to_z(num).get_mpz_t());
    mpz_set(mpq_denref(out.get_mpq_t()), to_z(den).get_mpz_t());
  }
}
inline void to_rational(const Z& num, const Z& den, Q& out) {
  mpz_set(mpq_numref(out.get_mpq_t()), num.get_mpz_t());
  mpz_set(mpq_denref(out.get_mpq_t()), den.get_mpz_t());
  out.canonicalize();
}

/// True if the rational q (in lowest terms) is an integer.
inline bool is_integer(const Q& q) {
  mpz_srcptr den = mpq_denref(q.get_mpq_t());
  return mpz_size(den) == 1 && mpz_getlimbn(den, 0) == 1;
}

/// The rationals q(0), ..., q(k-1) over their least common denominator L (returned, > 0) in the exact ring R:
/// q(i) = out[i] / L.
template <class R, class Get>
R to_common_denominator(Index k, Get q, R* out) {
  R L(1), den;
  for (Index i = 0; i < k; ++i) {
    const Q& v = q(i);
    if (is_integer(v)) continue;
    from_integer(v.get_den(), den);
    L = lcm(L, den);
  }
  for (Index i = 0; i < k; ++i) {
    const Q& v = q(i);
    from_integer(v.get_num(), out[i]);
    if (is_integer(v)) {
      if (L != 1) out[i] = mul(out[i], L);
    } else if (sign(out[i]) != 0) {
      from_integer(v.get_den(), den);
      if (den != L) out[i] = mul(out[i], divexact(L, den));
    }
  }
  return L;
}

/// A field row as a ring row: the primitive integer multiple (Q: the row over its common denominator, divided
/// by its content), the unit max-norm multiple (a float).
inline void to_ring(const Q* row, Index k, std::int64_t* out) {
  to_common_denominator<std::int64_t>(
      k, [row](Index i) -> const Q& { return row[i]; }, out);
  normalize(out, k);
}
inline void to_ring(const Q* row, Index k, Z* out) {
  to_common_denominator<Z>(
      k, [row](Index i) -> const Q& { return row[i]; }, out);
  normalize(out, k);
}

/// out = x in the field T, in place (a rational's limbs are reused: no temporary is made).
inline void to_field(std::int64_t x, Q& out) { mpq_set_si(out.get_mpq_t(), static_cast<long>(x), 1); }
inline void to_field(const Z& x, Q& out) { mpq_set_z(out.get_mpq_t(), x.get_mpz_t()); }
template <class T, class R>
void to_field(const R& x, T& out) {
  out = to_field<T>(x);
}

}  // namespace ring
}  // namespace contactcert::exact
