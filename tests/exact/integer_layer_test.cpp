// The integer layer of the exact checks: rational reconstruction (continued fractions under a denominator
// bound), scaling rows to integers over their common denominators, and fraction-free elimination with the
// restart from 128-bit integers into GMP.
#include <gtest/gtest.h>

#include <cmath>

#include "exact/integer_system.h"
#include "exact/rational_reconstruction.h"

namespace contactcert::exact {
namespace {

Q q(const char* s) { return Q(s); }

void expect_fraction(double v, std::int64_t num, std::int64_t den) {
  const std::optional<Fraction> f = reconstruct(v);
  ASSERT_TRUE(f.has_value()) << v;
  EXPECT_EQ(f->num, num) << v;
  EXPECT_EQ(f->den, den) << v;
}

TEST(Reconstruction, SimpleFractionsExactly) {
  expect_fraction(0.1, 1, 10);
  expect_fraction(-1.0 / 3.0, -1, 3);
  expect_fraction(8.0 / 5.0 + 1e-15, 8, 5);
  expect_fraction(-7.0, -7, 1);
  expect_fraction(0.5 + std::ldexp(1.0, -40), 1, 2);
  // Below 1/B every convergent but the first (-1 for a negative value) is 0.
  expect_fraction(1e-12, 0, 1);
  expect_fraction(-1e-12, 0, 1);
  expect_fraction(0.0, 0, 1);
  // Below 2^-9 a double is N / 2^k with k > 62: the continued fraction runs in 128 bits.
  expect_fraction(1.0 / 3000.0, 1, 3000);
  expect_fraction(-3.0 / 7000.0, -3, 7000);
  expect_fraction(1e-6, 1, 1000000);
}

// The first convergent of pi within max(1, |v|) / 2^30 = 2.9e-9: 355/113 is 2.7e-7 away, 103993/33102 5.8e-10.
TEST(Reconstruction, FirstConvergentWithinTheBound) { expect_fraction(M_PI, 103993, 33102); }

TEST(Reconstruction, RefusesWhatItCannotBound) {
  EXPECT_FALSE(reconstruct(std::nan("")).has_value());
  EXPECT_FALSE(reconstruct(INFINITY).has_value());
  EXPECT_FALSE(reconstruct(1e16).has_value());  // >= 2^50
  // Within 2^-30 of 0 (below 1/B): 0, not 1/(2^31 + 1) with its denominator beyond B.
  expect_fraction(1.0 / 2147483649.0, 0, 1);
}

TEST(Reconstruction, VectorOverItsCommonDenominator) {
  std::vector<Int128> X;
  Int128 D;
  ASSERT_TRUE(reconstruct_vector<Int128>({0.5, 1.0 / 3.0, -0.25}, X, D));
  EXPECT_TRUE(D == 12);
  EXPECT_TRUE(X[0] == 6 && X[1] == 4 && X[2] == -3);
  std::vector<Z> XZ;
  Z DZ;
  ASSERT_TRUE(reconstruct_vector<Z>({0.5, 1.0 / 3.0, -0.25}, XZ, DZ));
  EXPECT_EQ(DZ, 12);
  EXPECT_EQ(XZ, (std::vector<Z>{6, 4, -3}));
  EXPECT_FALSE(reconstruct_vector<Z>({0.5, std::nan("")}, XZ, DZ));
}

TEST(Scaling, RowsOverTheLcmOfTheirDenominators) {
  Mat<Q> A(2, 2);
  A << q("1/2"), q("1/3"), 2, 4;
  Vec<Q> b(2);
  b << 1, q("6/7");
  const IntegerSystem<Z> s = integer_system<Z>(rational_rows(A, b));
  EXPECT_EQ(s.row_scale, (std::vector<Z>{6, 7}));
  EXPECT_EQ(s.A.rows(), 2);
  EXPECT_EQ(s.A.cols(), 2);
  EXPECT_TRUE(s.A(0, 0) == 3 && s.A(0, 1) == 2 && s.A(1, 0) == 14 && s.A(1, 1) == 28);
  EXPECT_EQ(s.b, (std::vector<Z>{6, 6}));
  const IntegerSystem<Int128> c = integer_system<Int128>(rational_rows(Mat<Q>(A.col(1)), b));  // column 1 alone
  EXPECT_TRUE(c.row_scale[0] == 3 && c.A(0, 0) == 1 && c.b[0] == 3);
  LpProblem<Q> lp{A, b, Vec<Q>(2), {}};
  lp.c << q("1/4"), q("-1/6");
  const std::optional<IntegerLp> ilp = integer_lp(lp);
  ASSERT_TRUE(ilp.has_value());
  EXPECT_TRUE(ilp->A(0, 0) == 3 && ilp->A(0, 1) == 2 && ilp->A(1, 0) == 14 && ilp->A(1, 1) == 28);
  EXPECT_EQ(ilp->c, (std::vector<std::int64_t>{3, -2}));
  EXPECT_EQ(ilp->objective_scale, 12);
  lp.A(0, 0) = Q(Z(1) << 70);  // does not fit in 64 bits
  EXPECT_FALSE(integer_lp(lp).has_value());
}

// A 3 x 3 system with entries near 2^62: its 3 x 3 minors need about 186 bits, so the 128-bit elimination
// overflows and with_exact_ring restarts in GMP, with the same (exact) answer.
TEST(Bareiss, OverflowRestartsInGmp) {
  const Z big = Z(1) << 62;
  Mat<Q> A(3, 3);
  A << Q(big + 1), Q(big - 3), Q(big + 7), Q(big - 11), Q(big + 13), Q(big - 17), Q(big + 19), Q(big - 23), Q(big + 29);
  Vec<Q> x(3);
  x << 1, -2, q("3/5");
  const Vec<Q> b = A * x;
  const IntegerSystem<Int128> narrow = integer_system<Int128>(rational_rows(A, b));
  EXPECT_THROW(unique_solution(narrow), RingOverflow);
  int rings = 0;
  const std::optional<Vec<Q>> y = with_exact_ring<Q, Int128>([&]<class R>() {
    ++rings;
    return unique_solution(integer_system<R>(rational_rows(A, b)));
  });
  EXPECT_EQ(rings, 2);
  ASSERT_TRUE(y.has_value());
  EXPECT_EQ(*y, x);
}

TEST(Bareiss, RankAndConsistency) {
  Mat<Q> A(3, 2);
  A << 1, 2, 2, 4, 1, 0;
  Vec<Q> b(3);
  b << 3, 6, 1;
  const std::optional<Vec<Q>> x = unique_solution(integer_system<Int128>(rational_rows(A, b)));
  ASSERT_TRUE(x.has_value());
  EXPECT_EQ((*x)(0), 1);
  EXPECT_EQ((*x)(1), 1);
  b(1) = 7;  // inconsistent
  EXPECT_FALSE(unique_solution(integer_system<Z>(rational_rows(A, b))).has_value());
  A.col(1) = 2 * A.col(0);  // rank 1
  EXPECT_FALSE(unique_solution(integer_system<Int128>(rational_rows(A, b))).has_value());
}

}  // namespace
}  // namespace contactcert::exact
