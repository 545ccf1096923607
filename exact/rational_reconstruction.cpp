#include "exact/rational_reconstruction.h"

#include <cmath>

namespace contactcert::exact {

namespace {

/// floor(a / b) for b > 0, in 64 bits when both fit (a 128-bit division costs several times more).
Int128 floor_div(Int128 a, Int128 b) {
  if (ring::fits_int64(a) && ring::fits_int64(b)) {
    const auto x = static_cast<std::int64_t>(a), y = static_cast<std::int64_t>(b), q = x / y;
    return q * y > x ? q - 1 : q;
  }
  const Int128 q = a / b;
  return q * b > a ? q - 1 : q;
}

}  // namespace

std::optional<Fraction> reconstruct(double v) {
  constexpr Int128 B = kReconstructionBound;
  if (!std::isfinite(v) || std::abs(v) >= 0x1p50) return std::nullopt;
  // Every convergent of v with |v| <= 1/B after the first is 0/1 (the first, -1/1 for v < 0, is too far).
  if (std::abs(v) <= 1.0 / static_cast<double>(B)) return Fraction{0, 1};
  // v = N / M exactly, M = 2^k: |N| < 2^53 (or v an integer, |N| < 2^50) and k <= 83 since |v| > 2^-30.
  int e = 0;
  const double mantissa = std::frexp(v, &e);  // v = mantissa 2^e, 1/2 <= |mantissa| < 1
  Int128 N = static_cast<std::int64_t>(std::ldexp(mantissa, 53));
  int k = 53 - e;
  if (k < 0) N <<= -k, k = 0;
  const Int128 M = Int128(1) << k;
  const Int128 tolerance = std::max(M, N < 0 ? -N : N);  // max(1, |v|) M
  // Euclid on (num, den) = (N, M): v = [a0; a1, ...], convergents p_i / q_i = (a_i p_{i-1} + p_{i-2}) / (...).
  Int128 num = N, den = M, p0 = 0, p1 = 1, q0 = 1, q1 = 0;
  for (;;) {
    const Int128 a = floor_div(num, den), rest = num - a * den;
    if (q1 > 0 && a > B) return std::nullopt;  // q2 >= a > B
    const Int128 q2 = a * q1 + q0;
    if (q2 > B) return std::nullopt;
    const Int128 p2 = a * p1 + p0;
    if (!ring::fits_int64(p2)) return std::nullopt;
    // |v - p2/q2| <= max(1, |v|) / B  <=>  |N q2 - p2 M| B <= max(M, |N|) q2 (|N q2 - p2 M| <= M).
    const Int128 error = N * q2 - p2 * M;
    if ((error < 0 ? -error : error) * B <= tolerance * q2)
      return Fraction{static_cast<std::int64_t>(p2), static_cast<std::int64_t>(q2)};
    num = den, den = rest;
    p0 = p1, p1 = p2, q0 = q1, q1 = q2;
  }
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

}  // namespace contactcert::exact
