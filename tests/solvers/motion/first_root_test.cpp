#include "solvers/motion/first_root.h"

#include <gtest/gtest.h>

namespace contactcert::solvers::motion {
namespace {

const auto always = [](const Q&) { return true; };

TEST(FirstGapRoot, LinearRootIsExact) {
  // 1 - 3 tau: closes at 1/3.
  const auto r = first_gap_root<Q>({Q(1), Q(-3)}, Q(1), always);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->exact);
  EXPECT_EQ(r->tau, Q(1, 3));
  EXPECT_FALSE(first_gap_root<Q>({Q(1), Q(-3)}, Q(1, 4), always));  // not within H
  EXPECT_FALSE(first_gap_root<Q>({Q(1), Q(3)}, Q(1), always));      // opening
}

TEST(FirstGapRoot, QuadraticRationalAndIrrationalRoots) {
  // (tau - 2/7)(tau - 5/7) = tau^2 - tau + 10/49: first root 2/7, exact.
  const auto r = first_gap_root<Q>({Q(10, 49), Q(-1), Q(1)}, Q(1), always);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->exact);
  EXPECT_EQ(r->tau, Q(2, 7));
  // Reject the first root (e.g. off the edge's segment): the second one.
  const auto second = first_gap_root<Q>({Q(10, 49), Q(-1), Q(1)}, Q(1), [](const Q& t) { return t > Q(1, 2); });
  ASSERT_TRUE(second);
  EXPECT_EQ(second->tau, Q(5, 7));
  // tau^2 - 2 tau + 1/2: root 1 - 1/sqrt(2), irrational: a time just before it, the gap still > 0.
  const std::vector<Q> g{Q(1, 2), Q(-2), Q(1)};
  const auto irr = first_gap_root<Q>(g, Q(1), always);
  ASSERT_TRUE(irr);
  EXPECT_FALSE(irr->exact);
  const Q gap = g[0] + g[1] * irr->tau + g[2] * irr->tau * irr->tau;
  EXPECT_GT(gap, 0);
  EXPECT_LT(gap, Q(1, 1000000000));
  // A double root (grazing): (tau - 1/3)^2 touches at 1/3.
  const auto graze = first_gap_root<Q>({Q(1, 9), Q(-2, 3), Q(1)}, Q(1), always);
  ASSERT_TRUE(graze);
  EXPECT_TRUE(graze->exact);
  EXPECT_EQ(graze->tau, Q(1, 3));
}

TEST(FirstGapRoot, CubicRationalRoot) {
  // (1 - 3 tau)(1 + tau^2) = 1 - 3 tau + tau^2 - 3 tau^3: the simplest rational of the bracket is the root.
  const auto r = first_gap_root<Q>({Q(1), Q(-3), Q(1), Q(-3)}, Q(1), always);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->exact);
  EXPECT_EQ(r->tau, Q(1, 3));
}

TEST(SimplestBetween, SmallestDenominator) {
  EXPECT_EQ(simplest_between(Q(3, 10), Q(4, 10)), Q(1, 3));
  EXPECT_EQ(simplest_between(Q(0), Q(1, 5)), Q(1, 6));
  EXPECT_EQ(simplest_between(Q(2), Q(7, 2)), Q(3));
}

}  // namespace
}  // namespace contactcert::solvers::motion
