#include "exact/rational_text.h"

#include <cctype>
#include <charconv>
#include <cstdint>
#include <iterator>
#include <limits>
#include <numeric>

namespace contactcert::exact {
namespace {

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

// Splits an optional leading sign.
bool take_sign(std::string_view& s) {
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) {
    bool negative = s.front() == '-';
    s.remove_prefix(1);
    return negative;
  }
  return false;
}

Z pow10(long e) {
  Z r = 1;
  Z ten = 10;
  // binary powering keeps big exponents cheap
  while (e > 0) {
    if (e & 1) r *= ten;
    ten *= ten;
    e >>= 1;
  }
  return r;
}

[[noreturn]] void bad(std::string_view text, const char* why) {
  throw NumberSyntaxError("\"" + std::string(text.substr(0, 40)) + (text.size() > 40 ? "..." : "") +
                          "\" is not an exact number (" + why + "; expected e.g. 3, -0.966, 2.5e-3 or 1/5)");
}

/// Digits that fit an unsigned 64-bit integer however they read (10^18 - 1 at most).
constexpr std::size_t kWordDigits = 18;

std::uint64_t word_of(std::string_view digits) {
  std::uint64_t v = 0;
  std::from_chars(digits.data(), digits.data() + digits.size(), v);
  return v;
}

std::uint64_t pow10_word(long e) {
  std::uint64_t p = 1;
  while (e-- > 0) p *= 10;
  return p;
}

/// Decimal digits without a leading zero that fit one machine word.
bool word_digits(std::string_view s) {
  return !s.empty() && s.size() <= kWordDigits && s.front() != '0' && all_digits(s);
}

/// out = (negative ? -n : n) / d in lowest terms; n < 2^63, 0 < d.
void set_ratio(bool negative, std::uint64_t n, std::uint64_t d, Q& out) {
  const std::uint64_t g = std::gcd(n, d);
  const auto num = static_cast<long>(n / g);
  mpq_set_si(out.get_mpq_t(), negative ? -num : num, d / g);
}

const char* parse_integer_ratio(std::string_view s, Q& out) {
  size_t slash = s.find('/');
  std::string_view num = s.substr(0, slash), den = s.substr(slash + 1);
  bool neg = take_sign(num);
  bool neg_den = take_sign(den);
  if (!all_digits(num) || !all_digits(den)) return "a fraction needs integer numerator and denominator";
  if (num.size() > kMaxDigits || den.size() > kMaxDigits) return "more than 4096 digits";
  if (num.size() <= kWordDigits && den.size() <= kWordDigits) {  // in machine words, no GMP temporaries
    const std::uint64_t n = word_of(num), d = word_of(den);
    if (d == 0) return "zero denominator";
    set_ratio(neg != neg_den, n, d, out);
    return nullptr;
  }
  Q q{Z(std::string(num), 10), Z(std::string(den), 10)};
  if (q.get_den() == 0) return "zero denominator";
  q.canonicalize();
  out = (neg != neg_den) ? Q(-q) : q;
  return nullptr;
}

/// Why text is not an exact number, or nullptr with its value in out.
const char* parse_into(std::string_view text, Q& out) {
  std::string_view s = text;
  if (s.empty()) return "empty";
  if (s.find('/') != std::string_view::npos) return parse_integer_ratio(s, out);

  bool negative = take_sign(s);
  long exponent = 0;
  size_t e = s.find_first_of("eE");
  if (e != std::string_view::npos) {
    std::string_view es = s.substr(e + 1);
    bool eneg = take_sign(es);
    if (!all_digits(es)) return "malformed exponent";
    long v = 0;
    if (es.size() > 9 || (std::from_chars(es.data(), es.data() + es.size(), v), v > kMaxDecimalExponent))
      return "exponent out of range (at most 4096 in absolute value)";
    exponent = eneg ? -v : v;
    s = s.substr(0, e);
  }
  std::string_view int_part = s, frac_part;
  size_t dot = s.find('.');
  if (dot != std::string_view::npos) {
    int_part = s.substr(0, dot);
    frac_part = s.substr(dot + 1);
  }
  if (int_part.empty() && frac_part.empty()) return "no digits";
  if ((!int_part.empty() && !all_digits(int_part)) || (!frac_part.empty() && !all_digits(frac_part)))
    return "unexpected character";
  if (int_part.size() + frac_part.size() > kMaxDigits) return "more than 4096 digits";
  exponent -= static_cast<long>(frac_part.size());
  if (int_part.size() + frac_part.size() <= kWordDigits && exponent >= -static_cast<long>(kWordDigits) &&
      exponent <= static_cast<long>(kWordDigits)) {  // mantissa 10^exponent in machine words, if it fits
    const std::uint64_t m = word_of(int_part) * pow10_word(static_cast<long>(frac_part.size())) + word_of(frac_part);
    if (exponent < 0) {
      set_ratio(negative, m, pow10_word(-exponent), out);
      return nullptr;
    }
    const std::uint64_t scale = pow10_word(exponent);
    if (m <= static_cast<std::uint64_t>(std::numeric_limits<long>::max()) / scale) {
      set_ratio(negative, m * scale, 1, out);
      return nullptr;
    }
  }
  std::string digits = std::string(int_part) + std::string(frac_part);
  Z mantissa(digits, 10);
  if (negative) mantissa = -mantissa;
  if (exponent >= 0) {
    out = Q(Z(mantissa * pow10(exponent)));
    return nullptr;
  }
  out = Q{mantissa, pow10(-exponent)};
  out.canonicalize();
  return nullptr;
}

}  // namespace

bool parse_rational_into(std::string_view text, Q& out) { return parse_into(text, out) == nullptr; }

Q parse_rational(std::string_view text) {
  Q q;
  if (const char* why = parse_into(text, q)) bad(text, why);
  return q;
}

bool is_lowest_terms_text(std::string_view text) {
  if (text == "0") return true;
  if (!text.empty() && text.front() == '-') text.remove_prefix(1);
  const std::size_t slash = text.find('/');
  const std::string_view num = text.substr(0, slash);
  if (!word_digits(num)) return false;
  if (slash == std::string_view::npos) return true;
  const std::string_view den = text.substr(slash + 1);
  if (!word_digits(den)) return false;
  const std::uint64_t d = word_of(den);
  return d > 1 && std::gcd(word_of(num), d) == 1;
}

std::string to_string(const Q& x) {
  const mpz_srcptr n = mpq_numref(x.get_mpq_t()), d = mpq_denref(x.get_mpq_t());
  if (mpz_size(n) > 1 || mpz_size(d) > 1) return x.get_str();  // GMP prints canonical "n/d", or "n" when d = 1
  // One limb each (most numbers met): the same text by to_chars, without GMP's conversion buffers.
  char text[2 * std::numeric_limits<mp_limb_t>::digits10 + 4];
  char* end = text;
  if (mpz_sgn(n) < 0) *end++ = '-';
  end = std::to_chars(end, std::end(text), mpz_getlimbn(n, 0)).ptr;
  if (mpz_getlimbn(d, 0) != 1) {
    *end++ = '/';
    end = std::to_chars(end, std::end(text), mpz_getlimbn(d, 0)).ptr;
  }
  return std::string(text, end);
}

std::vector<Z> primitive(const std::vector<Q>& v) {
  // Multiply by the lcm of the denominators, then divide by the gcd of the numerators.
  Z l = 1;
  for (const Q& x : v) l = lcm(l, x.get_den());
  std::vector<Z> out;
  out.reserve(v.size());
  Z g = 0;
  for (const Q& x : v) {
    out.push_back(Z(x.get_num() * (l / x.get_den())));
    g = gcd(g, out.back());
  }
  if (g > 1)
    for (Z& z : out) z /= g;
  return out;
}

std::vector<Z> primitive(const Vec<Q>& v) { return primitive(std::vector<Q>(v.data(), v.data() + v.size())); }

}  // namespace contactcert::exact
