// --arith adaptive for the UCP: every verdict equals the exact one and carries exact evidence that the
// independent checker accepts; the ladder climbs when a float rung's verdict does not check out.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "checker/ucp_check.h"
#include "exact/integer_system.h"
#include "exact/json_input.h"
#include "exact/rounded_check.h"
#include "runtime/scenes.h"
#include "solvers/ucp/certificate.h"
#include "solvers/ucp/face_lp.h"
#include "solvers/ucp/farkas_rounding.h"
#include "solvers/ucp/float_check.h"
#include "solvers/ucp/generate.h"
#include "solvers/ucp/solve.h"
#include "tests/solvers/ucp/random_problems.h"

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
    text = solvable_certificate(p, a.x->to_q(), a.y->to_q());
  } else {
    ASSERT_EQ(a.status, UcpStatus::kJammed) << what;
    ASSERT_TRUE(a.proof) << what;
    text = jammed_certificate(p, *a.proof);
  }
  const checker::CertificateCheck c = checker::check_ucp_certificate(exact::JsonInput::parse(text, "certificate"));
  EXPECT_EQ(c.verdict, checker::CertificateVerdict::kValid) << what << ": " << c.reason;
}

TEST(UcpAdaptive, RandomProblemsGetTheExactVerdictWithACertificate) {
  std::map<std::string, int> rungs;
  for (int seed = 0; seed < 30; ++seed) {
    const UcpProblem p = testing::random_problem(seed, 4);
    expect_certified_like_exact(p, "random seed " + std::to_string(seed));
    ++rungs[solve(p, Arith::kAdaptive).decided_by];
  }
  // Well-scaled problems mostly need no more than doubles (27 of 30 with these seeds: a float search tree
  // whose leaves do not all check out sends the problem up the ladder).
  EXPECT_GE(rungs["double"], 25);
}

// Issue 18: --arith verified follows the float path and only checks it (nc = 10 seed 5 once took 240 LPs verified
// against 4 in floats); its verdicts are the exact ones.
TEST(UcpAdaptive, VerifiedTakesNoMoreLpsThanFloat) {
  for (int seed = 0; seed < 60; ++seed) {
    const UcpProblem p = testing::random_problem(seed, 10);
    const UcpReport f = solve(p, Arith::kFloat), v = solve(p, Arith::kVerified);
    EXPECT_LE(v.lps, f.lps) << "random seed " << seed;
    EXPECT_EQ(v.status, solve(p, Arith::kAdaptive).status) << "random seed " << seed;
  }
  std::mt19937_64 rng(5);
  RandomProblemOptions o;
  o.nc = 10;
  const UcpProblem p = generate_random_problem(o, rng);
  EXPECT_LE(solve(p, Arith::kVerified).lps, solve(p, Arith::kFloat).lps);
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
  UcpInstance<Q> ucp;
  ucp.X.A = Mat<Q>(1, 2);
  ucp.X.A << 1, -1;
  ucp.X.b = Vec<Q>::Constant(1, -eps);
  ucp.Y.A = Mat<Q>(1, 2);
  ucp.Y.A << 0, 1;
  ucp.Y.b = Vec<Q>::Constant(1, Q(1));
  p.set(ucp);
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

/// The exact search tree of tiny_gap(eps): branch on index 1; x_1 = 0 leaves x_0 = -eps (X empty, Farkas
/// vector (1)), y_1 = 0 contradicts y_1 = 1 (Y empty, Farkas vector (-1)). `farkas` are the float vectors
/// the leaves carry.
FloatTree tiny_gap_tree(double fx, double fy) {
  FloatTree t;
  t.nodes.resize(3);
  t.nodes[0].branch = 1, t.nodes[0].child_x_zero = 1, t.nodes[0].child_y_zero = 2;
  t.nodes[1].side = Side::kX, t.nodes[2].side = Side::kY;
  t.farkas = {Vec<double>(), Vec<double>::Constant(1, fx), Vec<double>::Constant(1, fy)};
  return t;
}

void expect_valid_jammed_certificate(const UcpProblem& p, SearchResult<Q> proof) {
  proof.status = UcpStatus::kJammed;
  proof.reason = "search tree";
  const checker::CertificateCheck c =
      checker::check_ucp_certificate(exact::JsonInput::parse(jammed_certificate(p, proof), "certificate"));
  EXPECT_EQ(c.verdict, checker::CertificateVerdict::kValid) << c.reason;
}

TEST(UcpAdaptive, LeavesAreProvenByTheirRoundedFarkasVectorsElseByAnExactLp) {
  const UcpProblem p = tiny_gap(Q(1, 3));
  // Float Farkas vectors near exact ones: rounded and checked in integers, no LP.
  ProvenTree good = prove_leaves(p, tiny_gap_tree(1.0000000000001, -1), std::nullopt);
  ASSERT_EQ(good.result.status, UcpStatus::kJammed);
  EXPECT_EQ(good.result.counters.lps, 0);
  EXPECT_EQ(good.leaves.repaired, 0);
  EXPECT_EQ(good.leaves.rounded, good.leaves.total() - good.leaves.reused);
  expect_valid_jammed_certificate(p, good.result);
  // Float vectors that prove nothing (wrong sign): each leaf falls back to an exact face LP.
  ProvenTree bad = prove_leaves(p, tiny_gap_tree(-1, 1), std::nullopt);
  ASSERT_EQ(bad.result.status, UcpStatus::kJammed);
  EXPECT_EQ(bad.result.counters.lps, 2);
  EXPECT_EQ(bad.leaves.repaired, 0);
  EXPECT_EQ(bad.leaves.lp, 2);
  expect_valid_jammed_certificate(p, bad.result);
}

TEST(UcpAdaptive, ALeafWhoseFaceIsNotEmptyIsRepairedByAnExactSearchBelowIt) {
  const UcpProblem jammed = tiny_gap(Q(1, 3));
  // A float tree that calls the root a leaf with X empty: X is not empty, the float vector fails.
  FloatTree root;
  root.nodes.resize(1);
  root.farkas = {Vec<double>::Constant(1, 1)};
  EXPECT_EQ(prove_leaves(jammed, root, std::nullopt).result.status, UcpStatus::kUnknown);
  ProvenTree repaired = prove_leaves(jammed, root, SearchOptions{});
  ASSERT_EQ(repaired.result.status, UcpStatus::kJammed);
  EXPECT_EQ(repaired.leaves.repaired, 1);
  EXPECT_GE(repaired.result.tree.size(), 3u);
  expect_valid_jammed_certificate(jammed, repaired.result);
  // The same wrong leaf on a solvable problem (eps = -1/3: x = (1/3, 0), y = (0, 1)): the repair finds the
  // exactly complementary pair.
  const UcpProblem solvable = tiny_gap(Q(-1, 3));
  ProvenTree found = prove_leaves(solvable, root, SearchOptions{});
  ASSERT_EQ(found.result.status, UcpStatus::kSolvable);
  EXPECT_EQ(found.leaves.repaired, 1);
  EXPECT_EQ(solvable.ucp().X.A * found.result.x, solvable.ucp().X.b);
  EXPECT_EQ(solvable.ucp().Y.A * found.result.y, solvable.ucp().Y.b);
  EXPECT_EQ(found.result.x.dot(found.result.y), 0);
}

TEST(UcpAdaptive, IntegerChecksThatOverflow128BitsRestartInGmp) {
  // X = {x in R^3_+ : a x_0 + a x_1 = 2^126} with a = 3 2^125 (fits in 128 bits): the rounded point
  // (1/3, 1/3, 0) gives a 1 + a 1 = 3 2^126 = 3 (2^126), beyond 128 bits on both sides; Y = {y in R^3_+ : y_2 = 1}.
  UcpProblem p;
  Q a = 3, b = 1;
  mpq_mul_2exp(a.get_mpq_t(), a.get_mpq_t(), 125);
  mpq_mul_2exp(b.get_mpq_t(), b.get_mpq_t(), 126);
  UcpInstance<Q> ucp;
  ucp.X.A = Mat<Q>(1, 3);
  ucp.X.A << a, a, 0;
  ucp.X.b = Vec<Q>::Constant(1, b);
  ucp.Y.A = Mat<Q>(1, 3);
  ucp.Y.A << 0, 0, 1;
  ucp.Y.b = Vec<Q>::Constant(1, Q(1));
  p.set(ucp);
  Vec<double> x(3), y(3);
  x << 1.0 / 3, 1.0 / 3, 0;
  y << 0, 0, 1;
  LpCounters count;
  const auto pair = exact_pair(p, x, y, {false, false, true}, {true, true, false}, count);
  ASSERT_TRUE(pair);
  EXPECT_EQ(count.lps, 0);  // checked in integers (in GMP after the 128-bit overflow), no LP
  EXPECT_EQ(pair->first(0), Q(1, 3));
  EXPECT_EQ(pair->first(1), Q(1, 3));
}

TEST(UcpAdaptive, PaperDataSetsAreDecidedInDoubleWithoutARepairedLeaf) {
  // Data Set 4's X has rows of size 1e9 (the left null space of P): before the float simplex equilibrated such
  // rows, a phase-1 residual of rounding size called a non-empty face empty (with a zero Farkas vector) and
  // the adaptive check had to repair that leaf with an exact search.
  for (int k = 1; k <= 4; ++k) {
    const UcpProblem p = load_ucp_problem(contactcert::runtime::bundled_scenes_dir() + "/pang1994_dataset" +
                                          std::to_string(k) + ".json");
    const std::string what = "Data Set " + std::to_string(k);
    expect_certified_like_exact(p, what);
    const UcpReport a = solve(p, Arith::kAdaptive);
    EXPECT_EQ(a.decided_by, "double") << what;
    EXPECT_EQ(a.leaves.repaired, 0) << what;
  }
}

TEST(UcpAdaptive, ALeafIsProvenFromItsFloatLpBasisWhenRoundingFails) {
  // X = {x in R^2_+ : x0 + x1 = 1, x0 + x1 = 2} is empty, Farkas vector (1, -1); Y = {y in R^2_+ : y0 + y1 = 1}.
  UcpProblem p;
  UcpInstance<Q> ucp;
  ucp.X.A = Mat<Q>(2, 2);
  ucp.X.A << 1, 1, 1, 1;
  ucp.X.b = Vec<Q>(2);
  ucp.X.b << 1, 2;
  ucp.Y.A = Mat<Q>(1, 2);
  ucp.Y.A << 1, 1;
  ucp.Y.b = Vec<Q>::Constant(1, Q(1));
  p.set(ucp);
  LpCounters count;
  const FaceLpResult<double> f =
      minimize_on_face(make_face(to_double(p.rows()).X, {}), Vec<double>(Vec<double>::Zero(2)), Arith::kFloat, count);
  ASSERT_EQ(f.status, FaceLpStatus::kEmpty);
  ASSERT_EQ(f.farkas_basis.size(), 2u);
  // A float vector 1e-7 off: its rounding has y^T A_0 < 0, so only the basis proves the leaf without an LP.
  FloatTree root;
  root.nodes.resize(1);
  root.nodes[0].farkas_basis = f.farkas_basis;
  root.farkas = {f.farkas};
  root.farkas[0](1) *= 1 + 1e-7;
  const ProvenTree proven = prove_leaves(p, root, std::nullopt);
  ASSERT_EQ(proven.result.status, UcpStatus::kJammed);
  EXPECT_EQ(proven.result.counters.lps, 0);
  expect_valid_jammed_certificate(p, proven.result);
  // Without the basis the leaf needs an exact face LP.
  root.nodes[0].farkas_basis.clear();
  const ProvenTree by_lp = prove_leaves(p, root, std::nullopt);
  ASSERT_EQ(by_lp.result.status, UcpStatus::kJammed);
  EXPECT_EQ(by_lp.result.counters.lps, 1);
}

TEST(UcpAdaptive, VertexOfDataSet1IsSolvedIn128BitsWithoutOverflow) {
  // X of Data Set 1 has rows of size 3e8 (b scaled by 50): Cramer's rule by back substitution needed 136-bit
  // products; after dividing out column contents the fraction-free Gauss-Jordan stays within 66 bits.
  const UcpProblem p = load_ucp_problem(contactcert::runtime::bundled_scenes_dir() + "/pang1994_dataset1.json");
  const std::vector<Eigen::Index> support{2, 6, 8};
  const exact::RationalRows rows = exact::rational_rows(p.ucp().X.A(Eigen::all, support), p.ucp().X.b);
  std::optional<Vec<Q>> x;
  ASSERT_NO_THROW(x = exact::unique_solution(exact::integer_system<exact::Int128>(rows)));
  ASSERT_TRUE(x);
  const auto z = exact::unique_solution(exact::integer_system<exact::Z>(rows));
  ASSERT_TRUE(z);
  EXPECT_EQ(*x, *z);
  Vec<Q> full = Vec<Q>::Zero(9);
  for (std::size_t t = 0; t < support.size(); ++t) full(support[t]) = (*x)(static_cast<Eigen::Index>(t));
  EXPECT_EQ(p.ucp().X.A * full, p.ucp().X.b);
}

TEST(UcpAdaptive, LeavesOfALargeJammedTreeAreProvenFromTheirBasesWithoutAnLp) {
  // nc = 40, seed 4 (section 5 generator, as `ucp --generate random --nc 40 --seed 4`): 26 float leaves, most of
  // whose rounded vectors fail; each basis system (X's rows: sparse but for the columns of P's pivots) is
  // solved by singleton elimination and a small core, with no exact face LP.
  std::mt19937_64 rng(4);
  RandomProblemOptions o;
  o.nc = 40;
  const UcpProblem p = generate_random_problem(o, rng);
  const UcpReport v = solve(p, Arith::kVerified);
  ASSERT_EQ(v.status, UcpStatus::kJammed);
  ASSERT_TRUE(v.proof);
  EXPECT_GT(v.leaves.basis, 0);
  EXPECT_EQ(v.leaves.lp, 0);
  EXPECT_EQ(v.leaves.total(), static_cast<long>((v.proof->tree.size() + 1) / 2));
  expect_valid_jammed_certificate(p, *v.proof);
}

}  // namespace
}  // namespace contactcert::solvers::ucp
