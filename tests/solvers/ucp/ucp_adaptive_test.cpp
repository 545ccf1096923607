// --arith adaptive for the UCP: every verdict equals the exact one and carries exact evidence that the
// independent checker accepts; the ladder climbs when a float rung's verdict does not check out.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "exact/json_input.h"
#include "solvers/ucp/certificate.h"
#include "solvers/ucp/generate.h"
#include "solvers/ucp/solve.h"

namespace contactcert::solvers::ucp {
namespace {

UcpReport solve(const UcpProblem& p, Arith arith, std::uint64_t seed = 1) {
  UcpOptions o;
  o.arith = arith;
  o.seed = seed;
  return solve_ucp(p, o);
}

/// The adaptive verdict is the exact one, and its certificate checks.
void expect_certified_like_exact(const UcpProblem& p, const std::string& what) {
  const UcpReport a = solve(p, Arith::kAdaptive), e = solve(p, Arith::kExact);
  ASSERT_EQ(a.status, e.status) << what;
  ASSERT_FALSE(a.decided_by.empty()) << what;
  std::string text;
  if (a.status == UcpStatus::kSolvable) {
    ASSERT_TRUE(a.x && a.y) << what;
    text = solvable_certificate(p, *a.x, *a.y);
  } else {
    ASSERT_EQ(a.status, UcpStatus::kJammed) << what;
    ASSERT_TRUE(a.proof) << what;
    text = jammed_certificate(p, *a.proof);
  }
  const CertificateCheck c = check_ucp_certificate(exact::JsonInput::parse(text, "certificate"));
  EXPECT_EQ(c.verdict, CertificateVerdict::kValid) << what << ": " << c.reason;
}

TEST(UcpAdaptive, RandomProblemsGetTheExactVerdictWithACertificate) {
  std::map<std::string, int> rungs;
  for (int seed = 0; seed < 30; ++seed) {
    std::mt19937_64 gen(seed);
    RandomProblemOptions o;
    o.nc = 2 + seed % 4;
    o.mu_max = Q(1 + seed % 4, 2);
    o.mu_max.canonicalize();
    o.abar_size = seed % (o.nc + 1);
    const UcpProblem p = generate_random_problem(o, gen);
    expect_certified_like_exact(p, "random seed " + std::to_string(seed));
    ++rungs[solve(p, Arith::kAdaptive).decided_by];
  }
  // Well-scaled problems mostly need no more than doubles (27 of 30 with these seeds: a float search tree
  // whose leaves do not all check out sends the problem up the ladder).
  EXPECT_GE(rungs["double"], 25);
}

TEST(UcpAdaptive, ReductionInstancesGetTheExactVerdictWithACertificate) {
  for (int seed = 0; seed < 30; ++seed) {
    std::mt19937_64 gen(seed);
    const ZeroOneProblem zo = random_zero_one(1 + seed % 3, 3 + seed % 4, seed % 2 == 0, gen);
    expect_certified_like_exact(reduction_problem(zo), "reduction seed " + std::to_string(seed));
  }
}

/// X = {x in R^2_+ : x1 - x2 = -eps}, Y = {y in R^2_+ : y2 = 1}: x2 = x1 + eps > 0 = y2 is impossible, so
/// the problem is jammed; a number type that takes eps for 0 finds the "solution" x = (0, eps), y = (0, 1).
UcpProblem tiny_gap(const Q& eps) {
  UcpProblem p;
  p.ucp.X.A = Mat<Q>(1, 2);
  p.ucp.X.A << 1, -1;
  p.ucp.X.b = Vec<Q>::Constant(1, -eps);
  p.ucp.Y.A = Mat<Q>(1, 2);
  p.ucp.Y.A << 0, 1;
  p.ucp.Y.b = Vec<Q>::Constant(1, Q(1));
  return p;
}

TEST(UcpAdaptive, ClimbsPastARungThatTakesATinyGapForZero) {
  // eps = 1/(3 2^k): the float path calls k = 80 solvable; adaptive climbs and proves it jammed.
  const auto eps = [](unsigned k) {
    Q e(1, 3);
    mpq_div_2exp(e.get_mpq_t(), e.get_mpq_t(), k);
    return e;
  };
  EXPECT_EQ(solve(tiny_gap(eps(80)), Arith::kFloat).status, UcpStatus::kSolvable);
  for (unsigned k : {10u, 80u, 200u, 600u}) {
    const UcpProblem p = tiny_gap(eps(k));
    expect_certified_like_exact(p, "k = " + std::to_string(k));
    const UcpReport a = solve(p, Arith::kAdaptive);
    EXPECT_EQ(a.status, UcpStatus::kJammed);
    if (k == 10) {
      EXPECT_EQ(a.decided_by, "double");
    } else {
      EXPECT_NE(a.decided_by, "double");
    }
  }
}

}  // namespace
}  // namespace contactcert::solvers::ucp
