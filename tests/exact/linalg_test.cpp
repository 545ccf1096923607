#include "exact/linalg.h"

#include <gtest/gtest.h>

#include <random>

namespace contactcert::exact {
namespace {

Mat<Q> random_rank_matrix(std::mt19937_64& rng, int m, int n, int r) {
  std::uniform_int_distribution<int> d(-5, 5);
  Mat<Q> L(m, r), R(r, n);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < r; ++j) L(i, j) = d(rng);
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < n; ++j) R(i, j) = d(rng);
  Mat<Q> A(m, n);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      Q s = 0;
      for (int k = 0; k < r; ++k) s += L(i, k) * R(k, j);
      A(i, j) = s;
    }
  return A;
}

TEST(Linalg, NullSpacesAreExactAndOfTheRightDimension) {
  std::mt19937_64 rng(7);
  for (int t = 0; t < 200; ++t) {
    int m = 1 + t % 6, n = 1 + (t / 6) % 7, r = std::min(m, n) - (t % 3 == 0 ? 1 : 0);
    if (r < 0) r = 0;
    Mat<Q> A = random_rank_matrix(rng, m, n, r);
    Eigen::Index rk = rank<Q>(A);
    EXPECT_LE(rk, r);
    Mat<Q> N = null_space<Q>(A);
    EXPECT_EQ(N.cols(), n - rk);
    EXPECT_EQ(rank<Q>(N), N.cols());
    Mat<Q> AN = A * N;
    for (Eigen::Index i = 0; i < AN.size(); ++i) EXPECT_EQ(AN(i), 0);
    Mat<Q> Z = left_null_space<Q>(A);
    EXPECT_EQ(Z.rows(), m - rk);
    Mat<Q> ZA = Z * A;
    for (Eigen::Index i = 0; i < ZA.size(); ++i) EXPECT_EQ(ZA(i), 0);
  }
}

TEST(Linalg, SolveAndInverse) {
  Mat<Q> A(3, 3);
  A << 2, 1, 0, 1, 3, 1, 0, 1, 4;
  Vec<Q> b(3);
  b << 1, 2, 3;
  auto x = solve<Q>(A, b);
  ASSERT_TRUE(x);
  Vec<Q> r = A * *x - b;
  for (Eigen::Index i = 0; i < 3; ++i) EXPECT_EQ(r(i), 0);
  auto Ai = inverse<Q>(A);
  ASSERT_TRUE(Ai);
  Mat<Q> I = A * *Ai;
  for (Eigen::Index i = 0; i < 3; ++i)
    for (Eigen::Index j = 0; j < 3; ++j) EXPECT_EQ(I(i, j), i == j ? 1 : 0);
  EXPECT_EQ((*Ai)(0, 0), Q(11) / 18);

  Mat<Q> S(2, 2);
  S << 1, 2, 2, 4;
  EXPECT_FALSE(inverse<Q>(S));
  Vec<Q> c(2);
  c << 1, 3;
  EXPECT_FALSE(solve<Q>(S, c));  // inconsistent
  c << 1, 2;
  EXPECT_TRUE(solve<Q>(S, c));
}

TEST(Linalg, FloatPathAgreesOnWellConditionedData) {
  Mat<double> A(3, 4);
  A << 1, 2, 3, 4, 2, 4, 6, 8, 1, 0, 1, 0;
  EXPECT_EQ(rank<double>(A), 2);
  Mat<double> N = null_space<double>(A);
  EXPECT_EQ(N.cols(), 2);
  EXPECT_LT((A * N).norm(), 1e-12);
}

}  // namespace
}  // namespace contactcert::exact
