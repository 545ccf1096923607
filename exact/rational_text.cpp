#include "exact/rational_text.h"

#include <cctype>
#include <charconv>

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
                          "\" is not an exact number (" + why +
                          "; expected e.g. 3, -0.966, 2.5e-3 or 1/5)");
}

Q parse_integer_ratio(std::string_view text, std::string_view s) {
  size_t slash = s.find('/');
  std::string_view num = s.substr(0, slash), den = s.substr(slash + 1);
  bool neg = take_sign(num);
  bool neg_den = take_sign(den);
  if (!all_digits(num) || !all_digits(den)) bad(text, "a fraction needs integer numerator and denominator");
  if (num.size() > kMaxDigits || den.size() > kMaxDigits) bad(text, "more than 4096 digits");
  Q q{Z(std::string(num), 10), Z(std::string(den), 10)};
  if (q.get_den() == 0) bad(text, "zero denominator");
  q.canonicalize();
  return (neg != neg_den) ? Q(-q) : q;
}

}  // namespace

Q parse_rational(std::string_view text) {
  std::string_view s = text;
  if (s.empty()) bad(text, "empty");
  if (s.find('/') != std::string_view::npos) return parse_integer_ratio(text, s);

  bool negative = take_sign(s);
  long exponent = 0;
  size_t e = s.find_first_of("eE");
  if (e != std::string_view::npos) {
    std::string_view es = s.substr(e + 1);
    bool eneg = take_sign(es);
    if (!all_digits(es)) bad(text, "malformed exponent");
    long v = 0;
    if (es.size() > 9 || (std::from_chars(es.data(), es.data() + es.size(), v), v > kMaxDecimalExponent))
      bad(text, "exponent out of range (at most 4096 in absolute value)");
    exponent = eneg ? -v : v;
    s = s.substr(0, e);
  }
  std::string_view int_part = s, frac_part;
  size_t dot = s.find('.');
  if (dot != std::string_view::npos) {
    int_part = s.substr(0, dot);
    frac_part = s.substr(dot + 1);
  }
  if (int_part.empty() && frac_part.empty()) bad(text, "no digits");
  if ((!int_part.empty() && !all_digits(int_part)) || (!frac_part.empty() && !all_digits(frac_part)))
    bad(text, "unexpected character");
  if (int_part.size() + frac_part.size() > kMaxDigits) bad(text, "more than 4096 digits");
  exponent -= static_cast<long>(frac_part.size());
  std::string digits = std::string(int_part) + std::string(frac_part);
  Z mantissa(digits, 10);
  if (negative) mantissa = -mantissa;
  if (exponent >= 0) return Q(Z(mantissa * pow10(exponent)));
  Q q{mantissa, pow10(-exponent)};
  q.canonicalize();
  return q;
}

std::string to_string(const Q& x) {
  return x.get_str();  // GMP prints canonical "n/d", or "n" when d = 1
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
