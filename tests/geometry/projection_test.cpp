// The cone { g : exists z >= 0, z_i > 0 on strict, K z = P g }: the paper's route and the LP route agree.
#include "geometry/projection.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "exact/fraction_free.h"
#include "exact/linalg.h"
#include "geometry/canonical.h"
#include "tests/geometry/test_util.h"

namespace contactcert::geometry {
namespace {

using testing::rows;
using testing::vec;

// Section 4: K z = P g with mu_s = 1/5, z = (-a2n, (mu c1n + c1t)/2mu, (mu c1n - c1t)/2mu), -a2n > 0.
ProjectionProblem<Q> paper_example() {
  ProjectionProblem<Q> p;
  p.K = Mat<Q>(3, 3);
  p.K << 0, -1, -1, -1, Q(1, 5), Q(-1, 5), 0, Q(2, 5), Q(-2, 5);
  p.P = rows({{0, 1, 0}, {-1, 0, 0}, {-1, 0, -1}});
  p.strict = {true, false, false};
  return p;
}

TEST(Projection, PaperExampleBothRoutes) {
  const ProjectionProblem<Q> p = paper_example();
  const FaceCone<Q> a = project_by_polar(p);
  const FaceCone<Q> b = project_by_lp(p);
  EXPECT_TRUE(identical(a, b));
  // G = P^-1 K = [1 -1/5 1/5; 0 -1 -1; -1 -1/5 1/5] (the paper's printed cone); the face of g2, g3 is open.
  const Mat<Q> G = *exact::inverse<Q>(p.P) * p.K;
  Mat<Q> expected_G(3, 3);
  expected_G << 1, Q(-1, 5), Q(1, 5), 0, -1, -1, -1, Q(-1, 5), Q(1, 5);
  EXPECT_EQ(G, expected_G);
  EXPECT_EQ(a.inequalities.rows(), 2);
  EXPECT_EQ(a.strict.rows(), 1);
  const Vec<Q> g1 = G.col(0), g2 = G.col(1), g3 = G.col(2);
  EXPECT_TRUE(contains_point(a, g1));
  EXPECT_FALSE(contains_point(a, Vec<Q>(g2 + g3)));
  EXPECT_FALSE(contains_point(a, vec({0, 0, 0})));
  EXPECT_TRUE(contains_point(a, Vec<Q>(g1 + g2)));
  // Without the strict component: the closed cone pos(G).
  ProjectionProblem<Q> closed = p;
  closed.strict.clear();
  const FaceCone<Q> c = project_by_polar(closed);
  EXPECT_TRUE(identical(c, project_by_lp(closed)));
  EXPECT_TRUE(identical(c, canonical(to_face(SpanCone<Q>::from_columns(G)))));
  EXPECT_EQ(c.strict.rows(), 0);
}

TEST(Projection, RandomProblemsBothRoutesAgree) {
  std::mt19937_64 rng(23);
  std::uniform_int_distribution<long> u(-3, 3);
  int with_strict = 0, empty = 0;
  for (int rep = 0; rep < 150; ++rep) {
    const Eigen::Index m = 3 + rep % 4, n = 2 + rep % 6, d = 2 + rep % 3;
    ProjectionProblem<Q> p;
    p.K = Mat<Q>(m, n);
    p.P = Mat<Q>(m, d);
    for (Eigen::Index i = 0; i < m; ++i) {
      for (Eigen::Index j = 0; j < n; ++j) p.K(i, j) = u(rng);
      for (Eigen::Index j = 0; j < d; ++j) p.P(i, j) = u(rng);
    }
    if (rep % 5 == 0) p.P.col(0) = p.P.col(1);  // P with a kernel: a line in the result
    p.strict.assign(static_cast<size_t>(n), false);
    for (Eigen::Index j = 0; j < n; ++j) p.strict[static_cast<size_t>(j)] = (rep + j) % 3 == 0;
    const FaceCone<Q> a = project_by_polar(p);
    const FaceCone<Q> b = project_by_lp(p);
    ASSERT_TRUE(identical(a, b)) << "rep " << rep << "\nK\n"
                                 << p.K << "\nP\n"
                                 << p.P << "\npolar\n"
                                 << a.inequalities << "\n/\n"
                                 << a.strict << "\nlp\n"
                                 << b.inequalities << "\n/\n"
                                 << b.strict;
    if (a.strict.rows() > 0) ++with_strict;
    if (a.equalities.rows() == d) ++empty;
  }
  EXPECT_GT(with_strict, 20);
}

// The paper's route on rows already in the ring ([P | K], any positive row factor) is the LP route's
// cone; with entries up to 2^40 std::int64_t overflows (RingOverflow) and Z still agrees.
TEST(Projection, RingRowsRouteAgreesWithTheLpRouteAndOverflowsIntoZ) {
  std::mt19937_64 rng(31);
  int overflowed = 0;
  for (int rep = 0; rep < 40; ++rep) {
    const Eigen::Index m = 3 + rep % 2, n = 3 + rep % 4, d = 3;
    std::uniform_int_distribution<long> u(rep % 2 ? -(long{1} << 40) : -3, rep % 2 ? long{1} << 40 : 3);
    ProjectionProblem<Q> p;
    p.K = Mat<Q>(m, n);
    p.P = Mat<Q>(m, d);
    exact::IntMatrix<Z> wide(m, d + n);
    exact::IntMatrix<std::int64_t> fixed(m, d + n);
    for (Eigen::Index i = 0; i < m; ++i) {
      const long scale = 1 + (rep + i) % 3;  // a positive factor per row
      for (Eigen::Index j = 0; j < d + n; ++j) {
        const long x = u(rng);
        (j < d ? p.P(i, j) : p.K(i, j - d)) = Q(x);
        wide(i, j) = Z(x) * scale;
        fixed(i, j) = x * scale;
      }
    }
    p.strict.assign(static_cast<size_t>(n), false);
    for (Eigen::Index j = 0; j < n; ++j) p.strict[static_cast<size_t>(j)] = (rep + j) % 3 == 0;
    const FaceCone<Q> want = project_by_lp(p);
    ASSERT_TRUE(identical(project_by_polar_rows<Q, Z>(wide, d, p.strict), want)) << "rep " << rep;
    try {
      ASSERT_TRUE(identical(project_by_polar_rows<Q, std::int64_t>(fixed, d, p.strict), want)) << "rep " << rep;
    } catch (const exact::RingOverflow&) {
      ++overflowed;
    }
  }
  EXPECT_GT(overflowed, 10);
}

TEST(Projection, FloatRoutesAgreeOnThePaperExample) {
  const ProjectionProblem<Q> p = paper_example();
  ProjectionProblem<double> pd{exact::to_double(p.K), exact::to_double(p.P), p.strict};
  const FaceCone<double> a = project_by_polar(pd);
  const FaceCone<double> b = project_by_lp(pd);
  EXPECT_EQ(a.inequalities.rows(), 2);
  EXPECT_EQ(a.strict.rows(), 1);
  EXPECT_TRUE((a.inequalities - b.inequalities).cwiseAbs().maxCoeff() < 1e-9);
}

TEST(Projection, Theorem1Offset) {
  // z >= k with k = (1, 0, 0): the cone shifted by K k = P g0.
  const ProjectionProblem<Q> p = paper_example();
  const AffineFace<Q> t = theorem1<Q>(p.K, p.P, vec({1, 0, 0}));
  const Mat<Q> G = *exact::inverse<Q>(p.P) * p.K;
  const Vec<Q> g1 = G.col(0);
  // g = G z with z = (1, 0, 0) is the apex: every row tight.
  EXPECT_EQ(Vec<Q>(t.A * g1 - t.b), Vec<Q>(Vec<Q>::Zero(t.A.rows())));
  // z = (1/2, 0, 0) is not allowed.
  EXPECT_GT((t.A * Vec<Q>(g1 / 2) - t.b).maxCoeff(), 0);
}

}  // namespace
}  // namespace contactcert::geometry
