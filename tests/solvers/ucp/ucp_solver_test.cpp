#include <gtest/gtest.h>

#include <random>

#include "solvers/ucp/bilinear.h"
#include "solvers/ucp/enumerate.h"
#include "solvers/ucp/generate.h"
#include "solvers/ucp/recovery.h"
#include "solvers/ucp/search.h"

namespace contactcert::solvers::ucp {
namespace {

std::string scene(int k) { return std::string(CONTACTCERT_SCENES_DIR) + "/pang1994_dataset" + std::to_string(k) + ".json"; }

bool in_polyhedron(const StandardPolyhedron<Q>& P, const Vec<Q>& x) {
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (sgn(x(i)) < 0) return false;
  return P.A * x == P.b;
}

void expect_physical_solution(const UcpProblem& p, const Vec<Q>& x, const Vec<Q>& y) {
  ASSERT_TRUE(in_polyhedron(p.ucp.X, x));
  ASSERT_TRUE(in_polyhedron(p.ucp.Y, y));
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
      const auto r = bilinear(make_face(p.ucp.X, {}), make_face(p.ucp.Y, {}), o, rng);
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
    const auto r = complete_search(p.ucp, SearchOptions{}, rng);
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
