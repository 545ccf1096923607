// Not-necessarily-closed cones: the paper's section 4 cone with an open face, the origin as a closure
// point, empty strict systems, and random strict systems against brute-force membership.
#include "geometry/nnc_cone.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "exact/fraction_free.h"
#include "geometry/canonical.h"
#include "geometry/set_ops.h"
#include "tests/geometry/random_cones.h"
#include "tests/geometry/test_util.h"

namespace contactcert::geometry {
namespace {

using testing::rows;
using testing::vec;

// The cone G of section 4 (mu_s = 1/5, generators scaled by 5): g1 = (1,0,-1), g2 = (-1,-5,-1),
// g3 = (1,-5,1); g2 and g3 are the friction edges. The face they span is open (a2n < 0 strictly).
struct PaperExample {
  Vec<Q> g1 = vec({1, 0, -1}), g2 = vec({-1, -5, -1}), g3 = vec({1, -5, 1});
  FaceCone<Q> cone() const {
    const FaceCone<Q> closed =
        canonical(to_face(SpanCone<Q>::from_rows(3, rows({{1, 0, -1}, {-1, -5, -1}, {1, -5, 1}}), Mat<Q>(0, 3))));
    std::vector<Eigen::Index> open, kept;
    for (Eigen::Index f = 0; f < closed.inequalities.rows(); ++f)
      (closed.inequalities.row(f).dot(g2) == 0 && closed.inequalities.row(f).dot(g3) == 0 ? open : kept).push_back(f);
    EXPECT_EQ(open.size(), 1u);
    return FaceCone<Q>::from_rows(3, closed.inequalities(kept, Eigen::all), Mat<Q>(0, 3),
                                  closed.inequalities(open, Eigen::all));
  }
};

TEST(NncCone, PaperExampleHasOneOpenFace) {
  const PaperExample ex;
  const NncForm<Q> n = nnc_form(ex.cone());
  ASSERT_EQ(n.status, NncStatus::kNonEmpty);
  EXPECT_EQ(n.dimension(), 3);
  EXPECT_EQ(n.closure.rays.rows(), 3);
  EXPECT_EQ(n.face.inequalities.rows(), 2);
  EXPECT_EQ(n.face.strict.rows(), 1);
  ASSERT_EQ(n.open_faces.size(), 1u);
  EXPECT_EQ(n.open_faces[0].size(), 2u);
  EXPECT_EQ(std::count(n.open_facets.begin(), n.open_facets.end(), true), 1);
  EXPECT_TRUE(contains_point(n.face, ex.g1));
  EXPECT_TRUE(contains_point(n.face, Vec<Q>(ex.g1 + ex.g2)));
  EXPECT_TRUE(contains_point(n.face, Vec<Q>(ex.g1 + ex.g2 + ex.g3)));
  EXPECT_FALSE(contains_point(n.face, ex.g2));
  EXPECT_FALSE(contains_point(n.face, Vec<Q>(ex.g2 + ex.g3)));
  EXPECT_FALSE(contains_point(n.face, vec({0, 0, 0})));  // origin excluded
  // Positions.
  EXPECT_EQ(locate(n.face, Vec<Q>(ex.g1 + ex.g2 + ex.g3)).location, PointLocation::kInterior);
  const auto b = locate(n.face, Vec<Q>(ex.g1 + ex.g2));
  EXPECT_EQ(b.location, PointLocation::kBoundary);
  EXPECT_EQ(b.tight.size(), 1u);
  EXPECT_EQ(locate(n.face, ex.g1).tight.size(), 2u);
  const auto o = locate(n.face, Vec<Q>(ex.g2 + ex.g3));
  EXPECT_EQ(o.location, PointLocation::kOutside);
  EXPECT_EQ(o.violated_kind, PointPosition<Q>::RowKind::kStrict);
  EXPECT_EQ(locate(n.face, Vec<Q>(-ex.g1)).location, PointLocation::kOutside);
}

TEST(NncCone, OriginAsClosurePoint) {
  // Octant minus the origin: x, y, z <= 0 and x + y + z < 0.
  const FaceCone<Q> c =
      FaceCone<Q>::from_rows(3, rows({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), Mat<Q>(0, 3), rows({{1, 1, 1}}));
  const NncForm<Q> n = nnc_form(c);
  ASSERT_EQ(n.status, NncStatus::kNonEmpty);
  ASSERT_EQ(n.open_faces.size(), 1u);
  EXPECT_TRUE(n.open_faces[0].empty());  // the face with no rays: the origin
  EXPECT_EQ(n.face.strict, rows({{1, 1, 1}}));
  EXPECT_EQ(n.face.inequalities.rows(), 3);
  EXPECT_FALSE(contains_point(n.face, vec({0, 0, 0})));
  EXPECT_TRUE(contains_point(n.face, vec({-1, 0, 0})));
  // The same set written differently (x + y + 3z < 0, or two strict rows that vanish only at the origin);
  // x + y < 0 also drops the z axis.
  const FaceCone<Q> same =
      FaceCone<Q>::from_rows(3, rows({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), Mat<Q>(0, 3), rows({{1, 1, 3}}));
  EXPECT_TRUE(identical(nnc_form(same).face, n.face));
  const FaceCone<Q> two =
      FaceCone<Q>::from_rows(3, rows({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), Mat<Q>(0, 3), rows({{2, 1, 1}, {1, 2, 1}}));
  EXPECT_TRUE(identical(nnc_form(two).face, n.face));
  const FaceCone<Q> other =
      FaceCone<Q>::from_rows(3, rows({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), Mat<Q>(0, 3), rows({{1, 1, 0}}));
  EXPECT_FALSE(identical(nnc_form(other).face, n.face));
  EXPECT_FALSE(contains_point(other, vec({0, 0, -1})));
  EXPECT_TRUE(contains_point(n.face, vec({0, 0, -1})));
  // With a line: the open face is the lineality space.
  const FaceCone<Q> wedge = FaceCone<Q>::from_rows(3, rows({{1, 0, 0}, {0, 1, 0}}), Mat<Q>(0, 3), rows({{1, 1, 0}}));
  const NncForm<Q> w = nnc_form(wedge);
  EXPECT_EQ(w.closure.lines.rows(), 1);
  ASSERT_EQ(w.open_faces.size(), 1u);
  EXPECT_TRUE(w.open_faces[0].empty());
  EXPECT_FALSE(contains_point(w.face, vec({0, 0, 7})));
}

TEST(NncCone, EmptyStrictSystems) {
  const FaceCone<Q> a = FaceCone<Q>::from_rows(2, Mat<Q>(0, 2), Mat<Q>(0, 2), rows({{1, 0}, {-1, 0}}));
  const FaceCone<Q> b = FaceCone<Q>::from_rows(2, Mat<Q>(0, 2), rows({{1, 1}}), rows({{1, 1}}));
  const FaceCone<Q> c = FaceCone<Q>::from_rows(2, rows({{1, 0}, {0, 1}}), Mat<Q>(0, 2), rows({{-1, -1}}));
  for (const auto& e : {a, b, c}) {
    const NncForm<Q> n = nnc_form(e);
    EXPECT_EQ(n.status, NncStatus::kEmpty);
    EXPECT_EQ(n.dimension(), -1);
    EXPECT_TRUE(identical(n.face, nnc_form(a).face));
    EXPECT_FALSE(contains_point(n.face, vec({0, 0})));
  }
  // Not empty: x < 0 alone.
  EXPECT_EQ(nnc_form(FaceCone<Q>::from_rows(2, Mat<Q>(0, 2), Mat<Q>(0, 2), rows({{1, 0}}))).status,
            NncStatus::kNonEmpty);
}

// Brute force: the canonical NNC form and the input accept the same points among many test points
// (integer points and sums of subsets of closure rays, which land in every face).
TEST(NncCone, RandomStrictSystemsKeepTheirPoints) {
  std::mt19937_64 rng(11);
  int nonempty = 0, empty = 0, with_open = 0;
  for (int rep = 0; rep < 300; ++rep) {
    const Eigen::Index d = 2 + rep % 3;
    const FaceCone<Q> c = testing::random_face(rng, d, 1 + rep % 4, rep % 7 == 0 ? 1 : 0, 1 + rep % 3, 2);
    const NncForm<Q> n = nnc_form(c);
    if (n.status == NncStatus::kEmpty) {
      ++empty;
    } else {
      ++nonempty;
      if (!n.open_faces.empty()) ++with_open;
    }
    std::vector<Vec<Q>> pts;
    std::uniform_int_distribution<long> u(-3, 3);
    for (int k = 0; k < 60; ++k) {
      Vec<Q> p(d);
      for (Eigen::Index j = 0; j < d; ++j) p(j) = u(rng);
      pts.push_back(p);
    }
    const Eigen::Index nr = n.closure.rays.rows();
    for (unsigned mask = 0; nr < 12 && mask < (1u << nr); ++mask) {
      Vec<Q> p = Vec<Q>::Zero(d);
      for (Eigen::Index r = 0; r < nr; ++r)
        if (mask & (1u << r)) p += n.closure.rays.row(r).transpose();
      pts.push_back(p);
    }
    for (const auto& p : pts) ASSERT_EQ(contains_point(c, p), contains_point(n.face, p)) << "rep " << rep;
    // Closure: every closure ray is a limit of points of the cone: ray + t * interior point.
    if (n.status == NncStatus::kNonEmpty) {
      Vec<Q> inner = Vec<Q>::Zero(d);
      for (Eigen::Index r = 0; r < nr; ++r) inner += n.closure.rays.row(r).transpose();
      ASSERT_TRUE(contains_point(c, inner));
      for (Eigen::Index r = 0; r < nr; ++r)
        ASSERT_TRUE(contains_point(c, Vec<Q>(n.closure.rays.row(r).transpose() * 1000 + inner)));
    }
  }
  EXPECT_GT(nonempty, 50);
  EXPECT_GT(empty, 5);
  EXPECT_GT(with_open, 20);
}

template <class R>
exact::IntMatrix<R> ring_rows_of(const Mat<Q>& M) {
  exact::IntMatrix<R> out(M.rows(), M.cols());
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = 0; j < M.cols(); ++j) exact::ring::from_integer(M(i, j), out(i, j));
  return out;
}

// pointed_nnc_face is nnc_form's face whenever it answers (pointed full-dimensional closure, or an
// empty cone), in Z and in std::int64_t; with entries up to 2^40 the machine integers overflow
// (RingOverflow) and Z still agrees.
TEST(NncCone, RingFaceFormIsNncFormsFaceAndOverflowsIntoZ) {
  std::mt19937_64 rng(29);
  int answered = 0, overflowed = 0, empty = 0;
  for (int rep = 0; rep < 300; ++rep) {
    const Eigen::Index d = 2 + rep % 3;
    const long range = rep % 4 == 3 ? long{1} << 40 : 5;
    const FaceCone<Q> c = testing::random_face(rng, d, 2 + rep % 4, 0, 1 + rep % 3, range);
    const FaceCone<Q> want = nnc_form(c).face;
    const auto z = pointed_nnc_face<Q, Z>(ring_rows_of<Z>(c.inequalities), ring_rows_of<Z>(c.strict));
    if (z) {
      ++answered;
      ASSERT_TRUE(identical(*z, want)) << "rep " << rep;
      if (want.strict.rows() == 1 && want.equalities.rows() == d) ++empty;
    }
    try {
      const auto s = pointed_nnc_face<Q, std::int64_t>(ring_rows_of<std::int64_t>(c.inequalities),
                                                       ring_rows_of<std::int64_t>(c.strict));
      ASSERT_EQ(s.has_value(), z.has_value()) << "rep " << rep;
      if (s) {
        ASSERT_TRUE(identical(*s, want)) << "rep " << rep;
      }
    } catch (const exact::RingOverflow&) {
      ++overflowed;
    }
  }
  EXPECT_GT(answered, 100);
  EXPECT_GT(empty, 2);
  EXPECT_GT(overflowed, 20);
}

TEST(NncCone, FloatPathAgreesOnThePaperExample) {
  const PaperExample ex;
  const FaceCone<Q> c = ex.cone();
  const FaceCone<double> cd =
      FaceCone<double>::from_rows(3, exact::to_double(c.inequalities), Mat<double>(0, 3), exact::to_double(c.strict));
  const NncForm<double> n = nnc_form(cd);
  EXPECT_EQ(n.status, NncStatus::kNonEmpty);
  EXPECT_EQ(n.open_faces.size(), 1u);
  EXPECT_EQ(n.face.strict.rows(), 1);
}

// nnc_form of a span cone (one conversion) equals nnc_form of its face form (the route through both
// conversions), lower-dimensional and non-pointed cones included.
TEST(NncCone, SpanInputConvertsOnce) {
  std::mt19937_64 rng(23);
  for (Eigen::Index dim = 2; dim <= 6; ++dim)
    for (int rep = 0; rep < 10; ++rep) {
      SpanCone<Q> C = testing::random_span(rng, dim, rep % 7, rep % 3, rep % 2 == 0 ? rep % 7 : 0);
      const NncForm<Q> once = nnc_form(C);
      const NncForm<Q> twice = nnc_form(canonical(to_face(C)));
      ASSERT_TRUE(identical(once.face, twice.face));
      ASSERT_TRUE(identical(once.closure, twice.closure));
      ASSERT_TRUE(identical(once.closure_face, twice.closure_face));
      EXPECT_EQ(once.open_facets, twice.open_facets);
      EXPECT_TRUE(once.open_faces.empty());
    }
}

}  // namespace
}  // namespace contactcert::geometry
