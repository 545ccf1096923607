// Exact text forms of rational numbers (SPEC section 1): parsing without any rounding, printing in
// lowest terms, and primitive integer direction vectors.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "exact/number.h"

namespace contactcert::exact {

/// Thrown by parse_rational; what() says what was expected.
struct NumberSyntaxError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Largest |decimal exponent| accepted ("1e4096" is fine, "1e99999" is rejected): bounds the work
/// an input number can cause.
inline constexpr long kMaxDecimalExponent = 4096;

/// Most decimal digits accepted in a mantissa, a numerator or a denominator: with the exponent bound, the size
/// of every input number (and so the arithmetic it can cause) is bounded.
inline constexpr std::size_t kMaxDigits = 4096;

/// Parses SPEC section 1 syntax exactly: integers ("-3"), decimals ("0.966" = 966/1000),
/// scientific ("-2.5e-3" = -1/400) and fractions ("1/5", "-7/20"; non-zero denominator).
Q parse_rational(std::string_view text);
/// The same without throwing: out = the value of text, or false (out unspecified) if text is not such a number.
/// Numbers of up to 18 digits are read in machine words, without GMP temporaries.
bool parse_rational_into(std::string_view text, Q& out);

/// Lowest terms: "-7/20", "3", "0".
std::string to_string(const Q& x);
/// True if text is what to_string gives for its value: "0", or -?[1-9][0-9]* with an optional /[1-9][0-9]* whose
/// denominator is above 1 and prime to the numerator. Decided in machine words up to 18 digits a part; longer text
/// answers false (parse and print it instead).
bool is_lowest_terms_text(std::string_view text);

/// The primitive integer vector with the same direction as v (integers, gcd 1); zero stays zero.
std::vector<Z> primitive(const std::vector<Q>& v);
std::vector<Z> primitive(const Vec<Q>& v);

}  // namespace contactcert::exact
