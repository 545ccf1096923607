// Dixon's p-adic lifting (exact/padic_solve.h) against fraction-free elimination (IntMatrix::solve) on seeded random
// square integer systems, sparse and dense, with right-hand sides of hundreds of bits; singular systems give nullopt.
#include "exact/padic_solve.h"

#include <gtest/gtest.h>

#include <random>

namespace contactcert::exact {
namespace {

using Index = Eigen::Index;

/// A random k x (k + 1) matrix [A | b]: A with about `density` of its entries in -9..9 plus a non-zero diagonal (so
/// usually regular), b with entries of up to `rhs_bits` bits.
IntMatrix<Z> random_system(std::mt19937_64& rng, Index k, double density, int rhs_bits) {
  std::uniform_int_distribution<int> entry(-9, 9), digit(0, 1 << 30);
  std::bernoulli_distribution take(density);
  IntMatrix<Z> M(k, k + 1);
  for (Index i = 0; i < k; ++i) {
    for (Index j = 0; j < k; ++j)
      if (i == j || take(rng)) M(i, j) = entry(rng) == 0 ? 1 : entry(rng);
    Z b = entry(rng);
    for (int bits = 0; bits < rhs_bits; bits += 30) b = b * (1 << 30) + digit(rng);
    M(i, k) = b;
  }
  return M;
}

/// u_j = U_j / D as fractions.
std::vector<Q> fractions(const std::vector<Z>& U, const Z& D) {
  std::vector<Q> u;
  for (const Z& x : U) {
    u.emplace_back(x, D);
    u.back().canonicalize();
  }
  return u;
}

TEST(PadicSolve, AgreesWithFractionFreeElimination) {
  std::mt19937_64 rng(15);
  int solved = 0;
  for (int draw = 0; draw < 40; ++draw) {
    const Index k = 16 + draw % 25;
    const IntMatrix<Z> M = random_system(rng, k, draw % 2 ? 0.1 : 0.6, 30 * (draw % 8));
    IntMatrix<Z> E = M;
    std::vector<Z> N(static_cast<std::size_t>(k));
    Z d;
    const SolutionKind kind = E.solve(N.data(), d);
    const std::optional<LiftedSolution> s = padic_solve(M);
    ASSERT_EQ(s.has_value(), kind == SolutionKind::kUnique) << "draw " << draw;
    if (!s) continue;
    ++solved;
    EXPECT_GT(sgn(s->D), 0);
    EXPECT_EQ(fractions(s->U, s->D), fractions(N, d)) << "draw " << draw;
    Z g = s->D;  // over the least common denominator
    for (const Z& x : s->U) g = gcd(g, x);
    EXPECT_EQ(g, 1) << "draw " << draw;
  }
  EXPECT_GE(solved, 30);  // seed 15: 34 regular, 6 singular
}

TEST(PadicSolve, SingularSystemsAndOnesSingularModuloThePrime) {
  std::mt19937_64 rng(16);
  IntMatrix<Z> M = random_system(rng, 20, 0.3, 60);
  // Row 5 = row 3 + 2 row 7 (and b likewise): singular over Q, so modulo every prime.
  for (Index j = 0; j <= 20; ++j) M(5, j) = M(3, j) + 2 * M(7, j);
  EXPECT_FALSE(padic_solve(M));
  // det = 2^31 - 1 (the first prime): [[2^31 - 1, 0], [0, 1]] padded with the identity; x = (1, 3, 1, ..., 1).
  IntMatrix<Z> P(18, 19);
  for (Index i = 0; i < 18; ++i) P(i, i) = P(i, 18) = 1;
  P(0, 0) = P(0, 18) = Z(2147483647);
  P(1, 18) = 3;
  const std::optional<LiftedSolution> s = padic_solve(P);
  ASSERT_TRUE(s);
  std::vector<Q> want(18, Q(1));
  want[1] = 3;
  EXPECT_EQ(fractions(s->U, s->D), want);
}

TEST(PadicSolve, SparseSquareSolveLiftedIsTheSameSolution) {
  std::mt19937_64 rng(17);
  for (int draw = 0; draw < 10; ++draw) {
    const Index k = 20 + 4 * draw;
    const IntMatrix<Z> M = random_system(rng, k, 0.15, 90);
    std::vector<SparseEquation<Z>> eqs(static_cast<std::size_t>(k));
    for (Index i = 0; i < k; ++i) {
      for (Index j = 0; j < k; ++j)
        if (sgn(M(i, j)) != 0) eqs[static_cast<std::size_t>(i)].terms.emplace_back(j, M(i, j));
      eqs[static_cast<std::size_t>(i)].rhs = M(i, k);
    }
    std::vector<Z> U, V;
    Z D, E;
    const SolutionKind a = solve_sparse_square(eqs, k, U, D), b = solve_sparse_square(eqs, k, V, E, CoreSolve::kLifted);
    ASSERT_EQ(a, b) << "draw " << draw;
    if (a == SolutionKind::kUnique) {
      EXPECT_EQ(fractions(U, D), fractions(V, E)) << "draw " << draw;
    }
  }
}

}  // namespace
}  // namespace contactcert::exact
