#include "exact/tangent_cone.h"

#include <gtest/gtest.h>

#include <vector>

namespace contactcert::exact {
namespace {

template <class T>
std::vector<std::vector<T>> rows_of(const std::vector<Vec<T>>& rays) {
  std::vector<std::vector<T>> out;
  for (const Vec<T>& r : rays) out.emplace_back(r.data(), r.data() + r.size());
  return out;
}

// {w >= 0 : w_1 - w_2 <= 0, 2 w_1 - w_3 <= 0} in R^3. Motzkin's iteration on the orthant's rays e_1, e_2, e_3:
// the first row keeps e_2, e_3 and adds e_1 + e_2 (from e_1 and e_2); the second keeps e_2, e_3 and adds
// (1, 1, 2) (from e_1 + e_2 and e_3). The rays come in that order, first entry 1, in every number type.
TEST(OrthantConeRays, RaysInTheOrderOfTheIterationOnTheOrthant) {
  Mat<Q> G(2, 3);
  G << 1, -1, 0, 2, 0, -1;
  const std::optional<std::vector<Vec<Q>>> exact_rays = orthant_cone_rays<Q>(G, 100);
  ASSERT_TRUE(exact_rays.has_value());
  EXPECT_EQ(rows_of(*exact_rays), (std::vector<std::vector<Q>>{{0, 1, 0}, {0, 0, 1}, {1, 1, 2}}));
  Mat<double> Gd(2, 3);
  Gd << 1, -1, 0, 2, 0, -1;
  const std::optional<std::vector<Vec<double>>> float_rays = orthant_cone_rays<double>(Gd, 100);
  ASSERT_TRUE(float_rays.has_value());
  EXPECT_EQ(rows_of(*float_rays), (std::vector<std::vector<double>>{{0, 1, 0}, {0, 0, 1}, {1, 1, 2}}));
  // Rational rows: the ray (1/2, 1/2, 1) is scaled to its first entry 1 as well.
  Mat<Q> H = G;
  H.row(1) /= Q(7);
  EXPECT_EQ(rows_of(orthant_cone_rays<Q>(H, 100).value()), rows_of(*exact_rays));
}

// The budget counts the rays held at once: the orthant's three and one more do not fit in three.
TEST(OrthantConeRays, BudgetRunOutIsNoRays) {
  Mat<Q> G(1, 3);
  G << 1, -1, 0;
  EXPECT_FALSE(orthant_cone_rays<Q>(G, 3).has_value());
  EXPECT_TRUE(orthant_cone_rays<Q>(G, 4).has_value());
}

}  // namespace
}  // namespace contactcert::exact
