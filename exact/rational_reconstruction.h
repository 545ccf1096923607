// Rational reconstruction: the simple fraction a float approximates, read off the continued fraction of the
// float's exact (dyadic) value under a denominator bound, and the fraction a residue modulo m stands for (Dixon's
// p-adic lifting, padic_solve.h). Every "round the float answer, then check it exactly" of the verified paths
// reconstructs its numbers here.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "exact/fraction_free.h"

namespace contactcert::exact {

/// The denominator bound B of a reconstructed fraction.
inline constexpr std::int64_t kReconstructionBound = std::int64_t(1) << 30;

/// num / den with den > 0, in lowest terms.
struct Fraction {
  std::int64_t num, den;
};

/// The first convergent p/q of the continued fraction of v (computed exactly on v = N / 2^k) with
/// |v - p/q| <= max(1, |v|) / B, B = kReconstructionBound; nullopt if v is not finite, |v| >= 2^50, or a
/// convergent's denominator exceeds B (or its numerator 64 bits) first.
std::optional<Fraction> reconstruct(double v);

/// The entries of v reconstructed and written over their least common denominator D in the exact ring R:
/// v_i ~ out_i / D. False if an entry has no reconstruction; Int128 throws RingOverflow if D or an out_i
/// does not fit.
template <class R>
bool reconstruct_vector(const std::vector<double>& v, std::vector<R>& out, R& D);

/// n / d (d > 0, lowest terms) with n = d u mod m and |n|, d <= bound (bound <= sqrt(m / 2) makes it unique), if
/// there is one: the extended Euclidean algorithm on (m, u) stopped at the first remainder <= bound (von zur Gathen
/// and Gerhard, Modern Computer Algebra, section 5.10).
bool reconstruct_modular(const Z& u, const Z& m, const Z& bound, Z& n, Z& d);

extern template bool reconstruct_vector<Int128>(const std::vector<double>&, std::vector<Int128>&, Int128&);
extern template bool reconstruct_vector<Z>(const std::vector<double>&, std::vector<Z>&, Z&);

}  // namespace contactcert::exact
