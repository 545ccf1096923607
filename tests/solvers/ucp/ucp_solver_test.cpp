#include <gtest/gtest.h>

#include <random>

#include "runtime/scenes.h"
#include "solvers/ucp/bilinear.h"
#include "solvers/ucp/enumerate.h"
#include "solvers/ucp/generate.h"
#include "solvers/ucp/recovery.h"
#include "solvers/ucp/search.h"
#include "solvers/ucp/solve.h"
#include "tests/solvers/ucp/random_problems.h"

namespace contactcert::solvers::ucp {
namespace {

std::string scene(int k) {
  return contactcert::runtime::bundled_scenes_dir() + "/pang1994_dataset" + std::to_string(k) + ".json";
}

bool in_polyhedron(const StandardPolyhedron<Q>& P, const Vec<Q>& x) {
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (sgn(x(i)) < 0) return false;
  return P.A * x == P.b;
}

void expect_physical_solution(const UcpProblem& p, const Vec<Q>& x, const Vec<Q>& y) {
  ASSERT_TRUE(in_polyhedron(p.ucp().X, x));
  ASSERT_TRUE(in_polyhedron(p.ucp().Y, y));
  EXPECT_EQ(sgn(Q(x.dot(y))), 0);
  const auto s = recover(*p.quasistatic, x, y);
  ASSERT_TRUE(s.has_value());
  const ConditionsCheck c = check_conditions(*p.quasistatic, *s);
  EXPECT_EQ(c.status, ConditionsStatus::kSatisfied) << (c.violations.empty() ? "" : c.violations[0]);
}

TEST(UcpPaperAlgorithm, DataSets1To3AreSolvedWithExactlyComplementaryPairs) {
  for (int k = 1; k <= 3; ++k) {
    const UcpProblem p = load_ucp_problem(scene(k));
    for (Arith a : {Arith::kExact, Arith::kVerified}) {
      std::mt19937_64 rng(1);
      BilinearOptions o;
      o.arith = a;
      const auto r = bilinear(make_face(p.ucp().X, {}), make_face(p.ucp().Y, {}), o, rng);
      ASSERT_EQ(r.status, BilinearStatus::kComplementary) << "data set " << k;
      EXPECT_EQ(sgn(r.xTy), 0);
      // Section 5: "no more than two (x,y) pairs (a total of 6 linear programs, including the two initial ones)".
      EXPECT_LE(r.pairs, 2) << "data set " << k;
      EXPECT_LE(r.counters.lps, 6) << "data set " << k;
      expect_physical_solution(p, r.x.x, r.y.x);
    }
  }
}

TEST(UcpCompleteSearch, DataSets1To3SolvableAndDataSet4Jammed) {
  for (int k = 1; k <= 4; ++k) {
    const UcpProblem p = load_ucp_problem(scene(k));
    std::mt19937_64 rng(3);
    const auto r = complete_search(p.ucp(), SearchOptions{}, rng);
    if (k < 4) {
      ASSERT_EQ(r.status, UcpStatus::kSolvable) << k;
      expect_physical_solution(p, r.x, r.y);
    } else {
      ASSERT_EQ(r.status, UcpStatus::kJammed);
      EXPECT_GE(r.tree.size(), 1u);
    }
  }
}

}  // namespace
}  // namespace contactcert::solvers::ucp

namespace contactcert::solvers::ucp {
namespace {

UcpProblem with_mu(UcpProblem p, const Vec<Q>& mu) {
  p.quasistatic->mu = mu;
  p.set(build_ucp(*p.quasistatic));
  return p;
}

TEST(UcpCompleteSearch, DataSet2MuSweepAgreesWithTheEnumerativeBaseline) {
  const UcpProblem base = load_ucp_problem(scene(2));
  int solvable = 0, jammed = 0;
  const Q step(1, 4);
  for (int a = 0; a <= 4; ++a)
    for (int b = 0; b <= 4; ++b)
      for (int c = 0; c <= 4; ++c) {
        Vec<Q> mu(3);
        mu << step * a, step * b, step * c;
        const UcpProblem p = with_mu(base, mu);
        std::mt19937_64 rng(a * 25 + b * 5 + c);
        const SearchResult<Q> s = complete_search(p.ucp(), SearchOptions{}, rng);
        const EnumerateResult e = enumerate_modes(p, Arith::kExact, 1000);
        ASSERT_NE(s.status, UcpStatus::kUnknown);
        ASSERT_EQ(s.status, e.status) << "mu = " << mu.transpose();
        EXPECT_EQ(e.lps, 64);
        if (s.status == UcpStatus::kSolvable) {
          ++solvable;
          expect_physical_solution(p, s.x, s.y);
          expect_physical_solution(p, e.x, e.y);
        } else {
          ++jammed;
        }
      }
  // The grid crosses the jamming region (Data Set 4 lies in it): both verdicts occur.
  EXPECT_GT(solvable, 0);
  EXPECT_GT(jammed, 0);
}

// The prefix tree over the contacts finds the enumeration's solution modes, in its order, with fewer LPs when some
// prefix is empty (motion uniqueness, solvers/motion/uniqueness.h); its LP budget ends it `unknown`.
TEST(UcpSolutionModes, PrefixTreeFindsTheEnumeratedSolutionModes) {
  const UcpProblem base = load_ucp_problem(scene(2));
  long tree_lps = 0, enumerated_lps = 0;
  for (int a = 0; a <= 4; a += 2)
    for (int b = 0; b <= 4; b += 2) {
      Vec<Q> mu(3);
      mu << Q(a, 4), Q(b, 4), Q(1, 2);
      const UcpProblem p = with_mu(base, mu);
      for (Arith arith : {Arith::kExact, Arith::kVerified}) {
        const EnumerateResult e = enumerate_modes(p, arith, 1000);
        const EnumerateResult t = solution_modes_by_prefix(p, arith, 1000);
        EXPECT_EQ(t.status, e.status) << "mu = " << mu.transpose();
        EXPECT_TRUE(t.complete);
        EXPECT_EQ(t.solution_modes, e.solution_modes) << "mu = " << mu.transpose();
        tree_lps += t.lps, enumerated_lps += e.lps;
      }
    }
  EXPECT_LT(tree_lps, enumerated_lps);
  const EnumerateResult cut = solution_modes_by_prefix(base, Arith::kExact, 3);
  EXPECT_EQ(cut.status, UcpStatus::kUnknown);
  EXPECT_FALSE(cut.complete);
  EXPECT_EQ(cut.lps, 3);
}

TEST(UcpCompleteSearch, RandomProblemsAgreeWithTheEnumerativeBaselineOnEveryPath) {
  int solvable = 0, jammed = 0;
  for (int seed = 0; seed < 24; ++seed) {
    const UcpProblem p = testing::random_problem(seed, 3);
    const EnumerateResult e = enumerate_modes(p, Arith::kExact, 1000);
    for (Arith a : {Arith::kExact, Arith::kVerified}) {
      std::mt19937_64 rng(seed);
      SearchOptions so;
      so.heuristic.arith = a;
      const SearchResult<Q> s = complete_search(p.ucp(), so, rng);
      ASSERT_EQ(s.status, e.status) << "seed " << seed;
      if (s.status == UcpStatus::kSolvable) expect_physical_solution(p, s.x, s.y);
    }
    // The float path is unchecked but should agree on these well-scaled problems.
    std::mt19937_64 rng(seed);
    SearchOptions so;
    so.heuristic.arith = Arith::kFloat;
    EXPECT_EQ(complete_search(to_double(p.rows()), so, rng).status, e.status) << "float, seed " << seed;
    (e.status == UcpStatus::kSolvable ? solvable : jammed)++;
  }
  EXPECT_GT(solvable, 0);
  EXPECT_GT(jammed, 0);
}

// Seed s gives m = 1 + s % 3 rows, n = 3 + s % 4 columns, planted iff s is even: every one of the 12
// combinations occurs within 12 consecutive seeds. The ASan + UBSan build of CI runs each once (this test
// dominates the suite there), the normal build 40 seeds.
#ifdef CONTACTCERT_SANITIZED
constexpr int kReductionSeeds = 12;
#else
constexpr int kReductionSeeds = 40;
#endif

TEST(UcpCompleteSearch, ReductionInstancesAreSolvableExactlyWhenTheZeroOneProblemIs) {
  int feasible = 0, infeasible = 0;
  for (int seed = 0; seed < kReductionSeeds; ++seed) {
    std::mt19937_64 gen(seed);
    const int m = 1 + seed % 3, n = 3 + seed % 4;
    const ZeroOneProblem zo = random_zero_one(m, n, seed % 2 == 0, gen);
    const bool expected = zero_one_feasible(zo);
    const UcpProblem p = reduction_problem(zo);
    std::mt19937_64 rng(seed);
    const SearchResult<Q> s = complete_search(p.ucp(), SearchOptions{}, rng);
    ASSERT_EQ(s.status, expected ? UcpStatus::kSolvable : UcpStatus::kJammed) << "seed " << seed;
    if (expected) {
      ++feasible;
      ASSERT_TRUE(in_polyhedron(p.ucp().X, s.x));
      ASSERT_TRUE(in_polyhedron(p.ucp().Y, s.y));
      EXPECT_EQ(sgn(Q(s.x.dot(s.y))), 0);
      // Proposition 2: the z part of x is a 0-1 solution of A z = b.
      const Vec<Q> z = s.x.head(n);
      for (int j = 0; j < n; ++j) EXPECT_TRUE(z(j) == 0 || z(j) == 1);
      EXPECT_EQ(zo.A * z, zo.b);
    } else {
      ++infeasible;
    }
    if (2 * n <= 12) {
      EXPECT_EQ(enumerate_modes(p, Arith::kExact, 1 << 12).status, s.status) << "seed " << seed;
    }
  }
  EXPECT_GT(feasible, kReductionSeeds / 8);
  EXPECT_GT(infeasible, kReductionSeeds / 8);
}

TEST(UcpPaperAlgorithm, DataSet4IsNotDecidedByTheBilinearAlgorithm) {
  // Section 5: on the jamming region "the algorithm terminated due to cycling".
  const UcpProblem p = load_ucp_problem(scene(4));
  for (Step3Rule rule : {Step3Rule::kPaper, Step3Rule::kModified}) {
    std::mt19937_64 rng(5);
    BilinearOptions o;
    o.step3 = rule;
    const auto r = bilinear(make_face(p.ucp().X, {}), make_face(p.ucp().Y, {}), o, rng);
    EXPECT_EQ(r.status, BilinearStatus::kStopped);
    EXPECT_GT(sgn(r.xTy), 0);
    EXPECT_EQ(r.random_moves, o.max_random_moves + 1);
  }
}

TEST(UcpCompleteSearch, EmptyXIsJammedWithARootCertificate) {
  // X = {x >= 0 : x_0 + x_1 = -1} is empty.
  UcpProblem p;
  UcpInstance<Q> ucp;
  ucp.X.A = Mat<Q>::Ones(1, 2);
  ucp.X.b = Vec<Q>::Constant(1, Q(-1));
  ucp.Y.A = Mat<Q>::Ones(1, 2);
  ucp.Y.b = Vec<Q>::Constant(1, Q(1));
  p.set(ucp);
  std::mt19937_64 rng(1);
  const auto s = complete_search(p.ucp(), SearchOptions{}, rng);
  ASSERT_EQ(s.status, UcpStatus::kJammed);
  EXPECT_EQ(s.reason, "X is empty");
  ASSERT_EQ(s.tree.size(), 1u);
  EXPECT_EQ(s.tree[0].side, Side::kX);
}

TEST(UcpCompleteSearch, NodeBudgetGivesUnknown) {
  const UcpProblem p = load_ucp_problem(scene(4));
  std::mt19937_64 rng(1);
  SearchOptions so;
  so.max_nodes = 2;
  so.bilinear_first = false;
  EXPECT_EQ(complete_search(p.ucp(), so, rng).status, UcpStatus::kUnknown);
}

// A deadline that has passed stops the run inside its first LP, with a status and no exception, on every path:
// the face LP (kTimeLimit), the bilinear algorithm's Step 0, the complete search (`unknown`, no pair) and the
// enumeration (no mode tested); solve_ucp then reports the time limit with what it covered (the CLI's exit 3).
TEST(UcpTimeLimit, APassedDeadlineStopsInsideTheFirstLp) {
  const UcpProblem p = load_ucp_problem(scene(4));
  const exact::Deadline passed = exact::Deadline::after(1e-9);
  while (!passed.expired()) {
  }
  LpCounters count;
  const Vec<double> zero = Vec<double>::Zero(p.ucp().n());
  EXPECT_EQ(minimize_on_face(make_face(to_double(p.rows()).X, {}), zero, Arith::kFloat, count, passed).status,
            FaceLpStatus::kTimeLimit);
  for (Arith a : {Arith::kExact, Arith::kVerified, Arith::kAdaptive}) {
    const std::string what = exact::arith_name(a);
    count = {};
    EXPECT_EQ(minimize_on_face(make_face(p.ucp().X, {}), Vec<Q>(Vec<Q>::Zero(p.ucp().n())), a, count, passed).status,
              FaceLpStatus::kTimeLimit)
        << what;
    EXPECT_EQ(count.lps, 1) << what;
    BilinearOptions o;
    o.arith = a;
    o.deadline = passed;
    std::mt19937_64 rng(1);
    const BilinearResult<Q> b = bilinear(make_face(p.ucp().X, {}), make_face(p.ucp().Y, {}), o, rng);
    EXPECT_EQ(b.status, BilinearStatus::kTimeLimit) << what;
    EXPECT_EQ(b.counters.lps, 1) << what;
    SearchOptions so;
    so.heuristic = o;
    so.deadline = passed;
    const SearchResult<Q> s = complete_search(p.ucp(), so, rng);
    EXPECT_EQ(s.status, UcpStatus::kUnknown) << what;
    EXPECT_FALSE(s.paired) << what;
    EXPECT_EQ(s.counters.lps, 1) << what;
    const EnumerateResult e = enumerate_modes(p, a, 1000, passed);
    EXPECT_EQ(e.status, UcpStatus::kUnknown) << what;
    EXPECT_FALSE(e.complete) << what;
    EXPECT_EQ(e.lps, 0) << what;
  }
  for (Arith a : {Arith::kFloat, Arith::kExact, Arith::kVerified, Arith::kAdaptive}) {
    UcpOptions opts;
    opts.arith = a;
    opts.time_limit = 1e-9;
    const UcpReport r = solve_ucp(p, opts);
    EXPECT_EQ(r.status, UcpStatus::kUnknown) << exact::arith_name(a);
    EXPECT_NE(r.reason.find("time limit"), std::string::npos) << r.reason;
    EXPECT_FALSE(r.best_xTy.has_value()) << exact::arith_name(a);
  }
}

}  // namespace
}  // namespace contactcert::solvers::ucp
