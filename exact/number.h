// The number types of contactcert and their traits.
//
// Q is the exact rational field. It is CGAL::Exact_rational, which CGAL 5.5 (configured with GMPXX,
// its CMake default) resolves to GMP's mpq_class; number.cpp checks that identity at compile time so
// that this header stays light (it does not include CGAL).
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <gmpxx.h>

namespace Eigen {
/// Eigen needs to know that mpq_class is an exact field (no epsilon, costly operations).
template <>
struct NumTraits<mpq_class> : GenericNumTraits<mpq_class> {
  using Real = mpq_class;
  using NonInteger = mpq_class;
  using Nested = mpq_class;
  using Literal = mpq_class;
  enum { IsInteger = 0, IsSigned = 1, IsComplex = 0, RequireInitialization = 1, ReadCost = 8, AddCost = 200, MulCost = 200 };
  static Real epsilon() { return 0; }
  static Real dummy_precision() { return 0; }
  static int digits10() { return 0; }
};
}  // namespace Eigen

namespace contactcert::exact {

/// The exact rational field (CGAL::Exact_rational over GMP). Always canonical (lowest terms).
using Q = mpq_class;
/// Exact integers (numerators, denominators, primitive vectors).
using Z = mpz_class;

template <class T>
using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
template <class T>
using Vec = Eigen::Matrix<T, Eigen::Dynamic, 1>;

/// Sign and zero tests over a number type: exact for Q, with a documented tolerance for double.
/// Algorithms are written once over T and call only these to decide a sign. `is_negligible` is not a
/// decision: it lets an update loop skip an entry that is zero for T (an interval skips only the point 0).
/// More number types (MPFR floats, intervals) have their traits in exact/mpfr_number.h, exact/interval_number.h.
template <class T>
struct NumberTraits;

template <>
struct NumberTraits<Q> {
  static constexpr bool is_exact = true;
  static constexpr const char* name = "exact";
  static int sign(const Q& x) { return sgn(x); }
  static bool is_negligible(const Q& x) { return sgn(x) == 0; }
  static double to_double(const Q& x) { return x.get_d(); }
  /// Pivot choice in elimination: any non-zero pivot is exact, so keep the first one.
  static bool better_pivot(const Q&, const Q&) { return false; }
};

template <>
struct NumberTraits<double> {
  static constexpr bool is_exact = false;
  static constexpr const char* name = "float";
  /// Absolute tolerance of the float path's sign test: |x| <= tolerance counts as zero. The data the
  /// papers use is of order 1 to 100; the verified path never trusts a float sign without an exact check.
  static constexpr double tolerance = 1e-9;
  static int sign(double x) { return x > tolerance ? 1 : (x < -tolerance ? -1 : 0); }
  static bool is_negligible(double x) { return sign(x) == 0; }
  static double to_double(double x) { return x; }
  /// An exact number rounded to the nearest double.
  static double from_q(const Q& x) { return x.get_d(); }
  /// Partial pivoting: prefer the entry of largest magnitude.
  static bool better_pivot(double candidate, double best) { return std::abs(candidate) > std::abs(best); }
};

template <class T>
int sign(const T& x) {
  return NumberTraits<T>::sign(x);
}
template <class T>
bool is_zero(const T& x) {
  return NumberTraits<T>::sign(x) == 0;
}
/// True if an update loop may skip x as a zero (not a sign decision; see NumberTraits).
template <class T>
bool is_negligible(const T& x) {
  return NumberTraits<T>::is_negligible(x);
}
template <class T>
bool is_positive(const T& x) {
  return NumberTraits<T>::sign(x) > 0;
}
template <class T>
bool is_negative(const T& x) {
  return NumberTraits<T>::sign(x) < 0;
}

/// Converts an exact matrix to doubles (for the float path and for `_approx` outputs).
Mat<double> to_double(const Mat<Q>& A);
Vec<double> to_double(const Vec<Q>& v);

}  // namespace contactcert::exact
