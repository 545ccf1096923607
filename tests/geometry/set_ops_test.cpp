// Intersection, containment (with witnesses) and equality of cones with strict rows.
#include "geometry/set_ops.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/canonical.h"
#include "tests/geometry/random_cones.h"
#include "tests/geometry/test_util.h"

namespace contactcert::geometry {
namespace {

using testing::rows;
using testing::vec;

TEST(SetOps, IntersectionIsContainedWithWitnessOtherwise) {
  std::mt19937_64 rng(17);
  int strict_witnesses = 0;
  for (int rep = 0; rep < 200; ++rep) {
    const Eigen::Index d = 3 + rep % 2;
    const FaceCone<Q> A = testing::random_face(rng, d, 2 + rep % 3, 0, rep % 2, 3);
    const FaceCone<Q> B = testing::random_face(rng, d, 2, 0, rep % 3 == 0 ? 1 : 0, 3);
    const FaceCone<Q> AB = intersection(A, B);
    EXPECT_EQ(contains(A, AB).status, ContainmentStatus::kContained);
    EXPECT_EQ(contains(B, AB).status, ContainmentStatus::kContained);
    const Containment<Q> r = contains(AB, A);
    if (r.status == ContainmentStatus::kNotContained) {
      ASSERT_TRUE(contains_point(A, r.witness)) << "rep " << rep;
      ASSERT_FALSE(contains_point(AB, r.witness)) << "rep " << rep << "\nA\n"
                                                  << A.inequalities << "\n/\n"
                                                  << A.strict << "\nB\n"
                                                  << B.inequalities << "\n/\n"
                                                  << B.strict << "\nw " << r.witness.transpose();
      if (!contains_point(FaceCone<Q>::from_rows(d, AB.inequalities, AB.equalities, Mat<Q>(0, d)), r.witness)) continue;
      ++strict_witnesses;  // excluded only by a strict row
    } else {
      EXPECT_TRUE(equal(AB, A));
    }
    EXPECT_TRUE(equal(A, FaceCone<Q>(nnc_form(A).face)));
  }
  EXPECT_GT(strict_witnesses, 0);
}

TEST(SetOps, StrictContainment) {
  const FaceCone<Q> octant =
      FaceCone<Q>::from_rows(3, rows({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), Mat<Q>(0, 3), Mat<Q>(0, 3));
  const FaceCone<Q> punctured = FaceCone<Q>::from_rows(3, octant.inequalities, Mat<Q>(0, 3), rows({{1, 1, 1}}));
  const FaceCone<Q> open_x = FaceCone<Q>::from_rows(3, rows({{0, 1, 0}, {0, 0, 1}}), Mat<Q>(0, 3), rows({{1, 0, 0}}));
  EXPECT_EQ(contains(octant, punctured).status, ContainmentStatus::kContained);
  const Containment<Q> c = contains(punctured, octant);
  ASSERT_EQ(c.status, ContainmentStatus::kNotContained);
  EXPECT_EQ(c.witness, vec({0, 0, 0}));
  EXPECT_EQ(contains(punctured, open_x).status, ContainmentStatus::kContained);
  const Containment<Q> d = contains(open_x, punctured);
  ASSERT_EQ(d.status, ContainmentStatus::kNotContained);
  EXPECT_TRUE(contains_point(punctured, d.witness));
  EXPECT_FALSE(contains_point(open_x, d.witness));
  EXPECT_FALSE(equal(octant, punctured));
  EXPECT_TRUE(equal(punctured, FaceCone<Q>::from_rows(3, octant.inequalities, Mat<Q>(0, 3), rows({{3, 1, 2}}))));
}

}  // namespace
}  // namespace contactcert::geometry
