// Planar scenes: exact mass properties, contact frames from fixel positions, and the InputError
// table of SPEC section 3.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "exact/input_error.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"

namespace contactcert::geometry {
namespace {

using exact::parse_rational;

PlanarScene scene_from(const std::string& text) { return read_planar_scene(exact::JsonInput::parse(text, "scene.json")); }

Point2 pt(const char* x, const char* y) { return {parse_rational(x), parse_rational(y)}; }

TEST(Workpiece, ShoelaceCentroidAndInertiaOfARectangleAreExact) {
  const std::vector<Point2> box = {pt("0", "0"), pt("4", "0"), pt("4", "2"), pt("0", "2")};
  EXPECT_EQ(shoelace_area2(box), 16);
  EXPECT_TRUE(polygon_centroid(box) == pt("2", "1"));
  // I/m of a w x h rectangle about its centre: (w^2 + h^2) / 12 = 20/12.
  EXPECT_EQ(polygon_inertia_per_mass(box, pt("2", "1")), Q(5, 3));
  // Parallel axis: about the origin add |c|^2 = 5.
  EXPECT_EQ(polygon_inertia_per_mass(box, pt("0", "0")), Q(20, 3));
}

TEST(Workpiece, TriangleCentroidAndInertiaMatchClosedForms) {
  const std::vector<Point2> tri = {pt("0", "0"), pt("6", "0"), pt("2", "4")};
  EXPECT_TRUE(polygon_centroid(tri) == pt("8/3", "4/3"));
  // Triangle: I_c/m = (|a|^2 + |b|^2 + |c|^2)/36 over the side lengths: 36 + 20 + 32 = 88 -> 22/9.
  EXPECT_EQ(polygon_inertia_per_mass(tri, polygon_centroid(tri)), Q(22, 9));
}

TEST(Workpiece, DiskInertiaIsHalfRadiusSquared) {
  const PlanarScene s = scene_from(R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[1,2],"radius":"3/2"}},
    "fixels":[{"position":[1,"1/2"]}],"mu_s":0})");
  EXPECT_EQ(s.workpiece.inertia_per_mass, Q(9, 8));
  EXPECT_TRUE(s.workpiece.com == pt("1", "2"));
  EXPECT_TRUE(s.fixels[0].frame.touching());
}

TEST(Workpiece, NonConvexPolygonCentroid) {
  // An L shape: unit squares at (0,0), (1,0), (0,1): centroid (5/6, 5/6).
  const std::vector<Point2> L = {pt("0", "0"), pt("2", "0"), pt("2", "1"), pt("1", "1"), pt("1", "2"), pt("0", "2")};
  EXPECT_EQ(check_polygon(L).defect, PolygonDefect::kNone);
  EXPECT_TRUE(polygon_centroid(L) == pt("5/6", "5/6"));
}

TEST(Frames, DiskFixelsFollowTheErrataConvention) {
  const PlanarScene s = scene_from(R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1}},
    "fixels":[{"position":[0,-1]},{"position":["11/10",0]},{"position":["6/5","8/5"]}],"mu_s":"1/5"})");
  const ContactFrame& f1 = s.fixels[0].frame;
  EXPECT_TRUE(f1.touching());
  EXPECT_TRUE(f1.point == pt("0", "-1"));
  EXPECT_TRUE(f1.normal == pt("0", "1"));     // from the fixel toward the workpiece
  EXPECT_TRUE(f1.tangent() == pt("-1", "0"));  // t = (-n_y, n_x)
  const ContactFrame& f2 = s.fixels[1].frame;
  EXPECT_FALSE(f2.touching());
  EXPECT_EQ(f2.gap_squared, Q(1, 100));
  EXPECT_TRUE(f2.point == pt("1", "0"));
  // (6/5, 8/5) is at distance 2 from the centre: closest point (3/5, 4/5), gap 1.
  const ContactFrame& f3 = s.fixels[2].frame;
  EXPECT_TRUE(f3.point == pt("3/5", "4/5"));
  EXPECT_EQ(f3.gap_squared, 1);
  EXPECT_EQ(s.fixels[1].mu_k, Q(1, 5));  // mu_k defaults to mu_s
}

TEST(Frames, PolygonFixelsOnEdgesOutsideAndNearVertices) {
  const PlanarScene s = scene_from(R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[4,0],[4,2],[0,2]]}},
    "fixels":[{"position":[1,0]},{"position":[5,3]},{"position":["-1/2",1]},{"point":[4,2],"normal":[-1,-1],"gap":"1/3"}],
    "mu_s":"0.3","mu_k":"0.25"})");
  EXPECT_TRUE(s.fixels[0].frame.touching());
  EXPECT_EQ(sgn(s.fixels[0].frame.normal.x), 0);
  EXPECT_GT(sgn(s.fixels[0].frame.normal.y), 0);
  EXPECT_TRUE(s.fixels[1].frame.point == pt("4", "2"));  // closest point is the vertex
  EXPECT_TRUE(s.fixels[1].frame.normal == pt("-1", "-1"));
  EXPECT_EQ(s.fixels[1].frame.gap_squared, 2);
  EXPECT_TRUE(s.fixels[2].frame.point == pt("0", "1"));
  EXPECT_EQ(s.fixels[2].frame.gap_squared, Q(1, 4));
  EXPECT_EQ(s.fixels[3].frame.gap_squared, Q(1, 9));
  EXPECT_EQ(s.fixels[3].mu_k, Q(1, 4));
  EXPECT_EQ(s.workpiece.inertia_per_mass, Q(5, 3));
}

struct BadScene {
  const char* name;
  const char* json;
  const char* expected_in_message;
};

TEST(SceneInput, BadScenesAreInputErrorsThatSayWhatToFix) {
  const std::string disk = R"("workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1}})";
  const std::string box = R"("workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[4,0],[4,2],[0,2]]}})";
  const std::vector<BadScene> table = {
      {"fixel inside disk", R"({"kind":"planar",DISK,"fixels":[{"position":["1/2",0]}],"mu_s":1})", "inside"},
      {"fixel inside polygon", R"({"kind":"planar",BOX,"fixels":[{"position":[1,1]}],"mu_s":1})", "inside"},
      {"irrational disk direction", R"({"kind":"planar",DISK,"fixels":[{"position":[1,1]}],"mu_s":1})", "3/5, 4/5"},
      {"equidistant from two edges", R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[2,0],[2,1],[1,1],[1,2],[0,2]]}},"fixels":[{"position":["3/2","3/2"]}],"mu_s":1})", "equally close"},
      {"at a vertex without normal", R"({"kind":"planar",BOX,"fixels":[{"position":[4,2]}],"mu_s":1})", "explicit contact"},
      {"too few vertices", R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[1,0]]}},"fixels":[{"position":[5,5]}],"mu_s":1})", "at least 3"},
      {"clockwise polygon", R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[0,2],[4,2],[4,0]]}},"fixels":[{"position":[5,5]}],"mu_s":1})", "counter-clockwise"},
      {"collinear vertices", R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[1,0],[2,0],[1,1]]}},"fixels":[{"position":[5,5]}],"mu_s":1})", "collinear"},
      {"repeated vertex", R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[1,0],[1,0],[1,1]]}},"fixels":[{"position":[5,5]}],"mu_s":1})", "repeats"},
      {"self-intersecting", R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[2,2],[2,0],[0,2]]}},"fixels":[{"position":[5,5]}],"mu_s":1})", "simple polygon"},
      {"zero radius", R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":0}},"fixels":[{"position":[5,5]}],"mu_s":1})", "positive"},
      {"negative friction", R"({"kind":"planar",DISK,"fixels":[{"position":[0,-1]}],"mu_s":"-1/5"})", ">= 0"},
      {"missing friction", R"({"kind":"planar",DISK,"fixels":[{"position":[0,-1]}]})", "mu_s"},
      {"negative gap", R"({"kind":"planar",DISK,"fixels":[{"point":[0,-1],"normal":[0,1],"gap":-1}],"mu_s":1})", ">= 0"},
      {"point off the boundary", R"({"kind":"planar",DISK,"fixels":[{"point":[0,-2],"normal":[0,1],"gap":0}],"mu_s":1})", "boundary"},
      {"normal not at the centre", R"({"kind":"planar",DISK,"fixels":[{"point":[0,-1],"normal":[1,1],"gap":0}],"mu_s":1})", "centre"},
      {"normal out of the polygon", R"({"kind":"planar",BOX,"fixels":[{"point":[1,0],"normal":[0,-1],"gap":0}],"mu_s":1})", "edge"},
      {"zero normal", R"({"kind":"planar",BOX,"fixels":[{"point":[1,0],"normal":[0,0],"gap":0}],"mu_s":1})", "non-zero"},
      {"position and point", R"({"kind":"planar",BOX,"fixels":[{"position":[1,0],"point":[1,0]}],"mu_s":1})", "either"},
      {"unknown key", R"({"kind":"planar",BOX,"fixels":[{"position":[1,0]}],"mu_S":1})", "mu_S"},
      {"wrong kind", R"({"kind":"quasistatic",BOX,"fixels":[{"position":[1,0]}],"mu_s":1})", "planar"},
      {"no fixels", R"({"kind":"planar",BOX,"fixels":[],"mu_s":1})", "at least one"},
      {"inertia without mass", R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1},"inertia":1},"fixels":[{"position":[0,-1]}],"mu_s":1})", "mass"},
      {"float syntax error", R"({"kind":"planar",DISK,"fixels":[{"position":[0,"-1x"]}],"mu_s":1})", "fixels"},
      {"unknown shape", R"({"kind":"planar","workpiece":{"shape":{"type":"ellipse"}},"fixels":[{"position":[0,-1]}],"mu_s":1})", "polygon"},
  };
  for (const BadScene& b : table) {
    std::string text = b.json;
    for (auto [key, value] : {std::pair<std::string, std::string>{"DISK", disk}, {"BOX", box}})
      for (std::size_t at; (at = text.find(key)) != std::string::npos;) text.replace(at, key.size(), value);
    try {
      scene_from(text);
      ADD_FAILURE() << b.name << ": accepted";
    } catch (const exact::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(b.expected_in_message), std::string::npos) << b.name << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find("scene.json"), std::string::npos) << b.name << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace contactcert::geometry
