#include "exact/rational_reconstruction.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace contactcert::exact {

namespace {

/// floor(a / b) for b > 0 in the integer type I (std::int64_t or Int128), in 64 bits when both fit (a 128-bit
/// division costs several times more).
template <class I>
I floor_div(I a, I b) {
  if constexpr (std::is_same_v<I, Int128>)
    if (ring::fits_int64(a) && ring::fits_int64(b))
      return floor_div(static_cast<std::int64_t>(a), static_cast<std::int64_t>(b));
  const I q = a / b;
  return q * b > a ? q - 1 : q;
}

/// The first convergent of N / M (M > 0) within max(1, |N / M|) / B, B = kReconstructionBound, as reconstruct
/// states it. The Euclidean quantities are in I: std::int64_t when N and M fit (the common case, every division
/// in 64 bits), else Int128; a convergent's p and q are kept in 64 bits and their products formed in 128.
template <class I>
std::optional<Fraction> first_convergent(I N, I M) {
  constexpr std::int64_t B = kReconstructionBound;
  const I tolerance = std::max(M, N < 0 ? I(-N) : N);  // max(1, |v|) M
  // Euclid on (num, den) = (N, M): v = [a0; a1, ...], convergents p_i / q_i = (a_i p_{i-1} + p_{i-2}) / (...),
  // remainders r_i = r_{i-2} - a_i r_{i-1} (r_{-2} = N, r_{-1} = M), and by induction N q_i - M p_i = (-1)^i r_i.
  I num = N, den = M;
  std::int64_t p0 = 0, p1 = 1, q0 = 1, q1 = 0;
  for (;;) {
    const I a = floor_div(num, den), rest = num - a * den;  // 0 <= rest < den <= M
    if (q1 > 0 && a > B) return std::nullopt;               // q2 >= a > B
    // Now |a| < 2^50: a0 = floor(v), or a <= B.
    const auto a64 = static_cast<std::int64_t>(a);
    const Int128 q2 = Int128(a64) * q1 + q0;
    if (q2 > B) return std::nullopt;
    const Int128 p2 = Int128(a64) * p1 + p0;
    if (!ring::fits_int64(p2)) return std::nullopt;
    // |v - p2/q2| <= max(1, |v|) / B  <=>  |N q2 - p2 M| B <= max(M, |N|) q2, and |N q2 - p2 M| = rest.
    if (Int128(rest) * B <= Int128(tolerance) * q2)
      return Fraction{static_cast<std::int64_t>(p2), static_cast<std::int64_t>(q2)};
    num = den, den = rest;
    p0 = p1, p1 = static_cast<std::int64_t>(p2), q0 = q1, q1 = static_cast<std::int64_t>(q2);
  }
}

}  // namespace

std::optional<Fraction> reconstruct(double v) {
  if (!std::isfinite(v) || std::abs(v) >= 0x1p50) return std::nullopt;
  // Every convergent of v with |v| <= 1/B after the first is 0/1 (the first, -1/1 for v < 0, is too far).
  if (std::abs(v) <= 1.0 / static_cast<double>(kReconstructionBound)) return Fraction{0, 1};
  // An integer is its own first convergent (the common case of the LPs' optima and duals).
  if (v == std::floor(v)) return Fraction{static_cast<std::int64_t>(v), 1};
  // v = N / 2^k exactly in lowest terms: |N| < 2^53 and 1 <= k <= 83 since v is not an integer and |v| > 2^-30.
  int e = 0;
  const double mantissa = std::frexp(v, &e);  // v = mantissa 2^e, 1/2 <= |mantissa| < 1
  const std::int64_t n = static_cast<std::int64_t>(std::ldexp(mantissa, 53));
  const int twos = std::min(53 - e, __builtin_ctzll(static_cast<unsigned long long>(n)));
  const int k = 53 - e - twos;
  if (k <= 62) return first_convergent<std::int64_t>(n >> twos, std::int64_t(1) << k);
  return first_convergent<Int128>(n >> twos, Int128(1) << k);
}

template <class R>
bool reconstruct_vector(const std::vector<double>& v, std::vector<R>& out, R& D) {
  std::vector<Fraction> f;
  f.reserve(v.size());
  D = R(1);
  for (double x : v) {
    const std::optional<Fraction> r = reconstruct(x);
    if (!r) return false;
    D = ring::lcm(D, R(r->den));
    f.push_back(*r);
  }
  out.resize(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[i] = ring::mul(R(f[i].num), ring::divexact(D, R(f[i].den)));
  return true;
}

template bool reconstruct_vector<Int128>(const std::vector<double>&, std::vector<Int128>&, Int128&);
template bool reconstruct_vector<Z>(const std::vector<double>&, std::vector<Z>&, Z&);

bool reconstruct_modular(const Z& u, const Z& m, const Z& bound, Z& n, Z& d) {
  Z r0 = m, r1 = u, t0 = 0, t1 = 1, q, t;
  while (r1 > bound) {
    mpz_fdiv_q(q.get_mpz_t(), r0.get_mpz_t(), r1.get_mpz_t());
    t = r0 - q * r1;
    r0 = std::move(r1);
    r1 = std::move(t);
    t = t0 - q * t1;
    t0 = std::move(t1);
    t1 = std::move(t);
  }
  if (abs(t1) > bound || gcd(r1, t1) != 1) return false;
  n = sgn(t1) < 0 ? Z(-r1) : r1;
  d = abs(t1);
  return true;
}

}  // namespace contactcert::exact
