// Contact frames of fixels on non-convex polygons (issue 29): a fixel on the boundary takes the edge whose SEGMENT
// holds it, not the first edge whose supporting line passes through it; explicit contacts likewise; at a vertex an
// explicit normal lies in the cone of the two edges' inward normals, at a reflex vertex too.
#include "geometry/contact_frame.h"

#include <gtest/gtest.h>

namespace contactcert::geometry {
namespace {

Point2 P(int x, int y) { return {Q(x), Q(y)}; }
Point2 P(const char* x, const char* y) { return {Q(x), Q(y)}; }

// The L-shape of issue 29, counter-clockwise as the issue lists it (shoelace: 2A = 0 + 4 + 2 + 4 + 6 + 0 = 16 > 0):
// the foot [0,4] x [0,1] and the post [0,2] x [1,3]. Edges: 0 (0,0)-(4,0), 1 (4,0)-(4,1), 2 (4,1)-(2,1) (the inner
// edge y = 1, whose line passes through (0,1) on edge 5), 3 (2,1)-(2,3), 4 (2,3)-(0,3), 5 (0,3)-(0,0).
const Shape kL = PolygonShape{{P(0, 0), P(4, 0), P(4, 1), P(2, 1), P(2, 3), P(0, 3)}};

// A four-pointed star, counter-clockwise: tips at radius 2 on the axes, reflex vertices at (+-1/2, +-1/2).
// Edges: 0 (2,0)-(1/2,1/2), 1 (1/2,1/2)-(0,2), 2 (0,2)-(-1/2,1/2), 3 (-1/2,1/2)-(-2,0), 4 (-2,0)-(-1/2,-1/2),
// 5 (-1/2,-1/2)-(0,-2), 6 (0,-2)-(1/2,-1/2), 7 (1/2,-1/2)-(2,0).
const Shape kStar = PolygonShape{
    {P(2, 0), P("1/2", "1/2"), P(0, 2), P("-1/2", "1/2"), P(-2, 0), P("-1/2", "-1/2"), P(0, -2), P("1/2", "-1/2")}};

/// x = s y for some s > 0.
bool positive_multiple(const Point2& x, const Point2& y) { return sgn(Q(cross(x, y))) == 0 && sgn(Q(dot(x, y))) > 0; }

TEST(ContactFrame, LShapeIsCounterClockwise) {
  EXPECT_EQ(shoelace_area2(std::get<PolygonShape>(kL).vertices), Q(16));
  EXPECT_EQ(check_polygon(std::get<PolygonShape>(kL).vertices).defect, PolygonDefect::kNone);
  EXPECT_EQ(check_polygon(std::get<PolygonShape>(kStar).vertices).defect, PolygonDefect::kNone);
}

TEST(ContactFrame, LShapeFixelOnTheOuterEdgeNotTheInnerEdgesLine) {
  // (0,1) and (0,2) lie on edge 5 only; the line y = 1 of edge 2 passes through (0,1) but its segment x in [2,4]
  // does not. Edge 5's inward normal is perp((0,-3)) = (3,0).
  for (const Point2& f : {P(0, 1), P(0, 2)}) {
    const FrameResult r = frame_from_position(kL, f);
    ASSERT_EQ(r.status, FrameStatus::kOk);
    EXPECT_TRUE(r.frame.point == f);
    EXPECT_TRUE(r.frame.normal == P(3, 0));
    EXPECT_TRUE(r.frame.touching());
  }
  // On the inner edges themselves: (3,1) on edge 2, normal perp((-2,0)) = (0,-2); (2,2) on edge 3, perp((0,2)) =
  // (-2,0).
  EXPECT_TRUE(frame_from_position(kL, P(3, 1)).frame.normal == P(0, -2));
  EXPECT_TRUE(frame_from_position(kL, P(2, 2)).frame.normal == P(-2, 0));
}

TEST(ContactFrame, LShapeExplicitContactOnTheOuterEdge) {
  EXPECT_EQ(frame_from_contact(kL, P(0, 1), P(1, 0), Q(0)).status, FrameStatus::kOk);
  // The frame of the inner edge's line, forged at (0,1): refused.
  EXPECT_EQ(frame_from_contact(kL, P(0, 1), P(0, -1), Q(0)).status, FrameStatus::kNormalNotUnique);
  EXPECT_EQ(frame_from_contact(kL, P(0, 1), P(0, 1), Q(0)).status, FrameStatus::kNormalNotUnique);
  // (1,1) is inside the L, on the line of edge 2 only.
  EXPECT_NE(frame_from_contact(kL, P(1, 1), P(0, -1), Q(0)).status, FrameStatus::kOk);
}

TEST(ContactFrame, LShapeVertices) {
  // A fixel at a vertex has no unique normal.
  EXPECT_EQ(frame_from_position(kL, P(2, 1)).status, FrameStatus::kNormalNotUnique);
  EXPECT_EQ(frame_from_position(kL, P(0, 0)).status, FrameStatus::kNormalNotUnique);
  // Convex vertex (0,0): inward normals u = perp((0,-3)) = (3,0), v = perp((4,0)) = (0,4); n in pos(u, v).
  EXPECT_EQ(frame_from_contact(kL, P(0, 0), P(1, 1), Q(0)).status, FrameStatus::kOk);
  EXPECT_EQ(frame_from_contact(kL, P(0, 0), P(1, 0), Q(0)).status, FrameStatus::kOk);
  EXPECT_EQ(frame_from_contact(kL, P(0, 0), P(-1, 1), Q(0)).status, FrameStatus::kNormalNotUnique);
  // Reflex vertex (2,1): u = perp((-2,0)) = (0,-2), v = perp((0,2)) = (-2,0); pos(u, v) is the third quadrant.
  // (1,-1) pushes into the foot but no edge at (2,1) can exert it: refused (it was accepted before issue 29).
  EXPECT_EQ(frame_from_contact(kL, P(2, 1), P(-1, -1), Q(0)).status, FrameStatus::kOk);
  EXPECT_EQ(frame_from_contact(kL, P(2, 1), P(0, -1), Q(0)).status, FrameStatus::kOk);
  EXPECT_EQ(frame_from_contact(kL, P(2, 1), P(1, -1), Q(0)).status, FrameStatus::kNormalNotUnique);
  EXPECT_EQ(frame_from_contact(kL, P(2, 1), P(-1, 1), Q(0)).status, FrameStatus::kNormalNotUnique);
}

TEST(ContactFrame, LShapeOutside) {
  // (-1,1): closest point (0,1) on edge 5 at distance 1, normal p - f = (1,0).
  FrameResult r = frame_from_position(kL, P(-1, 1));
  ASSERT_EQ(r.status, FrameStatus::kOk);
  EXPECT_TRUE(r.frame.point == P(0, 1));
  EXPECT_TRUE(r.frame.normal == P(1, 0));
  EXPECT_EQ(r.frame.gap_squared, Q(1));
  // (3,2) in the notch: (3,1) on edge 2 and (2,2) on edge 3, both at distance 1: no unique frame.
  EXPECT_EQ(frame_from_position(kL, P(3, 2)).status, FrameStatus::kClosestNotUnique);
  // (3,3/2): (3,1) at 1/2 beats (2,3/2) at 1; normal (0,-1/2).
  r = frame_from_position(kL, P("3", "3/2"));
  ASSERT_EQ(r.status, FrameStatus::kOk);
  EXPECT_TRUE(r.frame.point == P(3, 1));
  EXPECT_TRUE(positive_multiple(r.frame.normal, P(0, -1)));
  // (5,2): vertex (4,1) at squared distance 2 (edges 1 and 2 both end there), normal (-1,-1).
  r = frame_from_position(kL, P(5, 2));
  ASSERT_EQ(r.status, FrameStatus::kOk);
  EXPECT_TRUE(r.frame.point == P(4, 1));
  EXPECT_TRUE(r.frame.normal == P(-1, -1));
  EXPECT_EQ(frame_from_position(kL, P(1, 1)).status, FrameStatus::kInsideWorkpiece);
}

TEST(ContactFrame, StarByHand) {
  // The line of edge 0, y = (2 - x) / 3, meets edge 2 (from (0,2) by (-1/2,-3/2) s) at s = 4/5: (-2/5, 4/5). That
  // point takes edge 2's normal perp((-1/2,-3/2)) = (3/2,-1/2), not edge 0's (-1/2,-3/2).
  FrameResult r = frame_from_position(kStar, P("-2/5", "4/5"));
  ASSERT_EQ(r.status, FrameStatus::kOk);
  EXPECT_TRUE(r.frame.normal == P("3/2", "-1/2"));
  // The line of edge 1, (1/2 - s, 1/2 + 3 s), meets edge 7 (y = -1/2 + (x - 1/2) / 3) at s = -3/10: (4/5,-2/5).
  // Edge 7's normal is perp((3/2,1/2)) = (-1/2,3/2); edge 1's would be (-3/2,-1/2).
  r = frame_from_position(kStar, P("4/5", "-2/5"));
  ASSERT_EQ(r.status, FrameStatus::kOk);
  EXPECT_TRUE(r.frame.normal == P("-1/2", "3/2"));
  EXPECT_EQ(frame_from_contact(kStar, P("4/5", "-2/5"), P(-1, 3), Q(0)).status, FrameStatus::kOk);
  EXPECT_EQ(frame_from_contact(kStar, P("4/5", "-2/5"), P(-3, -1), Q(0)).status, FrameStatus::kNormalNotUnique);
  // The midpoint (1/4, 5/4) of edge 1: normal perp((-1/2,3/2)) = (-3/2,-1/2).
  EXPECT_TRUE(frame_from_position(kStar, P("1/4", "5/4")).frame.normal == P("-3/2", "-1/2"));
  // (2,1): edge 0's closest point at t = ((0,1).(-3/2,1/2)) / (5/2) = 1/5 is (17/10, 1/10), squared distance
  // 9/10; edge 7's is the tip (2,0) at 1, edge 1's the vertex (1/2,1/2) at 5/2. Normal p - f = (-3/10,-9/10).
  r = frame_from_position(kStar, P(2, 1));
  ASSERT_EQ(r.status, FrameStatus::kOk);
  EXPECT_TRUE(r.frame.point == P("17/10", "1/10"));
  EXPECT_TRUE(r.frame.normal == P("-3/10", "-9/10"));
  EXPECT_EQ(r.frame.gap_squared, Q("9/10"));
  // (1,1) on the diagonal of the notch: (4/5,2/5) on edge 0 and (2/5,4/5) on edge 1, both at 2/5.
  EXPECT_EQ(frame_from_position(kStar, P(1, 1)).status, FrameStatus::kClosestNotUnique);
  // Reflex vertex (1/2,1/2): inward normals (-1/2,-3/2) and (-3/2,-1/2); (-1,-1) between them, (0,-1) not.
  EXPECT_EQ(frame_from_contact(kStar, P("1/2", "1/2"), P(-1, -1), Q(0)).status, FrameStatus::kOk);
  EXPECT_EQ(frame_from_contact(kStar, P("1/2", "1/2"), P(0, -1), Q(0)).status, FrameStatus::kNormalNotUnique);
  // Tip (2,0), convex: edge 7 ends there (inward normal perp((3/2,1/2)) = (-1/2,3/2)), edge 0 starts there
  // (perp((-3/2,1/2)) = (-1/2,-3/2)); their sum (-1,0) is in the cone, (1,0) is not.
  EXPECT_EQ(frame_from_contact(kStar, P(2, 0), P(-1, 0), Q(0)).status, FrameStatus::kOk);
  EXPECT_EQ(frame_from_contact(kStar, P(2, 0), P(1, 0), Q(0)).status, FrameStatus::kNormalNotUnique);
  EXPECT_EQ(frame_from_position(kStar, P(0, 0)).status, FrameStatus::kInsideWorkpiece);
}

TEST(ContactFrame, Disk) {
  const Shape disk = DiskShape{P(0, 0), Q(5)};
  FrameResult r = frame_from_position(disk, P(3, 4));
  ASSERT_EQ(r.status, FrameStatus::kOk);
  EXPECT_TRUE(r.frame.normal == P(-3, -4));
  r = frame_from_position(disk, P(6, 8));
  ASSERT_EQ(r.status, FrameStatus::kOk);
  EXPECT_TRUE(r.frame.point == P(3, 4));
  EXPECT_EQ(r.frame.gap_squared, Q(25));
  EXPECT_EQ(frame_from_position(disk, P(1, 1)).status, FrameStatus::kInsideWorkpiece);
  EXPECT_EQ(frame_from_position(disk, P(6, 1)).status, FrameStatus::kIrrationalDirection);
  EXPECT_EQ(frame_from_contact(disk, P(3, 4), P(-3, -4), Q(1)).status, FrameStatus::kOk);
  EXPECT_NE(frame_from_contact(disk, P(3, 4), P(-4, 3), Q(0)).status, FrameStatus::kOk);
}

}  // namespace
}  // namespace contactcert::geometry
