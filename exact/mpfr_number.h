// Binary floating point of any precision (MPFR, through CGAL::Gmpfr) as a number type of the templated
// algorithms: the MPFR rungs of the precision ladder (docs/precision.md).
//
// Why CGAL::Gmpfr and not boost::multiprecision's mpfr_float_backend<N>: boost fixes the precision in the
// type in decimal digits, so 53, 113, 256 or 1024 bits cannot be asked for (16 digits are 55 bits), and
// each precision would be one more instantiation of every algorithm. A Gmpfr carries its precision (in
// bits) and an operation rounds to the larger precision of its operands (never below MPFR's default, 53
// bits, which contactcert does not change): one instantiation serves every rung, and the rung is the
// precision the input is rounded to (to_mpfr).
//
// Include this header only where MPFR numbers are used: it pulls in CGAL.
#pragma once

#include <CGAL/Gmpfr.h>

#include "exact/lp_layer_extern.h"

namespace contactcert::exact {

using Mpfr = CGAL::Gmpfr;

/// MPFR floats: the float path's tolerance scaled with the precision p of x. |x| < 2^(-30 p / 53) counts
/// as zero (at p = 53, 2^-30 ~ 9.3e-10, as NumberTraits<double>): the same share of the mantissa is kept
/// as headroom for rounding errors at every precision.
template <>
struct NumberTraits<Mpfr> {
  static constexpr bool is_exact = false;
  static constexpr const char* name = "mpfr";
  static long zero_exponent(const Mpfr& x) { return -30L * precision(x) / 53; }
  /// The precision p of the test: x's own, or inside an MpfrPrecision scope the run's working precision
  /// (CGAL builds a Gmpfr from an int or a double with 256 or 512 bits whatever the default, and an
  /// operation keeps the larger precision, so constants would otherwise tighten the test below the
  /// accuracy of data rounded to fewer bits).
  static long precision(const Mpfr& x) {
    const long working = static_cast<long>(Mpfr::get_default_precision());
    return working > 53 ? working : static_cast<long>(x.get_precision());
  }
  static int sign(const Mpfr& x) {
    if (mpfr_zero_p(x.fr()) || mpfr_get_exp(x.fr()) <= zero_exponent(x)) return 0;
    return mpfr_sgn(x.fr());
  }
  static bool is_negligible(const Mpfr& x) { return sign(x) == 0; }
  static double to_double(const Mpfr& x) { return mpfr_get_d(x.fr(), MPFR_RNDN); }
  /// An exact number rounded to the nearest float of MPFR's default precision (the working precision of a
  /// scene algorithm's run, see MpfrPrecision).
  static Mpfr from_q(const Q& q) {
    Mpfr x;
    mpfr_set_q(x.fr(), q.get_mpq_t(), MPFR_RNDN);
    return x;
  }
  /// Partial pivoting, as for double.
  static bool better_pivot(const Mpfr& candidate, const Mpfr& best) {
    return mpfr_cmpabs(candidate.fr(), best.fr()) > 0;
  }
};

/// The sign tests of exact/number.h for Mpfr as plain functions: unqualified calls in the templated algorithms
/// pick them over CGAL's generic sign / is_zero / ..., which argument-dependent lookup also finds.
inline int sign(const Mpfr& x) { return NumberTraits<Mpfr>::sign(x); }
inline bool is_zero(const Mpfr& x) { return sign(x) == 0; }
inline bool is_positive(const Mpfr& x) { return sign(x) > 0; }
inline bool is_negative(const Mpfr& x) { return sign(x) < 0; }
inline bool is_negligible(const Mpfr& x) { return NumberTraits<Mpfr>::is_negligible(x); }

/// q rounded to the nearest float of `bits` bits (bits >= 53, MPFR's default precision).
Mpfr to_mpfr(const Q& q, long bits);
/// z rounded to the nearest float of `bits` bits (as to_mpfr(Q(z), bits)).
Mpfr to_mpfr(const Z& z, long bits);
/// The problem with every number rounded to `bits` bits.
LpProblem<Mpfr> to_mpfr(const LpProblem<Q>& problem, long bits);
/// x as the rational it is (every float is one).
Q to_rational(const Mpfr& x);

/// The working precision of the algorithms that read rational data (a scene) and convert it inside
/// (NumberTraits<Mpfr>::from_q): for the lifetime of this object, MPFR's default precision (per thread)
/// is `bits`, so that the data and every result carry at least `bits` bits (a constant built from an int or a
/// double carries 256 or 512, CGAL's choice); the previous one is restored after. (The UCP path rounds its problem up
/// front with to_mpfr; it needs the scope only for the sign test's working precision, see
/// NumberTraits<Mpfr>::precision.)
class MpfrPrecision {
 public:
  explicit MpfrPrecision(long bits) : previous_(Mpfr::set_default_precision(bits)) {}
  ~MpfrPrecision() { Mpfr::set_default_precision(previous_); }
  MpfrPrecision(const MpfrPrecision&) = delete;
  MpfrPrecision& operator=(const MpfrPrecision&) = delete;

 private:
  Mpfr::Precision_type previous_;
};

CONTACTCERT_LP_LAYER_EXTERN(Mpfr)

}  // namespace contactcert::exact
