// The integer route of recover and check_conditions (recovery.h) against a plain rational reference: the same
// PhysicalSolution in lowest terms and the same violations, on the paper's data sets, random problems, numbers
// beyond 128 bits (the GMP route) and corrupted solutions.
#include <gtest/gtest.h>

#include <random>

#include "exact/linalg.h"
#include "runtime/scenes.h"
#include "solvers/ucp/bilinear.h"
#include "solvers/ucp/recovery.h"
#include "solvers/ucp/solve.h"
#include "tests/solvers/ucp/random_problems.h"

namespace contactcert::solvers::ucp {
namespace {

using exact::Z;
using Index = Eigen::Index;

std::string scene(int k) {
  return contactcert::runtime::bundled_scenes_dir() + "/pang1994_dataset" + std::to_string(k) + ".json";
}

/// PhysicalSolution's vectors as Eigen vectors over Q, for the reference and for corrupting solutions.
struct Physics {
  Vec<Q> c_n, c_t, v_n, v_t, q_dot, theta_dot, tau;
  Physics() = default;
  explicit Physics(const PhysicalSolution& s)
      : c_n(s.c_n.to_q()),
        c_t(s.c_t.to_q()),
        v_n(s.v_n.to_q()),
        v_t(s.v_t.to_q()),
        q_dot(s.q_dot.to_q()),
        theta_dot(s.theta_dot.to_q()),
        tau(s.tau.to_q()) {}
  PhysicalSolution exact() const {
    using exact::RationalVector;
    return {RationalVector(c_n),   RationalVector(c_t),       RationalVector(v_n), RationalVector(v_t),
            RationalVector(q_dot), RationalVector(theta_dot), RationalVector(tau)};
  }
};

/// v with entry i replaced by value.
void change(exact::RationalVector& v, Index i, const Q& value) {
  Vec<Q> q = v.to_q();
  q(i) = value;
  v = exact::RationalVector(q);
}

// The reference: the proof of Proposition 1 and conditions (2)-(10) written with Eigen products over Q.
std::optional<PhysicalSolution> reference_recover(const QuasistaticProblem& p, const Vec<Q>& x, const Vec<Q>& y) {
  const Index nc = p.nc, nq = p.nq;
  Physics s;
  s.v_n = x.segment(0, nc);
  s.v_t = x.segment(nc, nc) - x.segment(2 * nc, nc);
  s.c_n = y.segment(0, nc);
  s.c_t = Vec<Q>(nc);
  for (Index i = 0; i < nc; ++i) s.c_t(i) = y(nc + i) - p.mu(i) * s.c_n(i);
  Vec<Q> v(2 * nc);
  v << s.v_n, s.v_t;
  const std::optional<Vec<Q>> b = exact::solve<Q>(p.P, Vec<Q>(v + p.J_alpha_theta_alpha()));
  if (!b) return std::nullopt;
  s.q_dot = b->segment(0, nq);
  s.theta_dot = p.theta_dot;
  for (std::size_t k = 0; k < p.abar.size(); ++k) s.theta_dot(p.abar[k]) = -(*b)(nq + static_cast<Index>(k));
  s.tau = p.Jn.transpose() * s.c_n + p.Jt.transpose() * s.c_t;
  return s.exact();
}

std::vector<std::string> reference_violations(const QuasistaticProblem& p, const PhysicalSolution& exact_s) {
  const Physics s(exact_s);
  std::vector<std::string> out;
  const Index nc = p.nc;
  const Mat<Q> Wn = p.Wn(), Wt = p.Wt();
  const Vec<Q> r2 = Wn * s.c_n + Wt * s.c_t + p.g_obj();
  for (Index k = 0; k < r2.size(); ++k)
    if (sgn(r2(k)) != 0) out.push_back("(2) equilibrium row " + std::to_string(k) + " is not zero");
  const Vec<Q> r3 = p.Jn.transpose() * s.c_n + p.Jt.transpose() * s.c_t - s.tau;
  for (Index k = 0; k < r3.size(); ++k)
    if (sgn(r3(k)) != 0) out.push_back("(3) joint " + std::to_string(k) + " equilibrium fails");
  for (std::size_t k = 0; k < p.abar.size(); ++k)
    if (s.tau(p.abar[k]) != -p.d(nc + p.nq + static_cast<Index>(k)))
      out.push_back("(3) joint " + std::to_string(p.abar[k]) + " does not carry its given effort");
  for (int j : p.alpha)
    if (s.theta_dot(j) != p.theta_dot(j))
      out.push_back("theta_dot of joint " + std::to_string(j) + " differs from its given value");
  const Vec<Q> r4 = Wn.transpose() * s.q_dot - p.Jn * s.theta_dot - s.v_n;
  const Vec<Q> r5 = Wt.transpose() * s.q_dot - p.Jt * s.theta_dot - s.v_t;
  for (Index i = 0; i < nc; ++i) {
    const std::string c = " contact " + std::to_string(i);
    if (sgn(r4(i)) != 0) out.push_back("(4)" + c + ": v_n != Wn^T q_dot - Jn theta_dot");
    if (sgn(r5(i)) != 0) out.push_back("(5)" + c + ": v_t != Wt^T q_dot - Jt theta_dot");
    if (sgn(s.v_n(i)) < 0) out.push_back("(6)" + c + ": v_n < 0");
    const Q bound = p.mu(i) * s.c_n(i);
    if (abs(s.c_t(i)) > bound) out.push_back("(7)" + c + ": |c_t| > mu c_n");
    if (sgn(s.c_n(i)) > 0 && sgn(s.v_n(i)) != 0) out.push_back("(8)" + c + ": c_n > 0 but v_n != 0");
    if (sgn(s.v_n(i)) > 0 && (sgn(s.c_n(i)) != 0 || sgn(s.c_t(i)) != 0))
      out.push_back("(9)" + c + ": v_n > 0 but c != 0");
    if (sgn(s.v_t(i)) > 0 && s.c_t(i) != -bound) out.push_back("(10)" + c + ": v_t > 0 but c_t != -mu c_n");
    if (sgn(s.v_t(i)) < 0 && s.c_t(i) != bound) out.push_back("(10)" + c + ": v_t < 0 but c_t != mu c_n");
  }
  return out;
}

/// Equal values, each in lowest terms with a positive denominator (the same numerator and denominator).
void expect_same(const Vec<Q>& got, const Vec<Q>& want, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (Index i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got(i), want(i)) << what << "(" << i << ")";
    Q canonical = got(i);
    canonical.canonicalize();
    EXPECT_EQ(mpz_cmp(got(i).get_num_mpz_t(), canonical.get_num_mpz_t()), 0) << what << "(" << i << ")";
    EXPECT_EQ(mpz_cmp(got(i).get_den_mpz_t(), canonical.get_den_mpz_t()), 0) << what << "(" << i << ")";
  }
}

void expect_same(const exact::RationalVector& got, const exact::RationalVector& want, const std::string& what) {
  expect_same(got.to_q(), want.to_q(), what);
}

void expect_same(const PhysicalSolution& got, const PhysicalSolution& want, const std::string& where) {
  expect_same(got.c_n, want.c_n, where + " c_n");
  expect_same(got.c_t, want.c_t, where + " c_t");
  expect_same(got.v_n, want.v_n, where + " v_n");
  expect_same(got.v_t, want.v_t, where + " v_t");
  expect_same(got.q_dot, want.q_dot, where + " q_dot");
  expect_same(got.theta_dot, want.theta_dot, where + " theta_dot");
  expect_same(got.tau, want.tau, where + " tau");
}

/// recover and check_conditions agree with the reference on (x, y); returns how many violations there were.
std::size_t expect_as_reference(const QuasistaticProblem& p, const Vec<Q>& x, const Vec<Q>& y,
                                const std::string& where) {
  const std::optional<PhysicalSolution> want = reference_recover(p, x, y), got = recover(p, x, y);
  EXPECT_EQ(got.has_value(), want.has_value()) << where;
  if (!got || !want) return 0;
  expect_same(*got, *want, where);
  const ConditionsCheck c = check_conditions(p, *got);
  const std::vector<std::string> violations = reference_violations(p, *want);
  EXPECT_EQ(c.violations, violations) << where;
  EXPECT_EQ(c.status, violations.empty() ? ConditionsStatus::kSatisfied : ConditionsStatus::kViolated) << where;
  return violations.size();
}

/// The best pair of the bilinear algorithm from a seeded start: x in X and y in Y, complementary or not.
std::pair<Vec<Q>, Vec<Q>> bilinear_pair(const UcpProblem& p, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  BilinearOptions o;
  o.arith = Arith::kExact;
  o.max_random_moves = 2;
  const BilinearResult<Q> r = bilinear(make_face(p.ucp().X, {}), make_face(p.ucp().Y, {}), o, rng);
  return {r.x.x, r.y.x};
}

std::pair<Vec<Q>, Vec<Q>> solved_pair(const UcpProblem& p, Arith arith) {
  UcpOptions o;
  o.arith = arith;
  const UcpReport r = solve_ucp(p, o);
  EXPECT_EQ(r.status, UcpStatus::kSolvable);
  return {r.x->to_q(), r.y->to_q()};
}

TEST(UcpRecovery, PaperDataSetsMatchTheRationalReference) {
  for (int k = 1; k <= 4; ++k) {
    const UcpProblem p = load_ucp_problem(scene(k));
    const std::string where = "data set " + std::to_string(k);
    if (k < 4) {
      for (Arith a : {Arith::kExact, Arith::kAdaptive}) {
        const auto [x, y] = solved_pair(p, a);
        EXPECT_EQ(expect_as_reference(*p.quasistatic, x, y, where), 0u) << where;
      }
    }
    // Data Set 4 is jammed: its best bilinear pairs are in X and Y but not complementary.
    std::size_t violated = 0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const auto [x, y] = bilinear_pair(p, seed);
      violated += expect_as_reference(*p.quasistatic, x, y, where + " seed " + std::to_string(seed));
    }
    if (k == 4) {
      EXPECT_GT(violated, 0u);
    }
  }
}

TEST(UcpRecovery, RandomProblemsMatchTheRationalReference) {
  int with_abar = 0, violated = 0;
  for (int seed = 0; seed < 60; ++seed) {
    const UcpProblem p = testing::random_problem(seed, 5);
    with_abar += !p.quasistatic->abar.empty();
    const auto [x, y] = bilinear_pair(p, static_cast<std::uint64_t>(seed));
    violated += expect_as_reference(*p.quasistatic, x, y, "seed " + std::to_string(seed)) > 0;
  }
  EXPECT_GT(with_abar, 30);
  EXPECT_GT(violated, 0);
}

/// The same problem in scaled object coordinates: q = S q' with S = diag(s), so W' = S W, P' = P diag(S, I) and
/// g_obj' = S g_obj. X and Y are the same sets, q_dot' = S^-1 q_dot, and everything else is unchanged.
QuasistaticProblem scale_object(QuasistaticProblem p, const std::vector<Q>& s) {
  for (Index k = 0; k < p.nq; ++k) {
    p.P.col(k) *= s[static_cast<std::size_t>(k)];
    p.d(p.nc + k) *= s[static_cast<std::size_t>(k)];
  }
  validate(p);
  return p;
}

/// Scales of the three object coordinates with denominators near 2^71.
std::vector<Q> wide_scales() {
  std::vector<Q> s;
  for (unsigned long k = 0; k < 3; ++k) {
    Z num, den;
    mpz_ui_pow_ui(den.get_mpz_t(), 3, 45);
    mpz_ui_pow_ui(num.get_mpz_t(), 2, 70);
    s.push_back(Q(num + 2 * k + 1, den + k));
    s.back().canonicalize();
  }
  return s;
}

TEST(UcpRecovery, NumbersBeyond128BitsTakeTheGmpRouteWithTheSameResult) {
  const UcpProblem p1 = load_ucp_problem(scene(1));
  const auto [x, y] = solved_pair(p1, Arith::kExact);
  const PhysicalSolution s1 = *recover(*p1.quasistatic, x, y);
  const std::vector<Q> s = wide_scales();
  const QuasistaticProblem p = scale_object(*p1.quasistatic, s);
  // A row of P over its common denominator needs more than 128 bits: the Int128 route cannot hold it.
  Z lcm = 1;
  for (Index j = 0; j < p.P.cols(); ++j) mpz_lcm(lcm.get_mpz_t(), lcm.get_mpz_t(), p.P(0, j).get_den_mpz_t());
  ASSERT_GT(mpz_sizeinbase(lcm.get_mpz_t(), 2), 128u);
  EXPECT_EQ(expect_as_reference(p, x, y, "scaled data set 1"), 0u);
  // Independently: q_dot' = S^-1 q_dot, and the rest as in the unscaled problem.
  const PhysicalSolution got = *recover(p, x, y);
  for (Index k = 0; k < 3; ++k) {
    const Q want = s1.q_dot(k) / s[static_cast<std::size_t>(k)];
    EXPECT_EQ(got.q_dot(k), want);
  }
  expect_same(got.tau, s1.tau, "tau");
  expect_same(got.c_t, s1.c_t, "c_t");
  // Corrupted with a denominator beyond 128 bits: the check goes to GMP and reports the same violations.
  PhysicalSolution bad = got;
  Z big;
  mpz_ui_pow_ui(big.get_mpz_t(), 2, 130);
  change(bad.c_t, 1, bad.c_t(1) + Q(1) / Q(big + 1));
  const std::vector<std::string> want = reference_violations(p, bad);
  EXPECT_EQ(check_conditions(p, bad).violations, want);
  EXPECT_FALSE(want.empty());
}

TEST(UcpRecovery, CorruptedSolutionsReportTheSameViolations) {
  const UcpProblem p1 = load_ucp_problem(scene(1));
  const QuasistaticProblem& p = *p1.quasistatic;
  const auto [x, y] = solved_pair(p1, Arith::kExact);
  const PhysicalSolution s = *recover(p, x, y);
  ASSERT_EQ(check_conditions(p, s).status, ConditionsStatus::kSatisfied);
  auto expect_violations = [&](const PhysicalSolution& bad, const std::vector<std::string>& expected) {
    const ConditionsCheck c = check_conditions(p, bad);
    EXPECT_EQ(c.status, ConditionsStatus::kViolated);
    EXPECT_EQ(c.violations, reference_violations(p, bad));
    for (const std::string& e : expected)
      EXPECT_NE(std::find(c.violations.begin(), c.violations.end(), e), c.violations.end()) << e;
  };
  PhysicalSolution bad = s;
  change(bad.v_n, 1, Q(-1));
  expect_violations(bad, {"(4) contact 1: v_n != Wn^T q_dot - Jn theta_dot", "(6) contact 1: v_n < 0"});
  bad = s;
  change(bad.theta_dot, 0, bad.theta_dot(0) + Q(1, 3));
  expect_violations(
      bad, {"theta_dot of joint 0 differs from its given value", "(4) contact 0: v_n != Wn^T q_dot - Jn theta_dot"});
  bad = s;
  change(bad.tau, 2, bad.tau(2) + 1);
  expect_violations(bad, {"(3) joint 2 equilibrium fails"});
  bad = s;
  change(bad.c_t, 0, bad.c_t(0) + Q(1, 7));
  expect_violations(bad, {"(2) equilibrium row 0 is not zero", "(3) joint 1 equilibrium fails"});
  bad = s;
  change(bad.q_dot, 0, bad.q_dot(0) + Q(2, 9));
  expect_violations(bad, {"(4) contact 0: v_n != Wn^T q_dot - Jn theta_dot"});
  bad = s;
  for (Index i = 0; i < p.nc; ++i) {
    change(bad.c_t, i, 2 * p.mu(i) * bad.c_n(i));
    change(bad.v_t, i, Q(1 - 2 * (i % 2)));
  }
  expect_violations(bad, {"(7) contact 0: |c_t| > mu c_n"});
  // A pair whose y is not in Y: its forces miss (2); an x off X has no q_dot at all.
  Vec<Q> y_bad = y;
  y_bad(0) += Q(5, 11);
  EXPECT_GT(expect_as_reference(p, x, y_bad, "y off Y"), 0u);
  Vec<Q> x_bad = x;
  x_bad(1) += Q(1, 13);
  EXPECT_FALSE(recover(p, x_bad, y).has_value());
  EXPECT_FALSE(reference_recover(p, x_bad, y).has_value());
}

/// x in P = {x >= 0 : A x = b} with x_j = 0 where zero[j], exactly.
void expect_in_face(const StandardPolyhedron<Q>& P, const Vec<Q>& x, const std::vector<bool>& zero,
                    const std::string& where) {
  ASSERT_EQ(x.size(), P.A.cols()) << where;
  EXPECT_EQ(Vec<Q>(P.A * x), P.b) << where;
  for (Index j = 0; j < x.size(); ++j) {
    EXPECT_GE(sgn(x(j)), 0) << where << " entry " << j;
    if (zero[static_cast<std::size_t>(j)]) {
      EXPECT_EQ(sgn(x(j)), 0) << where << " entry " << j;
    }
  }
}

/// The zero patterns of a complementary pair as the adaptive path reads them off a float pair: x's zeros, and
/// y's zeros plus every index where x is not zero.
std::pair<std::vector<bool>, std::vector<bool>> patterns(const Vec<Q>& x, const Vec<Q>& y) {
  std::vector<bool> xz(static_cast<std::size_t>(x.size())), yz = xz;
  for (Index i = 0; i < x.size(); ++i) {
    xz[static_cast<std::size_t>(i)] = sgn(x(i)) == 0;
    yz[static_cast<std::size_t>(i)] = sgn(x(i)) != 0 || sgn(y(i)) == 0;
  }
  return {xz, yz};
}

/// pattern_solution on the patterns of (x, y): if it succeeds, a complementary pair in X and Y with those patterns
/// whose physics is recover's and satisfies (2)-(10). Returns whether it succeeded.
bool expect_pattern_route(const UcpProblem& p, const Vec<Q>& x, const Vec<Q>& y, const std::string& where) {
  const QuasistaticProblem& q = *p.quasistatic;
  const auto [xz, yz] = patterns(x, y);
  const std::optional<PatternSolution> s = pattern_solution(q, xz, yz);
  if (!s) return false;
  const Vec<Q> xs = s->x.to_q(), ys = s->y.to_q();
  expect_in_face(p.ucp().X, xs, xz, where + " x");
  expect_in_face(p.ucp().Y, ys, yz, where + " y");
  EXPECT_EQ(xs.dot(ys), 0) << where;
  const std::optional<PhysicalSolution> want = recover(q, xs, ys);
  EXPECT_TRUE(want.has_value()) << where;
  if (want) expect_same(s->physical, *want, where);
  EXPECT_EQ(check_conditions(q, s->physical).violations, std::vector<std::string>()) << where;
  EXPECT_EQ(s->conditions.status, ConditionsStatus::kSatisfied) << where;
  EXPECT_EQ(s->conditions.violations, std::vector<std::string>()) << where;
  return true;
}

TEST(UcpRecovery, PatternRouteGivesAComplementaryPairWithItsPhysics) {
  for (int k = 1; k <= 3; ++k) {
    const UcpProblem p = load_ucp_problem(scene(k));
    const auto [x, y] = solved_pair(p, Arith::kExact);
    EXPECT_TRUE(expect_pattern_route(p, x, y, "data set " + std::to_string(k)));
  }
  int solved = 0, routed = 0, with_abar = 0;
  for (int seed = 0; seed < 60; ++seed) {
    const UcpProblem p = testing::random_problem(seed, 5);
    UcpOptions o;
    o.arith = Arith::kVerified;
    const UcpReport r = solve_ucp(p, o);
    if (r.status != UcpStatus::kSolvable) continue;
    ++solved;
    const bool ok = expect_pattern_route(p, r.x->to_q(), r.y->to_q(), "seed " + std::to_string(seed));
    routed += ok;
    with_abar += ok && !p.quasistatic->abar.empty();
  }
  // The search's pairs are vertices: their patterns fix u and c (P of full column rank, no degenerate vertex).
  EXPECT_GT(solved, 20);
  EXPECT_GT(routed, solved * 3 / 4);
  EXPECT_GT(with_abar, 0);
}

TEST(UcpRecovery, PatternRouteRefusesPatternsThatDoNotFixTheSolution) {
  const UcpProblem p = load_ucp_problem(scene(1));
  const QuasistaticProblem& q = *p.quasistatic;
  const auto [x, y] = solved_pair(p, Arith::kExact);
  const auto [xz, yz] = patterns(x, y);
  const Index nc = q.nc;
  ASSERT_TRUE(pattern_solution(q, xz, yz).has_value());
  // Nothing fixed: u is free.
  EXPECT_FALSE(pattern_solution(q, std::vector<bool>(xz.size(), false), yz).has_value());
  // A sliding contact with the sign of its slip swapped in the pattern (v_t^+ fixed to 0 where v_t > 0, or v_t^-
  // where v_t < 0): the same rows fix the same u, but v_t does not fit the pattern.
  Index sliding = -1;
  for (Index i = 0; i < nc; ++i)
    if (sgn(x(nc + i)) != 0 || sgn(x(2 * nc + i)) != 0) sliding = i;
  ASSERT_GE(sliding, 0);
  std::vector<bool> wrong = xz;
  wrong[static_cast<std::size_t>(nc + sliding)] = xz[static_cast<std::size_t>(2 * nc + sliding)];
  wrong[static_cast<std::size_t>(2 * nc + sliding)] = xz[static_cast<std::size_t>(nc + sliding)];
  EXPECT_FALSE(pattern_solution(q, wrong, yz).has_value());
  // Every contact force fixed to 0 under a load: (2) has no solution.
  std::vector<bool> no_force = yz;
  for (Index i = 0; i < nc; ++i) no_force[static_cast<std::size_t>(i)] = true;
  EXPECT_FALSE(pattern_solution(q, xz, no_force).has_value());
  // Friction set free at every contact: c_t is then an unknown too, and (2) with nq = 3 rows cannot fix 2 nc = 6
  // unknowns.
  std::vector<bool> free_friction = yz;
  for (Index i = 0; i < nc; ++i)
    free_friction[static_cast<std::size_t>(nc + i)] = free_friction[static_cast<std::size_t>(2 * nc + i)] = false;
  EXPECT_FALSE(pattern_solution(q, xz, free_friction).has_value());
}

TEST(UcpRecovery, PatternRouteBeyond128BitsTakesTheGmpRoute) {
  const UcpProblem p1 = load_ucp_problem(scene(1));
  const auto [x, y] = solved_pair(p1, Arith::kExact);
  const std::vector<Q> s = wide_scales();
  UcpProblem p;
  p.quasistatic = scale_object(*p1.quasistatic, s);
  p.set(build_ucp(*p.quasistatic));
  EXPECT_TRUE(expect_pattern_route(p, x, y, "scaled data set 1"));
}

TEST(UcpRecovery, RandomCorruptionsOfRandomSolutionsReportTheSameViolations) {
  std::mt19937_64 rng(7);
  int with_abar_effort = 0;
  for (int seed = 0; seed < 40; ++seed) {
    const UcpProblem p = testing::random_problem(seed, 4);
    const QuasistaticProblem& q = *p.quasistatic;
    const auto [x, y] = bilinear_pair(p, static_cast<std::uint64_t>(seed));
    const PhysicalSolution s = *recover(q, x, y);
    for (int t = 0; t < 10; ++t) {
      PhysicalSolution bad = s;
      exact::RationalVector* parts[] = {&bad.c_n, &bad.c_t, &bad.v_n, &bad.v_t, &bad.q_dot, &bad.theta_dot, &bad.tau};
      exact::RationalVector& v = *parts[rng() % 7];
      // The denominator is drawn first, as gcc evaluated the two constructor arguments (right to left).
      const auto den = static_cast<unsigned long>(1 + rng() % 50);
      Q delta(static_cast<long>(rng() % 7) - 3, den);
      delta.canonicalize();
      const auto at = static_cast<Index>(rng() % static_cast<std::uint64_t>(v.size()));
      change(v, at, v(at) + delta);
      const std::vector<std::string> want = reference_violations(q, bad);
      const ConditionsCheck c = check_conditions(q, bad);
      EXPECT_EQ(c.violations, want) << "seed " << seed;
      for (const std::string& w : want) with_abar_effort += w.find("does not carry its given effort") != w.npos;
    }
  }
  EXPECT_GT(with_abar_effort, 0);
}

}  // namespace
}  // namespace contactcert::solvers::ucp
