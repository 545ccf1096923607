// Unreduced fractions: the values and signs of sums, differences, products and quotients without a gcd, the order by
// cross-multiplication, the one reduction; RationalVector's signs and entries read from its numerators.
#include "exact/unreduced.h"

#include <gtest/gtest.h>

#include "exact/rational_vector.h"

namespace contactcert::exact {
namespace {

Q value(const Unreduced& x) { return Q(x.n) / Q(x.d); }

TEST(Unreduced, FormulasHaveTheValueOverQ) {
  const Q a(3, 4), b(-5, 6), c(7, 4);
  const Unreduced ua = unreduced(a), ub = unreduced(b), uc = unreduced(c);
  EXPECT_EQ(value(ua + ub), a + b);
  EXPECT_EQ(value(ua - uc), a - c);  // same denominators: no product
  EXPECT_EQ((ua - uc).d, Z(4));
  EXPECT_EQ(value(-ua * ub), -a * b);
  EXPECT_EQ(value(ua / ub), a / b);
  EXPECT_EQ(value(ua / uc), a / c);  // same denominators: n_a / n_c
  EXPECT_GT(sgn((ua / ub).d), 0);    // the divisor's sign moves to the numerator
  EXPECT_EQ(sign(ua / ub), -1);
  EXPECT_EQ(sign(ua - ua), 0);
}

TEST(Unreduced, OrderAndReduction) {
  const Unreduced x{6, 8}, y{-2, 4};  // 3/4 and -1/2, unreduced
  EXPECT_TRUE(y < x);
  EXPECT_FALSE(x < y);
  EXPECT_FALSE(x < x);
  const Q r = reduced(x);
  EXPECT_EQ(r.get_num(), Z(3));
  EXPECT_EQ(r.get_den(), Z(4));
  EXPECT_EQ(reduced(0.25), 0.25);
  EXPECT_EQ(unreduced(0.5), 0.5);
}

TEST(RationalVector, SignFromNumerators) {
  Vec<Q> v(3);
  v << Q(-1, 3), Q(0), Q(5, 7);
  const RationalVector small(v);
  EXPECT_EQ(small.sign(0), -1);
  EXPECT_EQ(small.sign(1), 0);
  EXPECT_EQ(small.sign(2), 1);
  const Z num[2] = {Z(3), Z(-4)};
  const RationalVector wide(num, 2, Z(-5));  // negative denominator: the signs flip
  EXPECT_EQ(wide.sign(0), -1);
  EXPECT_EQ(wide.sign(1), 1);
}

TEST(RationalVector, EntryOverTheCommonDenominator) {
  Vec<Q> v(2);
  v << Q(1, 2), Q(1, 3);
  Z n, d;
  RationalVector(v).entry(0, n, d);  // 3 / 6
  EXPECT_EQ(n, Z(3));
  EXPECT_EQ(d, Z(6));
  const Z num[2] = {Z(4), Z(-6)};
  RationalVector(num, 2, Z(-8)).entry(1, n, d);  // 6 / 8
  EXPECT_EQ(n, Z(6));
  EXPECT_EQ(d, Z(8));
}

}  // namespace
}  // namespace contactcert::exact
