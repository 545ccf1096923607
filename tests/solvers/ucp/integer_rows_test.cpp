#include "solvers/ucp/integer_rows.h"

#include <gtest/gtest.h>

namespace contactcert::solvers::ucp {
namespace {

using exact::Mat;
using exact::Q;
using exact::Z;

// An 80-bit denominator and numerator, as a pose reached by Cayley steps carries: entries scaled by them need more
// than 127 bits in an elimination, so the rows are computed in Z without the Int128 attempt.
const Q kBig(Z("1208925819614629174706189") /* 2^80 + 13 */, Z("1208925819614629174706176") /* 2^80 */);

// The left null space does not change when a column of P is scaled by a non-zero rational (z^T P c = 0 iff z^T P =
// 0), and the rows are primitive: the rows of a small-entry P (in Int128) equal those of P with 80-bit columns (in Z).
TEST(IntegerRows, LeftNullRowsDoNotDependOnTheColumnsScale) {
  Mat<Q> P(4, 3);
  P << 0, 1, Q(-3, 2), 0, 1, Q(5, 2), 1, 0, -1, 1, 0, 2;  // W^T of two contacts on a floor (normal rows, tangent rows)
  Mat<Q> big = P;
  for (Eigen::Index j = 0; j < 3; ++j) big.col(j) *= kBig * Q(static_cast<long>(j) + 2, 7);
  // Small entries try Int128; the 80-bit columns go straight to Z (three pivots of 80 bits each).
  EXPECT_LE(elimination_bits(P, false), 127u);
  EXPECT_GT(elimination_bits(big, false), 3 * 79u);
  EXPECT_GT(elimination_bits(big, true), 127u);
  const SparseRows a = left_null_rows(P), b = left_null_rows(big);
  ASSERT_EQ(a.rows(), 1);
  EXPECT_EQ(a.dense(), b.dense());
  for (Eigen::Index j = 0; j < 3; ++j) {  // z^T P = 0
    Q s(0);
    for (Eigen::Index t = a.begin(0); t < a.end(0); ++t) s += Q(a.value(t)) * P(a.col(t), j);
    EXPECT_EQ(s, 0);
  }
}

// primitive_integers is the same vector for v and for c v (c > 0), whatever ring computed it.
TEST(IntegerRows, PrimitiveIntegersDoNotDependOnTheScale) {
  const std::vector<Q> v = {Q(3, 4), Q(-5, 6), Q(0), Q(7)};
  std::vector<Q> w;
  for (const Q& x : v) w.push_back(x * kBig * kBig);
  std::vector<const Q*> pv, pw;
  for (std::size_t i = 0; i < v.size(); ++i) pv.push_back(&v[i]), pw.push_back(&w[i]);
  const std::vector<Z> expected = {Z(9), Z(-10), Z(0), Z(84)};
  EXPECT_EQ(primitive_integers(pv), expected);
  EXPECT_EQ(primitive_integers(pw), expected);
}

}  // namespace
}  // namespace contactcert::solvers::ucp
