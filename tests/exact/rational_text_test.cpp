#include "exact/rational_text.h"

#include <gtest/gtest.h>

namespace contactcert::exact {
namespace {

Q q(long n, long d = 1) { return Q(n) / Q(d); }

TEST(ParseRational, EveryFormOfSpecSection1) {
  EXPECT_EQ(parse_rational("0.966"), q(966, 1000));
  EXPECT_EQ(parse_rational("0.966"), q(483, 500));
  EXPECT_EQ(parse_rational("1/5"), q(1, 5));
  EXPECT_EQ(parse_rational("-2.5e-3"), q(-1, 400));
  EXPECT_EQ(parse_rational("3"), q(3));
  EXPECT_EQ(parse_rational("-7/20"), q(-7, 20));
  EXPECT_EQ(parse_rational("+4"), q(4));
  EXPECT_EQ(parse_rational(".5"), q(1, 2));
  EXPECT_EQ(parse_rational("5."), q(5));
  EXPECT_EQ(parse_rational("1E2"), q(100));
  EXPECT_EQ(parse_rational("1e+2"), q(100));
  EXPECT_EQ(parse_rational("6/4"), q(3, 2));  // canonicalised
  EXPECT_EQ(parse_rational("3/-4"), q(-3, 4));
  EXPECT_EQ(parse_rational("-0"), q(0));
  EXPECT_EQ(parse_rational("0.1") * 10, q(1));  // no binary rounding
}

TEST(ParseRational, LongDigitStringsStayExact) {
  Q x = parse_rational("0.1000000000000000000000000000000000001");
  EXPECT_NE(x, q(1, 10));
  EXPECT_EQ(x - q(1, 10), Q(1) / Q(Z("10000000000000000000000000000000000000", 10)));
  EXPECT_EQ(parse_rational("123456789012345678901234567890"), Q(Z("123456789012345678901234567890", 10)));
}

TEST(ParseRational, RejectsMalformedNumbersWithAReason) {
  for (const char* bad :
       {"",     "abc", "1/0", "nan", "NaN", "inf", "-inf", "1e",    "1e+",     "--1",      "1.2.3",          "1/2/3",
        "0x10", "1,5", " 1",  "1 ",  ".",   "-",   "e5",   "1/2.5", "1e99999", "1e-99999", "1e1234567890123"}) {
    EXPECT_THROW(parse_rational(bad), NumberSyntaxError) << "input: '" << bad << "'";
  }
  try {
    parse_rational("1/0");
  } catch (const NumberSyntaxError& e) {
    EXPECT_NE(std::string(e.what()).find("zero denominator"), std::string::npos);
  }
}

// Up to 18 digits a number is read in machine words; a leading zero makes it 19 digits and sends it through GMP.
// Both readings must agree, at the edges of the fast path (18 digits, exponents +-18, 2^63) and beyond them.
TEST(ParseRational, MachineWordReadingAgreesWithGmp) {
  const std::vector<std::string> texts = {"999999999999999999",
                                          "-999999999999999999",
                                          "999999999999999999e0",
                                          "9999999999999999.99",
                                          "922337203685477580",
                                          "92233720368547758e1",
                                          "9223372036854775e3",
                                          "9223372036854776e3",
                                          "999999999999999999e1",
                                          "1e18",
                                          "1e-18",
                                          "-1e-18",
                                          "123456789.123456789",
                                          "0.000000000000000001",
                                          "5e-18",
                                          "25e-17",
                                          "999999999999999999/999999999999999998",
                                          "-120/-36",
                                          "0/7",
                                          "-0.0",
                                          "3.14159e2",
                                          "1000000000000000000",
                                          "-0/-5"};
  for (const std::string& t : texts) {
    const Q fast = parse_rational(t);
    // The same number with 19 leading zero digits (in the denominator too): 19 digits or more.
    const auto pad = [](const std::string& s, std::size_t from) {
      const std::size_t at = s.find_first_of("0123456789", from);
      return s.substr(0, at) + std::string(19, '0') + s.substr(at);
    };
    std::string slow = pad(t, 0);
    if (const std::size_t slash = slow.find('/'); slash != std::string::npos) slow = pad(slow, slash);
    EXPECT_EQ(fast, parse_rational(slow)) << t << " vs " << slow;
    Q into;
    EXPECT_TRUE(parse_rational_into(t, into));
    EXPECT_EQ(into, fast) << t;
  }
  Q unused;
  for (const char* bad : {"1/0", "x", "1e", "0/000000000000000000000"}) EXPECT_FALSE(parse_rational_into(bad, unused));
}

TEST(ToString, LowestTerms) {
  EXPECT_EQ(to_string(q(-7, 20)), "-7/20");
  EXPECT_EQ(to_string(q(6, 2)), "3");
  EXPECT_EQ(to_string(q(0)), "0");
  EXPECT_EQ(to_string(q(14, -40)), "-7/20");
  EXPECT_EQ(parse_rational(to_string(q(-355, 113))), q(-355, 113));
}

TEST(ToString, OneLimbTextAgreesWithGmp) {
  const Z limb_max("18446744073709551615", 10);  // 2^64 - 1, the largest one-limb value
  for (const Z& n : {Z(0), Z(1), Z(-1), Z(10), Z(-123456789), limb_max, Z(-limb_max), Z(limb_max + 1)})
    for (const Z& d : {Z(1), Z(2), Z(7), Z(1000), limb_max, Z(limb_max + 1)}) {
      Q x(n, d);
      x.canonicalize();
      EXPECT_EQ(to_string(x), x.get_str()) << x.get_str();
    }
}

TEST(ToString, LowestTermsTextIsRecognisedAsItsOwnCanonicalForm) {
  // is_lowest_terms_text(t) holds exactly when t is to_string of its value (up to 18 digits a part).
  for (const char* t : {"0", "3", "-3", "-7/20", "123456789012345678", "999999999999999989/999999999999999999"}) {
    EXPECT_TRUE(is_lowest_terms_text(t)) << t;
    EXPECT_EQ(to_string(parse_rational(t)), t);
  }
  for (const char* t :
       {"-0", "03", "+3", "6/4", "1/1", "2/-3", "-2/3/4", "1.5", "1e3", "", "-", "/2", "1234567890123456789"}) {
    EXPECT_FALSE(is_lowest_terms_text(t)) << t;
  }
}

TEST(Primitive, IntegerVectorWithGcdOne) {
  auto v = primitive(std::vector<Q>{q(1, 2), q(-3, 4), q(0)});
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0], 2);
  EXPECT_EQ(v[1], -3);
  EXPECT_EQ(v[2], 0);
  auto w = primitive(std::vector<Q>{q(6), q(9), q(-12)});
  EXPECT_EQ(w, (std::vector<Z>{2, 3, -4}));
  auto z = primitive(std::vector<Q>{q(0), q(0)});
  EXPECT_EQ(z, (std::vector<Z>{0, 0}));
}

}  // namespace
}  // namespace contactcert::exact
