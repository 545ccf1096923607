#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "exact/input_error.h"
#include "exact/interval_number.h"
#include "exact/linalg.h"
#include "exact/mpfr_number.h"
#include "exact/rational_text.h"
#include "runtime/scenes.h"
#include "solvers/ucp/generate.h"
#include "solvers/ucp/problem.h"
#include "tests/solvers/ucp/random_problems.h"

namespace contactcert::solvers::ucp {
namespace {

using exact::InputError;
using exact::JsonInput;

std::string scene(int k) {
  return contactcert::runtime::bundled_scenes_dir() + "/pang1994_dataset" + std::to_string(k) + ".json";
}

Q frac(long a, long b) {
  Q q(a, b);
  q.canonicalize();
  return q;
}

UcpProblem parse(const std::string& text) { return read_ucp_problem(JsonInput::parse(text, "test.json")); }

/// A small valid problem with |abar| = 1 (joint 5), as JSON to be edited by the bad-input table.
nlohmann::json small_problem() {
  return nlohmann::json::parse(R"({
    "kind": "quasistatic", "nc": 2, "nq": 3, "ntheta": 4,
    "P": [["1","0","0","0"], ["0","1","1","0"], ["0","1","0","0"], ["-1","0","0","1"]],
    "Jn": [[1,0,0,0],[0,0,1,0]], "Jt": [[0,1,0,0],[0,0,0,1]],
    "theta_dot": ["0.5", "-1", "0.25", null],
    "alpha": [0, 1, 2],
    "d": [0, 0, "0", "-1", "0", "0.5"],
    "mu": ["0.5", "1/3"] })");
}

TEST(UcpProblem, DataSetsParseExactlyAsWrittenInThePaper) {
  const UcpProblem p1 = load_ucp_problem(scene(1));
  ASSERT_TRUE(p1.quasistatic);
  const QuasistaticProblem& q = *p1.quasistatic;
  EXPECT_EQ(q.P(0, 0), frac(966, 1000));
  EXPECT_EQ(q.P(4, 2), frac(-145, 100));
  EXPECT_EQ(q.theta_dot(1), frac(995, 1000));
  EXPECT_EQ(q.Jn(2, 4), 1);  // erratum: the third row of Jn is [0 0 0 0 1 0]
  EXPECT_EQ(q.g_obj(), (Vec<Q>(3) << 0, -1, 0).finished());
  EXPECT_EQ(q.mu(2), Q(3, 10));
  EXPECT_TRUE(q.abar.empty());
  const UcpProblem p4 = load_ucp_problem(scene(4));
  EXPECT_EQ(p4.quasistatic->mu, (Vec<Q>(3) << Q(7, 10), Q(9, 10), Q(9, 10)).finished());
  EXPECT_EQ(p4.quasistatic->P, load_ucp_problem(scene(2)).quasistatic->P);
}

/// X and Y as the rational builder made them before the integer one (the oracle of
/// XAndYInIntegersEqualTheRationalOnes): Z = left_null_space<Q>(P) with rows made primitive, X = [Z B | -Z J_alpha
/// theta_alpha] by dense products, C from Wn - Wt U, rows of [C | -d] primitive.
UcpInstance<Q> rational_ucp(const QuasistaticProblem& p) {
  const Eigen::Index nc = p.nc;
  Mat<Q> Z = exact::left_null_space<Q>(p.P);
  for (Eigen::Index r = 0; r < Z.rows(); ++r) {
    const std::vector<exact::Z> row = exact::primitive(Vec<Q>(Z.row(r).transpose()));
    for (Eigen::Index c = 0; c < Z.cols(); ++c) Z(r, c) = Q(row[static_cast<std::size_t>(c)]);
  }
  Mat<Q> B = Mat<Q>::Zero(2 * nc, 3 * nc), J(2 * nc, p.ntheta);
  for (Eigen::Index i = 0; i < nc; ++i) B(i, i) = 1, B(nc + i, nc + i) = 1, B(nc + i, 2 * nc + i) = -1;
  J << p.Jn, p.Jt;
  Vec<Q> h = Vec<Q>::Zero(2 * nc);
  for (int j : p.alpha) h += J.col(j) * p.theta_dot(j);
  UcpInstance<Q> u;
  u.X.A = Z * B;
  u.X.b = -(Z * h);
  const Eigen::Index nq = p.nq, na = static_cast<Eigen::Index>(p.abar.size());
  Mat<Q> U = Mat<Q>::Zero(nc, nc), JnT(na, nc), JtT(na, nc);
  for (Eigen::Index i = 0; i < nc; ++i) U(i, i) = p.mu(i);
  for (Eigen::Index k = 0; k < na; ++k) {
    JnT.row(k) = p.Jn.col(p.abar[static_cast<std::size_t>(k)]).transpose();
    JtT.row(k) = p.Jt.col(p.abar[static_cast<std::size_t>(k)]).transpose();
  }
  Mat<Q> C = Mat<Q>::Zero(nc + nq + na, 3 * nc);
  C.block(0, 0, nc, nc) = 2 * U;
  C.block(0, nc, nc, nc) = -Mat<Q>::Identity(nc, nc);
  C.block(0, 2 * nc, nc, nc) = -Mat<Q>::Identity(nc, nc);
  C.block(nc, 0, nq, nc) = p.Wn() - p.Wt() * U;
  C.block(nc, nc, nq, nc) = p.Wt();
  if (na > 0) C.block(nc + nq, 0, na, nc) = JnT - JtT * U, C.block(nc + nq, nc, na, nc) = JtT;
  u.Y.A = C;
  u.Y.b = -p.d;
  for (Eigen::Index r = 0; r < C.rows(); ++r) {
    Vec<Q> row(C.cols() + 1);
    row << C.row(r).transpose(), u.Y.b(r);
    const std::vector<exact::Z> z = exact::primitive(row);
    for (Eigen::Index c = 0; c < C.cols(); ++c) u.Y.A(r, c) = Q(z[static_cast<std::size_t>(c)]);
    u.Y.b(r) = Q(z.back());
  }
  return u;
}

/// The float rungs' instances made from the integer rows equal those converted from the rationals r, number by
/// number (double, intervals, MPFR), and so do the rows scaled to integers for the exact checks.
void expect_same_floats(const UcpProblem& u, const UcpInstance<Q>& r, const std::string& name) {
  for (const auto& [P, R] : {std::pair(&u.rows().X, &r.X), std::pair(&u.rows().Y, &r.Y)}) {
    const exact::IntegerSystem<exact::Z> a = exact::integer_system<exact::Z>(*P),
                                         b = exact::integer_system<exact::Z>(exact::rational_rows(R->A, R->b));
    EXPECT_EQ(a.A, b.A) << name;
    EXPECT_EQ(a.b, b.b) << name;
    EXPECT_EQ(a.row_scale, b.row_scale) << name;
  }
  const UcpInstance<double> d = to_double(u.rows());
  EXPECT_EQ(d.X.A, exact::to_double(r.X.A)) << name;
  EXPECT_EQ(d.X.b, exact::to_double(r.X.b)) << name;
  EXPECT_EQ(d.Y.A, exact::to_double(r.Y.A)) << name;
  EXPECT_EQ(d.Y.b, exact::to_double(r.Y.b)) << name;
  const auto same = [&](const auto& a, const auto& b, const auto& equal) {
    ASSERT_EQ(a.X.A.rows(), b.X.A.rows()) << name;
    ASSERT_EQ(a.Y.A.rows(), b.Y.A.rows()) << name;
    for (const auto& [P, R] : {std::pair(&a.X, &b.X), std::pair(&a.Y, &b.Y)})
      for (Eigen::Index i = 0; i < P->A.rows(); ++i) {
        for (Eigen::Index j = 0; j < P->A.cols(); ++j) EXPECT_TRUE(equal(P->A(i, j), R->A(i, j))) << name;
        EXPECT_TRUE(equal(P->b(i), R->b(i))) << name;
      }
  };
  const auto from_z_interval = [](const exact::Z& z) { return exact::to_interval(z); };
  const auto from_q_interval = [](const Q& q) { return exact::to_interval(q); };
  UcpInstance<exact::Interval> ri{{r.X.A.unaryExpr(from_q_interval), r.X.b.unaryExpr(from_q_interval)},
                                  {r.Y.A.unaryExpr(from_q_interval), r.Y.b.unaryExpr(from_q_interval)}};
  same(convert<exact::Interval>(u.rows(), from_z_interval, from_q_interval), ri,
       [](const exact::Interval& a, const exact::Interval& b) { return a.inf() == b.inf() && a.sup() == b.sup(); });
  constexpr long bits = 60;
  const exact::MpfrPrecision precision(bits);
  const auto from_z_mpfr = [](const exact::Z& z) { return exact::to_mpfr(z, bits); };
  const auto from_q_mpfr = [](const Q& q) { return exact::to_mpfr(q, bits); };
  UcpInstance<exact::Mpfr> rm{{r.X.A.unaryExpr(from_q_mpfr), r.X.b.unaryExpr(from_q_mpfr)},
                              {r.Y.A.unaryExpr(from_q_mpfr), r.Y.b.unaryExpr(from_q_mpfr)}};
  same(convert<exact::Mpfr>(u.rows(), from_z_mpfr, from_q_mpfr), rm, [](const exact::Mpfr& a, const exact::Mpfr& b) {
    return mpfr_equal_p(a.fr(), b.fr()) && mpfr_get_prec(a.fr()) == mpfr_get_prec(b.fr()) &&
           mpfr_signbit(a.fr()) == mpfr_signbit(b.fr());
  });
}

void expect_rational_ucp(const UcpProblem& u, const std::string& name) {
  const UcpInstance<Q> r = rational_ucp(*u.quasistatic);
  EXPECT_EQ(u.ucp().X.A, r.X.A) << name;
  EXPECT_EQ(u.ucp().X.b, r.X.b) << name;
  EXPECT_EQ(u.ucp().Y.A, r.Y.A) << name;
  EXPECT_EQ(u.ucp().Y.b, r.Y.b) << name;
  expect_same_floats(u, r, name);
}

TEST(UcpProblem, XIsTheSetOfContactVelocitiesReachableByQDotAndThetaAbar) {
  for (const UcpProblem& u : {load_ucp_problem(scene(1)), parse(small_problem().dump())}) {
    const QuasistaticProblem& p = *u.quasistatic;
    const Mat<Q> Z = exact::left_null_space<Q>(p.P);
    EXPECT_TRUE((Z * p.P).isZero());
    EXPECT_EQ(Z.rows(), 2 * p.nc - exact::rank<Q>(p.P));
    // Any q_dot, theta_abar gives v = P [q_dot; -theta_abar] - J_alpha theta_alpha; split v_t into +/- parts:
    // that x must satisfy X's equations.
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<int> d(-9, 9);
    for (int t = 0; t < 20; ++t) {
      Vec<Q> b(p.P.cols());
      for (Eigen::Index k = 0; k < b.size(); ++k) b(k) = Q(d(rng), 7);
      const Vec<Q> v = p.P * b - p.J_alpha_theta_alpha();
      Vec<Q> x = Vec<Q>::Zero(3 * p.nc);
      for (int i = 0; i < p.nc; ++i) {
        x(i) = v(i);
        (sgn(v(p.nc + i)) > 0 ? x(p.nc + i) : x(2 * p.nc + i)) = abs(v(p.nc + i));
      }
      EXPECT_EQ(u.ucp().X.A * x, u.ucp().X.b);
      if (Z.rows() == 0) continue;  // P has full row rank: every v is reachable
      x(0) += 1;                    // v_n changed alone: not reachable unless P spans e_0 (it does not here)
      EXPECT_NE(u.ucp().X.A * x, u.ucp().X.b);
    }
  }
}

TEST(UcpProblem, YEncodesEquilibriumAndCoulombFriction) {
  const UcpProblem u = parse(small_problem().dump());
  const QuasistaticProblem& p = *u.quasistatic;
  // Row r of Y is y_factor[r] > 0 times row r of [C | -d].
  Mat<Q> C = u.ucp().Y.A;
  ASSERT_EQ(C.rows(), p.nc + p.nq + 1);
  for (Eigen::Index k = 0; k < C.rows(); ++k) {
    const Q& f = u.rows().y_factor[static_cast<std::size_t>(k)];
    ASSERT_GT(f, 0);
    C.row(k) /= f;
    EXPECT_EQ(-u.ucp().Y.b(k) / f, p.d(k));
  }
  // y = (c_n, s+, s-) with s+ = mu c_n + c_t, s- = mu c_n - c_t: C y + d = (0; W c + g_obj; (J^T c)_abar + d_abar).
  Vec<Q> cn(2), ct(2);
  cn << 2, 3;
  ct << Q(1, 2), -1;
  Vec<Q> y(6);
  for (int i = 0; i < 2; ++i) y(i) = cn(i), y(2 + i) = p.mu(i) * cn(i) + ct(i), y(4 + i) = p.mu(i) * cn(i) - ct(i);
  const Vec<Q> r = C * y + p.d;
  EXPECT_EQ(r.head(2), Vec<Q>::Zero(2));
  EXPECT_EQ(r.segment(2, 3), p.Wn() * cn + p.Wt() * ct + p.g_obj());
  EXPECT_EQ(r(5), (p.Jn.col(3).dot(cn) + p.Jt.col(3).dot(ct)) + p.d(5));
}

TEST(UcpProblem, BadInputIsAnInputErrorNamingTheField) {
  struct Case {
    const char* what;
    std::function<void(nlohmann::json&)> edit;
    const char* path;
  };
  const std::vector<Case> cases = {
      {"P has a wrong number of rows", [](auto& j) { j["P"].erase(3); }, ".P"},
      {"P has a wrong number of columns",
       [](auto& j) {
         for (auto& r : j["P"]) r.erase(3);
       },
       ".P"},
      {"Jn has a wrong width", [](auto& j) { j["Jn"][0].push_back(0); }, ".Jn"},
      {"J_abar column of P differs from [Jn; Jt]", [](auto& j) { j["P"][3][3] = "2"; }, ".P"},
      {"mu < 0", [](auto& j) { j["mu"][1] = "-0.1"; }, ".mu[1]"},
      {"mu has the wrong length", [](auto& j) { j["mu"].push_back(1); }, ".mu"},
      {"alpha out of range", [](auto& j) { j["alpha"][2] = 4; }, ".alpha[2]"},
      {"alpha negative", [](auto& j) { j["alpha"][0] = -1; }, ".alpha[0]"},
      {"alpha repeats a joint", [](auto& j) { j["alpha"][2] = 1; }, ".alpha[2]"},
      {"d has the wrong length", [](auto& j) { j["d"].erase(5); }, ".d"},
      {"d's friction block is not zero", [](auto& j) { j["d"][1] = "1"; }, ".d[1]"},
      {"theta_dot misses a given velocity", [](auto& j) { j["theta_dot"][1] = nullptr; }, ".theta_dot[1]"},
      {"theta_dot has the wrong length", [](auto& j) { j["theta_dot"].erase(3); }, ".theta_dot"},
      {"nc is not a positive integer", [](auto& j) { j["nc"] = "1.5"; }, ".nc"},
      {"a number is not a number", [](auto& j) { j["P"][0][0] = "one"; }, ".P[0][0]"},
      {"unknown field", [](auto& j) { j["mu_s"] = 1; }, ".mu_s"},
      {"unknown kind", [](auto& j) { j["kind"] = "planar2"; }, ".kind"},
  };
  EXPECT_NO_THROW(parse(small_problem().dump()));
  for (const Case& c : cases) {
    nlohmann::json j = small_problem();
    c.edit(j);
    try {
      parse(j.dump());
      ADD_FAILURE() << c.what << ": accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file, "test.json") << c.what;
      EXPECT_EQ(e.json_path.rfind(std::string("$") + c.path, 0), 0u) << c.what << ": path " << e.json_path;
    }
  }
}

TEST(UcpProblem, WrittenProblemsReadBackIdentically) {
  std::mt19937_64 rng(11);
  for (int t = 0; t < 6; ++t) {
    RandomProblemOptions o;
    o.nc = 2 + t;
    o.mu_max = Q(6, 5);
    o.abar_size = t;
    const UcpProblem g = generate_random_problem(o, rng);
    const UcpProblem r = parse(to_json_text(g));
    EXPECT_EQ(r.quasistatic->P, g.quasistatic->P);
    EXPECT_EQ(r.quasistatic->d, g.quasistatic->d);
    EXPECT_EQ(r.quasistatic->theta_dot, g.quasistatic->theta_dot);
    EXPECT_EQ(r.quasistatic->alpha, g.quasistatic->alpha);
    EXPECT_EQ(r.ucp().X.A, g.ucp().X.A);
    EXPECT_EQ(r.ucp().Y.b, g.ucp().Y.b);
  }
  const UcpProblem red = reduction_problem(random_zero_one(2, 4, true, rng));
  const UcpProblem back = parse(to_json_text(red));
  EXPECT_FALSE(back.quasistatic);
  EXPECT_EQ(back.ucp().X.A, red.ucp().X.A);
  EXPECT_EQ(back.ucp().Y.b, red.ucp().Y.b);
}

TEST(UcpGenerator, RandomProblemsFollowSection5) {
  std::mt19937_64 rng(5);
  for (int t = 0; t < 10; ++t) {
    RandomProblemOptions o;
    o.nc = 1 + t;
    o.mu_max = frac(1 + t % 3, 2);
    o.abar_size = t % (o.nc + 1);
    const UcpProblem u = generate_random_problem(o, rng);
    const QuasistaticProblem& p = *u.quasistatic;
    EXPECT_EQ(p.ntheta, 2 * p.nc);
    EXPECT_EQ(p.nq, 3);
    EXPECT_EQ(static_cast<int>(p.abar.size()), o.abar_size);
    for (int i = 0; i < p.nc; ++i) {
      EXPECT_GT(sgn(p.mu(i)), 0);
      EXPECT_LT(p.mu(i), o.mu_max);
      // unit normals and tangents (rational), n x t = +1
      const Mat<Q> Wn = p.Wn(), Wt = p.Wt();
      EXPECT_EQ(Wn(0, i) * Wn(0, i) + Wn(1, i) * Wn(1, i), 1);
      EXPECT_EQ(Wn(0, i) * Wt(1, i) - Wn(1, i) * Wt(0, i), 1);
    }
  }
}

TEST(UcpGenerator, ReductionHasTheFormOfProposition2) {
  std::mt19937_64 rng(2);
  const ZeroOneProblem zo = random_zero_one(2, 3, true, rng);
  EXPECT_TRUE(zero_one_feasible(zo));
  const UcpProblem u = reduction_problem(zo);
  EXPECT_EQ(u.ucp().n(), 6);
  // If z solves (12), (z, e - z) is in X and (e - z, z) in Y, and they are orthogonal.
  for (unsigned mask = 0; mask < 8; ++mask) {
    Vec<Q> z(3);
    for (int j = 0; j < 3; ++j) z(j) = (mask >> j) & 1u;
    if (zo.A * z != zo.b) continue;
    Vec<Q> x(6), y(6);
    x << z, Vec<Q>(Vec<Q>::Ones(3) - z);
    y << Vec<Q>(Vec<Q>::Ones(3) - z), z;
    EXPECT_EQ(u.ucp().X.A * x, u.ucp().X.b);
    EXPECT_EQ(u.ucp().Y.A * y, u.ucp().Y.b);
    EXPECT_EQ(sgn(Q(x.dot(y))), 0);
  }
}

// Issue 18: X and Y are built in integers (fraction-free left null space, no products with B or U); they equal the
// rational construction exactly, also when the integers outgrow 128 bits and the elimination restarts in GMP.
TEST(UcpProblem, XAndYInIntegersEqualTheRationalOnes) {
  for (int k = 1; k <= 4; ++k) expect_rational_ucp(load_ucp_problem(scene(k)), "Data Set " + std::to_string(k));
  for (int seed = 0; seed < 100; ++seed)
    expect_rational_ucp(testing::random_problem(seed, 10), "random seed " + std::to_string(seed));
  // A generic UCP (the reduction family, rational rows): its integer rows, scaled once, give back the same numbers.
  std::mt19937_64 zo(4);
  for (int t = 0; t < 5; ++t) {
    const UcpProblem red = reduction_problem(random_zero_one(2 + t, 3 + t, t % 2 == 0, zo));
    UcpInstance<Q> r = red.ucp();
    r.X.A /= Q(2, 7 + 2 * t), r.X.b /= Q(2, 7 + 2 * t);  // rows over a common denominator
    UcpProblem scaled;
    scaled.set(r);
    const UcpInstance<Q> dense = to_dense_rational(scaled.rows());
    EXPECT_EQ(dense.X.A, r.X.A);
    EXPECT_EQ(dense.Y.A, r.Y.A);
    expect_same_floats(scaled, r, "reduction " + std::to_string(t));
  }
  // nc = 40 with Pythagorean normals ((a^2 - b^2) / h, 2ab / h), h = a^2 + b^2 the first 40 primes 1 mod 4: the lcm
  // of the denominators of a column of P exceeds 2^128, so the Int128 elimination overflows and restarts in GMP.
  std::mt19937_64 rng(2);
  RandomProblemOptions o;
  o.nc = 40;
  UcpProblem big = generate_random_problem(o, rng);
  QuasistaticProblem& p = *big.quasistatic;
  const auto prime = [](long h) {
    for (long d = 2; d * d <= h; ++d)
      if (h % d == 0) return false;
    return true;
  };
  const auto root = [](long v) {  // the integer square root of v, or -1
    const long r = std::lround(std::sqrt(static_cast<double>(v)));
    return r * r == v ? r : -1L;
  };
  for (long h = 5, i = 0; i < p.nc; ++h) {
    if (h % 4 != 1 || !prime(h)) continue;
    long a = 1, b = -1;
    while ((b = root(h - a * a)) < 0) ++a;
    const Q nx = frac(a * a - b * b, h), ny = frac(2 * a * b, h), rx = frac(i - 20, 3), ry = frac(7 - i % 5, 2);
    p.P(i, 0) = nx, p.P(i, 1) = ny, p.P(i, 2) = rx * ny - ry * nx;                        // Wn: n, r x n
    p.P(p.nc + i, 0) = -ny, p.P(p.nc + i, 1) = nx, p.P(p.nc + i, 2) = rx * nx + ry * ny;  // Wt: t = (-ny, nx), r x t
    ++i;
  }
  validate(p);
  big.set(build_ucp(p));
  exact::Z l = 1;
  for (Eigen::Index i = 0; i < p.P.rows(); ++i) l = lcm(l, p.P(i, 0).get_den());
  ASSERT_GT(mpz_sizeinbase(l.get_mpz_t(), 2), 128u);
  expect_rational_ucp(big, "nc 40");
}

}  // namespace
}  // namespace contactcert::solvers::ucp
