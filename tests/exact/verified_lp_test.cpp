#include "exact/verified_lp.h"

#include <gtest/gtest.h>

#include <random>

#include "exact/rounded_check.h"
#include "exact/simplex.h"
#include "exact/strict_feasibility.h"
#include "tests/exact/lp_expectations.h"
#include "tests/exact/random_lp.h"
#include "tests/reference/cdd_lp.h"

namespace contactcert::exact {
namespace {

// The verified path equals the exact simplex (status, value, valid certificates) on the random LPs of
// simplex_test, and the float basis usually checks out without exact pivots.
TEST(VerifiedLp, EqualsExactOnRandomLps) {
  std::mt19937_64 rng(20261123);
  int checked = 0;
  for (int t = 0; t < 1500; ++t) {
    const LpProblem<Q> p = testing::random_lp(rng);
    const LpResult<Q> e = solve_lp<Q>(p);
    const LpResult<Q> v = solve_lp_verified(p, testing::with_duals());
    testing::expect_certified_like(p, v, e, t);
    if (v.decided_by == DecidedBy::kFloatBasisCheckedExactly) {
      ++checked;
      EXPECT_EQ(v.pivots, 0);
    }
  }
  EXPECT_GT(checked, 1200);
}

// A rung below the last proposes a basis that must decide the LP with no exact pivot. Its basis at an unbounded
// edge does: min -x2 s.t. x1 - x2 = 1 is unbounded, the double rung's final basis is checked in Q and decides
// (status kUnbounded, the ray verified, no exact pivot) before the exact rung is reached.
TEST(VerifiedLp, UnboundedEdgeOfALowerRungBasisDecides) {
  LpProblem<Q> p;
  p.A = Mat<Q>(1, 2);
  p.A << 1, -1;
  p.b = Vec<Q>(1);
  p.b << 1;
  p.c = Vec<Q>(2);
  p.c << 0, -1;
  const std::vector<Rung> ladder{{Rung::Kind::kDouble, 0}, {Rung::Kind::kInterval, 0}, {Rung::Kind::kExact, 0}};
  const LpResult<Q> r = solve_lp_ladder(p, ladder);
  ASSERT_EQ(r.status, LpStatus::kUnbounded);
  EXPECT_EQ(r.decided_by, DecidedBy::kFloatBasisCheckedExactly);
  EXPECT_EQ(r.proposed_by, (Rung{Rung::Kind::kDouble, 0}));
  EXPECT_EQ(r.pivots, 0);
  EXPECT_TRUE(verify_ray(p, r.ray));
}

// min x1 + (1 - 10^-20) x2 s.t. x1 + x2 = 1: the costs are equal in double (and too big to scale to 64-bit
// integers), so the float simplex stops at x1 = 1; the exact check rejects that basis and the exact simplex
// moves to x2 = 1.
TEST(VerifiedLp, FloatPicksTheWrongBasisAndExactContinues) {
  LpProblem<Q> p;
  p.A = Mat<Q>(1, 2);
  p.A << 1, 1;
  p.b = Vec<Q>(1);
  p.b << 1;
  p.c = Vec<Q>(2);
  const Q eps = Q(1) / Q(mpz_class("100000000000000000000"));
  p.c << 1, Q(1 - eps);
  const LpResult<double> f = solve_lp<double>(to_double(p));
  ASSERT_EQ(f.status, LpStatus::kOptimal);
  EXPECT_EQ(f.x(0), 1.0);  // the float answer is wrong
  const LpResult<Q> v = solve_lp_verified(p, testing::with_duals());
  ASSERT_EQ(v.status, LpStatus::kOptimal);
  EXPECT_EQ(v.value, Q(1 - eps));
  EXPECT_EQ(v.x(1), 1);
  EXPECT_EQ(v.decided_by, DecidedBy::kExactContinuedFromFloatBasis);
  EXPECT_TRUE(verify_optimal(p, v.x, v.duals));
}

// x1 + x2 = 1 and x1 + x2 = 1 + 10^-20: equal in double, inconsistent in Q.
TEST(VerifiedLp, FloatMissesInfeasibility) {
  LpProblem<Q> p;
  p.A = Mat<Q>(2, 2);
  p.A << 1, 1, 1, 1;
  p.b = Vec<Q>(2);
  p.b << 1, Q(1 + Q(1) / Q(mpz_class("100000000000000000000")));
  p.c = Vec<Q>::Zero(2);
  EXPECT_EQ(solve_lp<double>(to_double(p)).status, LpStatus::kOptimal);
  const LpResult<Q> v = solve_lp_verified(p);
  ASSERT_EQ(v.status, LpStatus::kInfeasible);
  EXPECT_TRUE(verify_farkas(p, v.farkas));
  EXPECT_EQ(v.decided_by, DecidedBy::kExact);
}

// Ill-conditioned random LPs: entries k + j * 10^-13 (distinct in Q, nearly equal in double). Verified equals
// exact on every one, and cddlib agrees; some need exact pivots after the float basis.
TEST(VerifiedLp, IllConditionedLpsEqualExact) {
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int> small(-3, 3), pct(0, 99);
  const Q eps = Q(1) / Q(mpz_class("10000000000000"));
  int not_checked = 0;
  for (int t = 0; t < 300; ++t) {
    LpProblem<Q> p = testing::random_lp(rng);
    for (Eigen::Index i = 0; i < p.A.rows(); ++i)
      for (Eigen::Index j = 0; j < p.A.cols(); ++j)
        if (pct(rng) < 40) p.A(i, j) += eps * small(rng);
    for (Eigen::Index j = 0; j < p.c.size(); ++j)
      if (pct(rng) < 50) p.c(j) += eps * small(rng);
    for (Eigen::Index i = 0; i < p.b.size(); ++i)
      if (pct(rng) < 30) p.b(i) += eps * small(rng);
    const LpResult<Q> e = solve_lp<Q>(p);
    const LpResult<Q> v = solve_lp_verified(p, testing::with_duals());
    testing::expect_certified_like(p, v, e, t);
    const reference::CddLpResult ref = reference::cdd_solve_lp(p);
    ASSERT_EQ(v.status, ref.status) << "case " << t;
    if (v.status == LpStatus::kOptimal) {
      ASSERT_EQ(v.value, ref.value) << "case " << t;
    }
    if (v.decided_by != DecidedBy::kFloatBasisCheckedExactly) ++not_checked;
  }
  EXPECT_GT(not_checked, 5);
}

// The rounded certificate accepts the float optimum of a rational LP (rows scaled to integers) and rejects it
// once the float solution is perturbed or the basis is wrong.
TEST(VerifiedLp, RoundedCertificateAcceptsOnlyAnExactOptimum) {
  LpProblem<Q> p;
  p.A = Mat<Q>(2, 4);
  p.A << Q(1, 2), 1, 1, 0, 3, Q(1, 3), 0, 1;
  p.b = Vec<Q>(2);
  p.b << 2, Q(7, 3);
  p.c = Vec<Q>(4);
  p.c << -1, Q(-1, 5), 0, 0;
  const std::optional<IntegerLp> ilp = integer_lp(p);
  ASSERT_TRUE(ilp);
  EXPECT_EQ(ilp->row_scale, (std::vector<std::int64_t>{2, 3}));
  const LpResult<double> f = solve_lp<double>(ilp->to_double(p.is_free), testing::with_duals());
  ASSERT_EQ(f.status, LpStatus::kOptimal);
  const std::optional<OptimalCertificate> cert = round_and_check_optimal(p, *ilp, f.basis, f.x, f.duals);
  ASSERT_TRUE(cert);
  EXPECT_TRUE(verify_optimal(p, cert->x, cert->y));
  EXPECT_EQ(cert->value, solve_lp<Q>(p).value);
  Vec<double> x = f.x;
  x(f.basis[0]) += 1e-3;
  EXPECT_FALSE(round_and_check_optimal(p, *ilp, f.basis, x, f.duals));
  Vec<double> y = f.duals;
  y(0) += 1e-3;
  EXPECT_FALSE(round_and_check_optimal(p, *ilp, f.basis, f.x, y));
  EXPECT_FALSE(round_and_check_optimal(p, *ilp, {2, 3}, f.x, f.duals));
}

// StrictSolver::solve_rounded's float point: a point of A x = b in doubles when the float LP finds one (here
// x_0 / 2 + x_1 / 3 = 1 with x_0 > 0, x >= 0, on the integer row 3 x_0 + 2 x_1 = 6), none for an infeasible system
// (x_0 + x_1 = -1 with x >= 0).
TEST(StrictSolver, FloatPointOfTheRoundedSolve) {
  StrictSystem<Q> s{Mat<Q>(1, 2), Vec<Q>(1), {}, {true, false}};
  s.A << Q(1, 2), Q(1, 3);
  s.b << Q(1);
  bool feasible = false;
  Vec<double> x;
  ASSERT_TRUE(StrictSolver<Q>(s).solve_rounded(s.b, &feasible, &x));
  EXPECT_TRUE(feasible);
  ASSERT_EQ(x.size(), 2);
  EXPECT_NEAR(x(0) / 2 + x(1) / 3, 1, 1e-12);
  EXPECT_GT(x(0), 0);
  s.A << Q(1), Q(1);
  s.b << Q(-1);
  EXPECT_TRUE(StrictSolver<Q>(s).solve_rounded(s.b, &feasible, &x));
  EXPECT_FALSE(feasible);
  EXPECT_EQ(x.size(), 0);
}

// The Farkas vector of a float phase-1 basis, solved in the integer rows, is that basis's own (B1^T y = -1 on its
// artificial columns, 0 on the others, in the rational rows) and proves infeasibility; a basis whose vector
// proves nothing (all structural: y = 0) is refused.
TEST(VerifiedLp, BasisFarkasCertificateIsTheBasisOwnVector) {
  LpProblem<Q> p;
  p.A = Mat<Q>(2, 2);
  p.A << Q(1, 2), Q(1, 3), 1, Q(5, 7);
  p.b = Vec<Q>(2);
  p.b << 1, Q(-2, 5);
  const std::optional<IntegerLp> ilp = integer_lp(p);
  ASSERT_TRUE(ilp);
  const LpResult<double> f = solve_lp<double>(ilp->to_double(p.is_free));
  ASSERT_EQ(f.status, LpStatus::kInfeasible);
  const std::optional<Vec<Q>> y = basis_farkas_certificate(p, *ilp, f.basis);
  ASSERT_TRUE(y);
  EXPECT_TRUE(verify_farkas(p, *y));
  for (Eigen::Index v : f.basis) {
    const Q column_dot = v < 2 ? Q(p.A.col(v).dot(*y)) : Q(sgn(p.b(v - 2)) < 0 ? -(*y)(v - 2) : (*y)(v - 2));
    EXPECT_EQ(column_dot, v < 2 ? Q(0) : Q(-1)) << v;
  }
  EXPECT_FALSE(basis_farkas_certificate(p, *ilp, {0, 1}));
  EXPECT_FALSE(basis_farkas_certificate(p, *ilp, {0}));
}

// The Farkas vector solved on the float vector's support alone (basis_farkas_certificate with y_approx) is the
// basis's own, the same as the full solve: here rows 0-1 contradict each other (x_0 + x_1 = 1, 2 x_0 + 2 x_1 = 3:
// y = (2, -1) up to scale) and rows 2-3 have a point, so y is zero there. A y_approx whose support misses a row
// of y (the solve on it meets no basis equation there) or has the wrong size falls back to the full solve: the same
// vector again.
TEST(VerifiedLp, BasisFarkasOnTheFloatSupportIsTheSameVector) {
  LpProblem<Q> p;
  p.A = Mat<Q>::Zero(4, 5);
  p.A.row(0) << 1, 1, 0, 0, 0;
  p.A.row(1) << 2, 2, 0, 0, 0;
  p.A.row(2) << 0, Q(1, 3), 1, 0, Q(1, 2);
  p.A.row(3) << 0, 0, 1, Q(2, 7), 1;
  p.b = Vec<Q>(4);
  p.b << 1, 3, 2, Q(5, 3);
  const std::optional<IntegerLp> ilp = integer_lp(p);
  ASSERT_TRUE(ilp);
  const LpResult<double> f = solve_lp<double>(ilp->to_double(p.is_free));
  ASSERT_EQ(f.status, LpStatus::kInfeasible);
  ASSERT_EQ(f.farkas.size(), 4);
  ASSERT_EQ(f.farkas(2), 0);
  ASSERT_EQ(f.farkas(3), 0);
  const std::optional<Vec<Q>> full = basis_farkas_certificate(p, *ilp, f.basis);
  ASSERT_TRUE(full);
  EXPECT_TRUE(verify_farkas(p, *full));
  EXPECT_EQ(basis_farkas_certificate(*ilp, p.is_free, f.basis, f.farkas), full);
  Vec<double> missing = f.farkas;
  missing(0) = 0;
  EXPECT_EQ(basis_farkas_certificate(*ilp, p.is_free, f.basis, missing), full);
  EXPECT_EQ(basis_farkas_certificate(*ilp, p.is_free, f.basis, Vec<double>(f.farkas.head(3))), full);
}

}  // namespace
}  // namespace contactcert::exact
