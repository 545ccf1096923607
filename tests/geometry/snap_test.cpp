// Float input snapped exactly (geometry/snap.h): points onto edges and circles, numbers to the simplest rational,
// every snap reported, idempotent, and what cannot be snapped refused with its field named.
#include "geometry/snap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"

namespace contactcert::geometry {
namespace {

Q q(const char* s) { return exact::parse_rational(s); }

std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// A disk of radius 2 at (1, -1) with fixels at the given positions (texts).
std::string disk_scene(const std::string& fixels) {
  return R"({"kind": "planar", "workpiece": {"shape": {"type": "disk", "center": [1, -1], "radius": 2}, "mass": 1,
  "inertia": 1}, "fixels": [)" +
         fixels + R"(], "mu_s": "1/2"})";
}

std::string square_scene(const std::string& fixels) {
  return R"({"kind": "planar", "name": "square", "workpiece": {"shape": {"type": "polygon", "vertices": [[0,0],[2,0],[2,2],[0,2]]}},
  "fixels": [)" +
         fixels + R"(], "mu_s": 0.30000000000000004})";
}

TEST(SimplestBetween, SmallestDenominatorInTheInterval) {
  EXPECT_EQ(simplest_between(q("0.30000000000000004") - q("1e-9"), q("0.30000000000000004") + q("1e-9")), q("3/10"));
  EXPECT_EQ(simplest_between(q("0.3"), q("0.4")), q("1/3"));
  EXPECT_EQ(simplest_between(q("-0.4"), q("-0.3")), q("-1/3"));
  EXPECT_EQ(simplest_between(q("-1/2"), q("1/3")), Q(0));
  EXPECT_EQ(simplest_between(q("2.5"), q("3.7")), Q(3));
  EXPECT_EQ(simplest_between(q("355/113"), q("355/113")), q("355/113"));
  EXPECT_EQ(simplest_between(q("3.14159"), q("3.1416")), q("355/113"));
}

TEST(CirclePoint, ExactlyOnTheCircleInEveryQuadrant) {
  const Point2 c{q("1"), q("-1")};
  for (long quadrant = 0; quadrant < 4; ++quadrant)
    for (const char* t : {"0", "1/3", "7/9", "123456789/987654321"})
      EXPECT_EQ(norm2(circle_point(c, Q(2), q(t), quadrant) - c), Q(4));
}

TEST(SnapScene, DiskFixelAtCosSinGoesExactlyOntoTheCircleAndIsAccepted) {
  const std::string x = num(1 + 2 * std::cos(0.3)), y = num(-1 + 2 * std::sin(0.3));
  const std::string text = disk_scene(R"({"position": [)" + x + ", " + y + "]}");
  EXPECT_THROW(read_planar_scene(exact::JsonInput::parse(text, "in")), exact::InputError);  // irrational distance
  const SnappedScene s = snap_planar_scene(text, "in", q("1e-9"));
  ASSERT_EQ(s.snaps.size(), 1u);
  EXPECT_EQ(s.snaps[0].field, "$.fixels[0].position");
  EXPECT_LE(s.snaps[0].distance_squared, q("1e-18"));
  const PlanarScene scene = read_planar_scene(exact::JsonInput::parse(s.text, "in"));
  ASSERT_EQ(scene.fixels.size(), 1u);
  const Point2 p = *scene.fixels[0].position;
  EXPECT_EQ(norm2(p - Point2{Q(1), Q(-1)}), Q(4));
  EXPECT_TRUE(scene.fixels[0].frame.touching());
  // Snapped twice: unchanged.
  const SnappedScene again = snap_planar_scene(s.text, "in", q("1e-9"));
  EXPECT_TRUE(again.snaps.empty());
  EXPECT_EQ(again.text, s.text);
}

TEST(SnapScene, DiskPointsInEveryQuadrantWithinTolerance) {
  for (double angle = 0.1; angle < 6.3; angle += 0.7) {
    const std::string text =
        disk_scene(R"({"point": [)" + num(1 + 2 * std::cos(angle)) + ", " + num(-1 + 2 * std::sin(angle)) +
                   R"(], "normal": [)" + num(-std::cos(angle)) + ", " + num(-std::sin(angle)) + R"(], "gap": 0})");
    const SnappedScene s = snap_planar_scene(text, "in", q("1e-6"));
    const PlanarScene scene = read_planar_scene(exact::JsonInput::parse(s.text, "in"));
    EXPECT_EQ(norm2(scene.fixels[0].frame.point - Point2{Q(1), Q(-1)}), Q(4)) << angle;
    for (const Snap& x : s.snaps) EXPECT_LE(x.distance_squared, q("1e-12")) << x.field;
  }
}

TEST(SnapScene, FarDiskPositionMovesToARationalDistance) {
  // 3 away from the centre along cos/sin 1.1: a gap fixel, kept outside at a rational distance.
  const std::string text =
      disk_scene(R"({"position": [)" + num(1 + 3 * std::cos(1.1)) + ", " + num(-1 + 3 * std::sin(1.1)) + "]}");
  const SnappedScene s = snap_planar_scene(text, "in", q("1e-9"));
  const PlanarScene scene = read_planar_scene(exact::JsonInput::parse(s.text, "in"));
  EXPECT_FALSE(scene.fixels[0].frame.touching());
  EXPECT_TRUE(snap_planar_scene(s.text, "in", q("1e-9")).snaps.empty());
}

TEST(SnapScene, PolygonPointProjectedOntoTheNearestEdge) {
  const SnappedScene s = snap_planar_scene(square_scene(R"({"position": [0.30000000000000004, -1e-12]},
    {"position": [2.0000000001, 0.7]}, {"position": [3, 1.5]})"),
                                           "in", q("1e-9"));
  const PlanarScene scene = read_planar_scene(exact::JsonInput::parse(s.text, "in"));
  EXPECT_EQ(*scene.fixels[0].position, (Point2{q("0.30000000000000004"), Q(0)}));  // exact projection
  EXPECT_EQ(*scene.fixels[1].position, (Point2{Q(2), q("0.7")}));
  EXPECT_EQ(*scene.fixels[2].position, (Point2{Q(3), q("3/2")}));  // not meant to touch: unchanged
  EXPECT_EQ(scene.fixels[0].mu_s, q("3/10"));                      // the plain number: 0.1 + 0.2 -> 3/10
  ASSERT_EQ(s.snaps.size(), 3u);
  EXPECT_EQ(s.snaps[0].field, "$.mu_s");
  EXPECT_EQ(s.snaps[0].original, "7500000000000001/25000000000000000");
  EXPECT_EQ(s.snaps[0].snapped, "3/10");
  EXPECT_EQ(s.snaps[1].field, "$.fixels[0].position");
  EXPECT_EQ(s.snaps[1].distance_squared, q("1e-24"));
  EXPECT_NE(s.text.find(R"("name": "square")"), std::string::npos);  // labels kept
  EXPECT_TRUE(snap_planar_scene(s.text, "in", q("1e-9")).snaps.empty());
}

TEST(SnapScene, RefusesWhatCannotBeSnappedNamingTheField) {
  const auto message = [](const std::string& text, const char* tol) {
    try {
      snap_planar_scene(text, "in.json", q(tol));
    } catch (const exact::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string far_point = square_scene(R"({"point": [1, -0.001], "normal": [0, 1], "gap": 0})");
  EXPECT_NE(message(far_point, "1e-9").find("in.json: $.fixels[0].point"), std::string::npos)
      << message(far_point, "1e-9");
  EXPECT_EQ(message(far_point, "1e-2"), "no error");
  const std::string off_disk =
      disk_scene(R"({"position": [3, -1]}, {"point": [3.1, -1], "normal": [-1, 0], "gap": 0})");
  EXPECT_NE(message(off_disk, "1e-9").find("$.fixels[1].point"), std::string::npos) << message(off_disk, "1e-9");
  const std::string centre = disk_scene(R"({"position": [1, -1]})");
  EXPECT_NE(message(centre, "1e-9").find("$.fixels[0].position"), std::string::npos);
  EXPECT_NE(message(disk_scene(""), "0").find("--snap"), std::string::npos);
}

}  // namespace
}  // namespace contactcert::geometry
