#include "exact/simplex.h"

#include <gtest/gtest.h>

#include <random>

#include "exact/verified_lp.h"
#include "tests/exact/lp_expectations.h"
#include "tests/exact/random_lp.h"
#include "tests/reference/cdd_lp.h"

namespace contactcert::exact {
namespace {

Q q(const char* s) { return Q(s); }

LpProblem<Q> lp(std::initializer_list<std::initializer_list<Q>> A, std::initializer_list<Q> b,
                std::initializer_list<Q> c) {
  LpProblem<Q> p;
  p.A = Mat<Q>(static_cast<Eigen::Index>(A.size()), static_cast<Eigen::Index>(A.begin()->size()));
  Eigen::Index i = 0;
  for (const auto& row : A) {
    Eigen::Index j = 0;
    for (const Q& v : row) p.A(i, j++) = v;
    ++i;
  }
  p.b = Vec<Q>(static_cast<Eigen::Index>(b.size()));
  i = 0;
  for (const Q& v : b) p.b(i++) = v;
  p.c = Vec<Q>(static_cast<Eigen::Index>(c.size()));
  i = 0;
  for (const Q& v : c) p.c(i++) = v;
  return p;
}

// min -x1 - x2  s.t.  x1 + 2 x2 <= 4,  3 x1 + x2 <= 6: optimum at (8/5, 6/5), value -14/5, duals (-2/5, -1/5).
TEST(Simplex, TinyOptimalByHand) {
  const LpProblem<Q> p = lp({{1, 2, 1, 0}, {3, 1, 0, 1}}, {4, 6}, {-1, -1, 0, 0});
  for (PivotRule rule : {PivotRule::kBland, PivotRule::kDantzigThenBland}) {
    const LpResult<Q> r =
        solve_lp<Q>(p, {.warm_basis = {}, .max_pivots = 100, .rule = rule, .deadline = {}, .duals = true});
    ASSERT_EQ(r.status, LpStatus::kOptimal);
    EXPECT_EQ(r.value, q("-14/5"));
    EXPECT_EQ(r.x(0), q("8/5"));
    EXPECT_EQ(r.x(1), q("6/5"));
    EXPECT_EQ(r.duals(0), q("-2/5"));
    EXPECT_EQ(r.duals(1), q("-1/5"));
    EXPECT_TRUE(verify_optimal(p, r.x, r.duals));
    EXPECT_EQ(r.decided_by, DecidedBy::kExact);
    std::vector<Eigen::Index> basis = r.basis;
    std::sort(basis.begin(), basis.end());
    EXPECT_EQ(basis, (std::vector<Eigen::Index>{0, 1}));
  }
  const LpResult<double> f = solve_lp<double>(to_double(p));
  ASSERT_EQ(f.status, LpStatus::kOptimal);
  EXPECT_NEAR(f.value, -2.8, 1e-12);
  EXPECT_EQ(f.decided_by, DecidedBy::kFloat);
}

// x1 + x2 = -1 with x >= 0 is infeasible; y = (1) is a Farkas vector (y^T A = (1, 1) >= 0, y^T b = -1 < 0).
TEST(Simplex, TinyInfeasibleWithFarkasVector) {
  const LpProblem<Q> p = lp({{1, 1}, {1, -1}}, {-1, 0}, {1, 1});
  const LpResult<Q> r = solve_lp<Q>(p);
  ASSERT_EQ(r.status, LpStatus::kInfeasible);
  EXPECT_TRUE(verify_farkas(p, r.farkas));
  Vec<Q> wrong = r.farkas;
  wrong *= Q(-1);
  EXPECT_FALSE(verify_farkas(p, wrong));
  Vec<Q> by_hand(2);
  by_hand << 1, 0;
  EXPECT_TRUE(verify_farkas(p, by_hand));
  // A consistent system whose only solutions are negative: x1 - x2 = 2, x2 = -1... in x >= 0 form.
  const LpProblem<Q> p2 = lp({{1, -1}, {0, 1}}, {2, -1}, {0, 0});
  const LpResult<Q> r2 = solve_lp<Q>(p2);
  ASSERT_EQ(r2.status, LpStatus::kInfeasible);
  EXPECT_TRUE(verify_farkas(p2, r2.farkas));
}

// min -x1  s.t.  x1 - x2 = 1: unbounded along d = (1, 1).
TEST(Simplex, TinyUnboundedWithRay) {
  const LpProblem<Q> p = lp({{1, -1}}, {1}, {-1, 0});
  const LpResult<Q> r = solve_lp<Q>(p);
  ASSERT_EQ(r.status, LpStatus::kUnbounded);
  EXPECT_TRUE(verify_ray(p, r.ray));
  EXPECT_EQ(r.ray(0), r.ray(1));
  Vec<Q> wrong(2);
  wrong << 1, 0;
  EXPECT_FALSE(verify_ray(p, wrong));
  EXPECT_EQ(p.A * r.x, p.b);
}

// Beale's example (Chvatal, Linear Programming, p. 31): Dantzig's rule with largest-coefficient ties cycles.
TEST(Simplex, BealeCyclingExampleTerminates) {
  const LpProblem<Q> p =
      lp({{q("1/4"), -60, q("-1/25"), 9, 1, 0, 0}, {q("1/2"), -90, q("-1/50"), 3, 0, 1, 0}, {0, 0, 1, 0, 0, 0, 1}},
         {0, 0, 1}, {q("-3/4"), 150, q("-1/50"), 6, 0, 0, 0});
  for (PivotRule rule : {PivotRule::kBland, PivotRule::kDantzigThenBland}) {
    const LpResult<Q> r =
        solve_lp<Q>(p, {.warm_basis = {}, .max_pivots = 10000, .rule = rule, .deadline = {}, .duals = true});
    ASSERT_EQ(r.status, LpStatus::kOptimal);
    EXPECT_EQ(r.value, q("-1/20"));
    EXPECT_EQ(r.x(0), q("1/25"));
    EXPECT_EQ(r.x(2), 1);
    EXPECT_TRUE(verify_optimal(p, r.x, r.duals));
    const LpResult<double> f = solve_lp<double>(
        to_double(p), {.warm_basis = {}, .max_pivots = 10000, .rule = rule, .deadline = {}, .duals = true});
    ASSERT_EQ(f.status, LpStatus::kOptimal);
    EXPECT_NEAR(f.value, -0.05, 1e-12);
  }
  // Starting from the slack basis, the cycle of Beale's example is reached immediately.
  const LpResult<Q> warm = solve_lp<Q>(p, {.warm_basis = std::vector<Eigen::Index>{4, 5, 6},
                                           .max_pivots = 10000,
                                           .rule = PivotRule::kDantzigThenBland,
                                           .deadline = {},
                                           .duals = true});
  EXPECT_EQ(warm.value, q("-1/20"));
}

TEST(Simplex, FreeVariables) {
  // min x1 with x1 free, x1 + x2 = 3, x2 + s = 5: x1 = -2.
  LpProblem<Q> p = lp({{1, 1, 0}, {0, 1, 1}}, {3, 5}, {1, 0, 0});
  p.is_free = {true, false, false};
  const LpResult<Q> r = solve_lp<Q>(p, testing::with_duals());
  ASSERT_EQ(r.status, LpStatus::kOptimal);
  EXPECT_EQ(r.value, -2);
  EXPECT_EQ(r.x(0), -2);
  EXPECT_TRUE(verify_optimal(p, r.x, r.duals));
  // Without the bound on x2 it is unbounded with a ray that decreases x1.
  LpProblem<Q> u = lp({{1, 1}}, {3}, {1, 0});
  u.is_free = {true, false};
  const LpResult<Q> ru = solve_lp<Q>(u);
  ASSERT_EQ(ru.status, LpStatus::kUnbounded);
  EXPECT_TRUE(verify_ray(u, ru.ray));
  EXPECT_LT(ru.ray(0), 0);
  // A free column that never meets a constraint: min x1 with A = [0 1].
  LpProblem<Q> v = lp({{0, 1}}, {1}, {1, 0});
  v.is_free = {true, false};
  const LpResult<Q> rv = solve_lp<Q>(v);
  ASSERT_EQ(rv.status, LpStatus::kUnbounded);
  EXPECT_TRUE(verify_ray(v, rv.ray));
  // Infeasible with a free column: x1 free, x1 + x2 = 1, x1 = 2, x2 + x3 = -... : y^T A must vanish on x1.
  LpProblem<Q> w = lp({{1, 1, 0}, {1, 0, 0}, {0, 1, 1}}, {1, 2, 0}, {0, 0, 0});
  w.is_free = {true, false, false};
  const LpResult<Q> rw = solve_lp<Q>(w);
  ASSERT_EQ(rw.status, LpStatus::kInfeasible);
  EXPECT_TRUE(verify_farkas(w, rw.farkas));
}

TEST(Simplex, RedundantRowsGiveABasisOfRankSize) {
  const LpProblem<Q> p = lp({{1, 1, 1}, {2, 2, 2}, {1, -1, 0}}, {2, 4, 0}, {1, 2, 3});
  const LpResult<Q> r = solve_lp<Q>(p, testing::with_duals());
  ASSERT_EQ(r.status, LpStatus::kOptimal);
  EXPECT_EQ(r.basis.size(), 2u);
  EXPECT_EQ(r.value, 3);
  EXPECT_TRUE(verify_optimal(p, r.x, r.duals));
}

TEST(Simplex, WarmStartFromTheOptimalBasisNeedsNoPivot) {
  const LpProblem<Q> p = lp({{1, 2, 1, 0}, {3, 1, 0, 1}}, {4, 6}, {-1, -1, 0, 0});
  const LpResult<Q> cold = solve_lp<Q>(p);
  const LpResult<Q> warm = solve_lp<Q>(p, {.warm_basis = cold.basis, .deadline = {}, .duals = true});
  EXPECT_EQ(warm.pivots, 0);
  EXPECT_EQ(warm.value, cold.value);
  // An infeasible warm basis falls back to phase 1 and still finds the optimum.
  const LpResult<Q> bad =
      solve_lp<Q>(p, {.warm_basis = std::vector<Eigen::Index>{0, 3}, .deadline = {}, .duals = true});
  EXPECT_EQ(bad.value, cold.value);
  // The tableau gives access to pivoting.
  std::optional<SimplexTableau<Q>> tab = SimplexTableau<Q>::from_basis(p.A, p.b, {2, 3});
  ASSERT_TRUE(tab);
  tab->set_objective(p.c);
  EXPECT_EQ(tab->reduced_cost(0), -1);
  tab->pivot(tab->row_of(3), 0);  // x1 enters, s2 leaves: vertex (2, 0)
  EXPECT_EQ(tab->primal()(0), 2);
  EXPECT_EQ(tab->objective_value(), -2);
  EXPECT_FALSE(SimplexTableau<Q>::from_basis(p.A, p.b, {0, 0}).has_value());
}

TEST(Simplex, PivotBudgetThrows) {
  const LpProblem<Q> p = lp({{1, 2, 1, 0}, {3, 1, 0, 1}}, {4, 6}, {-1, -1, 0, 0});
  EXPECT_THROW(solve_lp<Q>(p, {.warm_basis = {}, .max_pivots = 0, .deadline = {}, .duals = true}), BudgetExceeded);
}

// The pivot limit is a status of the warm-started phase 2 (the verified LP asks it whether a float basis is
// optimal as it stands), not an exception thrown from the pivot loop.
TEST(Simplex, PivotLimitIsAStatus) {
  const LpProblem<Q> p = lp({{1, 2, 1, 0}, {3, 1, 0, 1}}, {4, 6}, {-1, -1, 0, 0});
  std::optional<SimplexTableau<Q>> slack = SimplexTableau<Q>::from_basis(p.A, p.b, {2, 3});
  ASSERT_TRUE(slack.has_value());
  const LpResult<Q> r =
      solve_lp_from_tableau(p, *slack, {.warm_basis = {}, .max_pivots = 0, .deadline = {}, .duals = true});
  EXPECT_EQ(r.status, LpStatus::kPivotLimit);
  EXPECT_EQ(r.pivots, 0);
  EXPECT_THROW(check_pivot_budget(r.status, {}), BudgetExceeded);
  // At the optimal basis (x1 = 8/5, x2 = 6/5) no pivot is needed.
  std::optional<SimplexTableau<Q>> opt = SimplexTableau<Q>::from_basis(p.A, p.b, {0, 1});
  ASSERT_TRUE(opt.has_value());
  const LpResult<Q> o =
      solve_lp_from_tableau(p, *opt, {.warm_basis = {}, .max_pivots = 0, .deadline = {}, .duals = true});
  ASSERT_EQ(o.status, LpStatus::kOptimal);
  EXPECT_EQ(o.value, q("-14/5"));
}

// The feasible tableau of `basis` priced by p's objective (throws if the basis is not primal feasible).
SimplexTableau<Q> priced_tableau(const LpProblem<Q>& p, const std::vector<Eigen::Index>& basis) {
  SimplexTableau<Q> tab = feasible_tableau(p, basis).value();
  tab.set_objective(p.objective());
  return tab;
}

// The basis of a feasible tableau decides the LP as it stands when it is optimal, or when the column the
// pricing rule enters has no blocking row (an unbounded edge: the verified LP accepts such a float basis with no
// exact pivot, as the zero-pivot phase 2 it replaces did); otherwise a pivot is needed.
TEST(Simplex, DecideAtBasisOptimalUnboundedOrPivot) {
  // min -x2 s.t. x1 - x2 + s = 1: at the basis {x1}, x2 prices out with B^-1 a_2 = -1 (no blocking row).
  const LpProblem<Q> u = lp({{1, -1, 1}}, {1}, {0, -1, 0});
  const SimplexTableau<Q> tu = priced_tableau(u, {0});
  EXPECT_FALSE(is_optimal_basis(tu, u.is_free));
  const std::optional<LpResult<Q>> ru = decide_at_basis(u, tu);
  ASSERT_TRUE(ru.has_value());
  EXPECT_EQ(ru->status, LpStatus::kUnbounded);
  EXPECT_EQ(ru->pivots, 0);
  EXPECT_EQ(ru->unbounded_column, 1);
  EXPECT_TRUE(verify_ray(u, ru->ray));
  // The same as phase 2 with no pivot allowed.
  const LpResult<Q> zero =
      solve_lp_from_tableau(u, tu, {.warm_basis = {}, .max_pivots = 0, .deadline = {}, .duals = true});
  EXPECT_EQ(zero.status, LpStatus::kUnbounded);
  EXPECT_EQ(zero.ray, ru->ray);

  // min -x1 - x2 s.t. x1 + 2 x2 <= 4, 3 x1 + x2 <= 6: the slack basis needs a pivot, {x1, x2} is optimal.
  const LpProblem<Q> p = lp({{1, 2, 1, 0}, {3, 1, 0, 1}}, {4, 6}, {-1, -1, 0, 0});
  const SimplexTableau<Q> slack = priced_tableau(p, {2, 3});
  EXPECT_FALSE(is_optimal_basis(slack, p.is_free));
  EXPECT_FALSE(decide_at_basis(p, slack).has_value());
  const SimplexTableau<Q> opt = priced_tableau(p, {0, 1});
  EXPECT_TRUE(is_optimal_basis(opt, p.is_free));
  const std::optional<LpResult<Q>> ro = decide_at_basis(p, opt, testing::with_duals());
  ASSERT_TRUE(ro.has_value());
  EXPECT_EQ(ro->status, LpStatus::kOptimal);
  EXPECT_EQ(ro->value, q("-14/5"));
  EXPECT_TRUE(verify_optimal(p, ro->x, ro->duals));
  // {x2, s1} has x1 = 0, x2 = 6, s1 = 4 - 12 < 0: not primal feasible.
  EXPECT_FALSE(feasible_tableau(p, {1, 2}).has_value());
}

// The duals are computed on request only (LpOptions::duals), in every number type and on the verified path.
TEST(Simplex, DualsOnlyOnRequest) {
  const LpProblem<Q> p = lp({{1, 2, 1, 0}, {3, 1, 0, 1}}, {4, 6}, {-1, -1, 0, 0});
  const LpResult<Q> none = solve_lp<Q>(p);
  ASSERT_EQ(none.status, LpStatus::kOptimal);
  EXPECT_EQ(none.duals.size(), 0);
  EXPECT_EQ(solve_lp<double>(to_double(p)).duals.size(), 0);
  EXPECT_EQ(solve_lp_verified(p).duals.size(), 0);
  const LpResult<Q> r = solve_lp<Q>(p, testing::with_duals());
  ASSERT_EQ(r.duals.size(), 2);
  EXPECT_EQ(r.duals(0), q("-2/5"));
  EXPECT_EQ(r.duals(1), q("-1/5"));
  EXPECT_EQ(solve_lp_verified(p, testing::with_duals()).duals, r.duals);
  EXPECT_EQ(solve_lp<double>(to_double(p), testing::with_duals()).duals.size(), 2);
}

// A deadline that has passed stops the simplex before its first pivot with the status kTimeLimit (no
// exception), in Q, in double and in the verified LP.
TEST(Simplex, TimeLimitIsAStatus) {
  const LpProblem<Q> p = lp({{1, 2, 1, 0}, {3, 1, 0, 1}}, {4, 6}, {-1, -1, 0, 0});
  LpOptions passed;
  passed.deadline = Deadline::after(1e-9);
  while (!passed.deadline.expired()) {
  }
  const LpResult<Q> r = solve_lp<Q>(p, passed);
  EXPECT_EQ(r.status, LpStatus::kTimeLimit);
  EXPECT_EQ(r.pivots, 0);
  EXPECT_EQ(solve_lp<double>(to_double(p), passed).status, LpStatus::kTimeLimit);
  EXPECT_EQ(solve_lp_verified(p, passed).status, LpStatus::kTimeLimit);
  // Without a limit the same LP is solved.
  EXPECT_EQ(solve_lp<Q>(p).status, LpStatus::kOptimal);
}

// 1500 seeded random LPs, many degenerate, against cddlib's exact LP: same status, same optimal value, and
// every certificate verifies exactly.
TEST(Simplex, RandomLpsAgreeWithCddlibExactly) {
  std::mt19937_64 rng(20261123);
  int counts[3] = {0, 0, 0};
  for (int t = 0; t < 1500; ++t) {
    const LpProblem<Q> p = testing::random_lp(rng);
    const reference::CddLpResult ref = reference::cdd_solve_lp(p);
    const PivotRule rule = t % 2 ? PivotRule::kBland : PivotRule::kDantzigThenBland;
    const LpResult<Q> r =
        solve_lp<Q>(p, {.warm_basis = {}, .max_pivots = 10000, .rule = rule, .deadline = {}, .duals = true});
    testing::expect_certified_like(p, r, ref.status, ref.value, t);
    ++counts[static_cast<int>(r.status)];
  }
  EXPECT_GT(counts[0], 200);
  EXPECT_GT(counts[1], 200);
  EXPECT_GT(counts[2], 200);
}

}  // namespace
}  // namespace contactcert::exact
