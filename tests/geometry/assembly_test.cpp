// Reading assemblies (geometry/assembly.h): defaults, frames from geometry, and every rejection naming its field;
// the exact overlap test of two shapes.
#include "geometry/assembly.h"

#include <gtest/gtest.h>

#include "geometry/shape_overlap.h"

namespace contactcert::geometry {
namespace {

using exact::InputError;
using exact::JsonInput;

Assembly read(const std::string& text) { return read_assembly(JsonInput::parse(text, "a.json")); }

/// The JSON path an InputError names, or "" if `text` reads.
std::string rejected_at(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.json_path;
  }
  return "";
}

const std::string kBox = R"({"type": "polygon", "vertices": [[0, 0], [2, 0], [2, 1], [0, 1]]})";
const std::string kTop = R"({"type": "polygon", "vertices": [[0, 1], [2, 1], [2, 2], [0, 2]]})";
const std::string kGround = R"({"type": "polygon", "vertices": [[-5, -1], [5, -1], [5, 0], [-5, 0]]})";

std::string scene(const std::string& bodies, const std::string& contacts, const std::string& more = "") {
  return R"({"kind": "planar", "mu_s": "1/2", "obstacles": [{"shape": )" + kGround + "}], \"bodies\": [" + bodies +
         "], \"contacts\": [" + contacts + "]" + more + "}";
}

TEST(AssemblyRead, DefaultsAndFramesFromGeometry) {
  const Assembly a = read(scene("{\"shape\": " + kBox + "}, {\"shape\": " + kTop + ", \"mass\": 3}",
                                R"({"from": {"obstacle": 0}, "to": {"body": 0}, "position": [1, 0]},
                                   {"from": {"body": 0}, "to": {"body": 1}, "position": ["1/2", 1], "mu_k": "1/4"},
                                   {"from": {"fixel": 0}, "to": {"body": 1}})",
                                R"(, "fixels": [{"position": [2, "3/2"]}], "gravity": [0, -10])"));
  ASSERT_EQ(a.bodies.size(), 2u);
  EXPECT_EQ(a.bodies[0].mass, Q(2));  // the area, density 1
  EXPECT_EQ(a.bodies[0].com.x, Q(1));
  EXPECT_EQ(a.bodies[0].inertia, Q(2) * Q(5, 12));  // m (w^2 + h^2) / 12
  EXPECT_EQ(a.bodies[0].load_fy, Q(-20));           // m g at the com
  EXPECT_EQ(a.bodies[1].load_fy, Q(-30));
  EXPECT_EQ(a.contacts[0].normal, (Point2{Q(0), Q(2)}));  // the edge's inward normal, not unit
  EXPECT_EQ(a.contacts[1].normal, (Point2{Q(0), Q(2)}));  // both edges agree
  EXPECT_EQ(a.contacts[1].mu_s, Q(1, 2));
  EXPECT_EQ(a.contacts[1].mu_k, Q(1, 4));
  // A fixel on the body's right edge: the edge's inward normal, from the fixel into the body.
  EXPECT_EQ(a.contacts[2].point, (Point2{Q(2), Q(3, 2)}));
  EXPECT_EQ(a.contacts[2].normal, (Point2{Q(-1), Q(0)}));
}

TEST(AssemblyRead, RejectionsNameTheField) {
  const std::string box = "{\"shape\": " + kBox + "}";
  const std::string ground_contact =
      R"({"from": {"obstacle": 0}, "to": {"body": 0}, "point": [0, 0], "normal": [0, 1]})";
  // Overlapping bodies (the second box shifted down into the first).
  EXPECT_EQ(rejected_at(scene(box + R"(, {"shape": {"type": "polygon", "vertices": [[1, "1/2"], [3, "1/2"], [3, 2],
                                       [1, 2]]}})",
                              ground_contact)),
            "$.bodies[1]");
  // Identical bodies overlap although no edge crosses another.
  EXPECT_EQ(rejected_at(scene(box + ", " + box, ground_contact)), "$.bodies[1]");
  // A contact point on one boundary only.
  EXPECT_EQ(rejected_at(scene(box, R"({"from": {"obstacle": 0}, "to": {"body": 0}, "point": [1, "1/2"],
                                      "normal": [0, 1]})")),
            "$.contacts[0]");
  // A normal that is not a common normal: slanted, and pointing out of `to`.
  EXPECT_EQ(rejected_at(scene(box, R"({"from": {"obstacle": 0}, "to": {"body": 0}, "point": [1, 0],
                                      "normal": [1, 1]})")),
            "$.contacts[0]");
  EXPECT_EQ(rejected_at(scene(box, R"({"from": {"obstacle": 0}, "to": {"body": 0}, "point": [1, 0],
                                      "normal": [0, -1]})")),
            "$.contacts[0]");
  // A disk has no exact default mass.
  EXPECT_EQ(rejected_at(scene(R"({"shape": {"type": "disk", "center": [0, 1], "radius": 1}})",
                              R"({"from": {"obstacle": 0}, "to": {"body": 0}, "point": [0, 0], "normal": [0, 1]})")),
            "$.bodies[0]");
  // Two fixed parties, a body with itself, an index out of range, a finger in a planar file.
  EXPECT_EQ(rejected_at(scene(box, R"({"from": {"obstacle": 0}, "to": {"fixel": 0}})",
                              R"(, "fixels": [{"position": [1, 0]}])")),
            "$.contacts[0]");
  EXPECT_EQ(rejected_at(scene(box, R"({"from": {"body": 0}, "to": {"body": 0}, "point": [1, 0], "normal": [0, 1]})")),
            "$.contacts[0]");
  EXPECT_EQ(
      rejected_at(scene(box, R"({"from": {"obstacle": 0}, "to": {"body": 1}, "point": [1, 0], "normal": [0, 1]})")),
      "$.contacts[0].to.body");
  EXPECT_EQ(rejected_at(scene(box, ground_contact, R"(, "fingers": [{"position": [0, 0], "velocity": [0, 1]}])")),
            "$.fingers");
  // A fixel inside a body; vertex against vertex without a normal.
  EXPECT_EQ(rejected_at(scene(box, ground_contact, R"(, "fixels": [{"position": [1, "1/2"]}])")), "$.fixels[0]");
  EXPECT_EQ(rejected_at(scene(
                box + ", {\"shape\": " + R"({"type": "polygon", "vertices": [[2, 1], [3, 1], [3, 2], [2, 2]]})" + "}",
                ground_contact + R"(, {"from": {"body": 0}, "to": {"body": 1}, "position": [2, 1]})")),
            "$.contacts[1]");
  // Friction: negative, or missing everywhere.
  EXPECT_EQ(rejected_at(scene(box, R"({"from": {"obstacle": 0}, "to": {"body": 0}, "point": [0, 0], "normal": [0, 1],
                                      "mu_s": "-1"})")),
            "$.contacts[0].mu_s");
  EXPECT_EQ(rejected_at(R"({"kind": "planar", "bodies": [)" + box + R"(], "fixels": [{"position": [1, 0]}],
                            "contacts": [{"from": {"fixel": 0}, "to": {"body": 0}}]})"),
            "$.contacts[0]");
}

TEST(AssemblyRead, OneWorkpieceFilesAreNotAssemblies) {
  const JsonInput one = JsonInput::parse(
      R"({"kind": "planar", "workpiece": {"shape": )" + kBox + R"(}, "fixels": [{"position": [1, 0]}], "mu_s": 1})",
      "one.json");
  EXPECT_FALSE(is_assembly(one));
  EXPECT_TRUE(is_assembly(JsonInput::parse(scene("{\"shape\": " + kBox + "}", "{}"), "a.json")));
}

Shape poly(std::initializer_list<std::pair<long, long>> v) {
  PolygonShape p;
  for (const auto& [x, y] : v) p.vertices.push_back({Q(x), Q(y)});
  return p;
}

TEST(ShapeOverlap, TouchingIsNotOverlapping) {
  const Shape a = poly({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  EXPECT_FALSE(interiors_overlap(a, poly({{2, 0}, {4, 0}, {4, 2}, {2, 2}})));  // a shared edge
  EXPECT_FALSE(interiors_overlap(a, poly({{2, 1}, {3, 1}, {3, 3}, {2, 3}})));  // part of an edge
  EXPECT_FALSE(interiors_overlap(a, poly({{2, 2}, {3, 2}, {3, 3}, {2, 3}})));  // a corner
  EXPECT_TRUE(interiors_overlap(a, a));
  EXPECT_TRUE(interiors_overlap(a, poly({{1, 1}, {3, 1}, {3, 3}, {1, 3}})));
  EXPECT_TRUE(interiors_overlap(a, poly({{-1, 1}, {3, 1}, {3, 2}, {-1, 2}})));    // a band through, no vertex inside
  EXPECT_TRUE(interiors_overlap(poly({{-1, -1}, {3, -1}, {3, 3}, {-1, 3}}), a));  // containment
  // A non-convex U around a box in its notch: they touch along three edges only.
  const Shape u = poly({{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});
  EXPECT_FALSE(interiors_overlap(u, poly({{1, 1}, {2, 1}, {2, 3}, {1, 3}})));
  EXPECT_TRUE(interiors_overlap(u, poly({{1, 1}, {2, 1}, {2, 3}, {0, 3}})));  // a part crosses into the left arm
  const Shape disk = DiskShape{{Q(1), Q(3)}, Q(1)};
  EXPECT_FALSE(interiors_overlap(a, disk));  // tangent to the top edge
  EXPECT_TRUE(interiors_overlap(a, DiskShape{{Q(1), Q(5, 2)}, Q(1)}));
  EXPECT_TRUE(interiors_overlap(a, DiskShape{{Q(1), Q(1)}, Q(1, 10)}));  // inside
  EXPECT_FALSE(interiors_overlap(disk, DiskShape{{Q(3), Q(3)}, Q(1)}));  // tangent disks
  EXPECT_TRUE(interiors_overlap(disk, DiskShape{{Q(2), Q(3)}, Q(1)}));
}

}  // namespace
}  // namespace contactcert::geometry
