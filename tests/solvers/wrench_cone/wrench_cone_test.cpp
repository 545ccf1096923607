// The wrench cones themselves: the section 4 example, both routes on every mode of several scenes,
// invariance under scaling a frame, the kinematically feasible modes of section 7.
#include "solvers/wrench_cone/wrench_cone.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <string>

#include "exact/rational_text.h"
#include "geometry/canonical.h"
#include "geometry/scene_json.h"
#include "runtime/scenes.h"

namespace contactcert::solvers {
namespace {

using geometry::PlanarScene;

PlanarScene load(const std::string& name) {
  return geometry::load_planar_scene(contactcert::runtime::bundled_scenes_dir() + "/" + name);
}
PlanarScene parse(const std::string& text) {
  return geometry::read_planar_scene(exact::JsonInput::parse(text, "test.json"));
}

std::vector<bool> touching_of(const PlanarScene& s) {
  std::vector<bool> t;
  for (const auto& f : s.fixels) t.push_back(f.frame.touching());
  return t;
}

ModeString mode_of(const PlanarScene& s, const std::string& text) {
  const ModeParse p = parse_mode(text, touching_of(s));
  EXPECT_EQ(p.status, ModeStatus::kValid) << p.message;
  return p.mode;
}

/// Every mode of the scene: each fixel takes every letter that fits it.
std::vector<ModeString> all_modes(const PlanarScene& s) {
  std::vector<ModeString> out(1);
  for (const auto& f : s.fixels) {
    std::vector<ModeString> next;
    for (const ModeString& m : out)
      for (Interaction l : letters_for(f.frame.touching())) {
        ModeString e = m;
        e.letters.push_back(l);
        next.push_back(e);
      }
    out = next;
  }
  return out;
}

std::vector<std::vector<long>> rows_of(const Mat<Q>& M) {
  std::vector<std::vector<long>> out;
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    std::vector<long> r;
    for (Eigen::Index j = 0; j < M.cols(); ++j) r.push_back(M(i, j).get_num().get_si());
    out.push_back(r);
  }
  return out;
}

TEST(Section4Cone, BothRoutesGiveThePapersGeneratorsWithTheFrictionFaceOpen) {
  const PlanarScene s = load("bt2002_section4_disk.json");
  for (Route route : {Route::kPaper, Route::kProject}) {
    const WrenchCone<Q> c = wrench_cone<Q>(s, mode_of(s, "na"), route);
    ASSERT_EQ(c.status, ConeStatus::kNonEmpty);
    const auto rays = rows_of(c.cone.closure.rays);
    const std::set<std::vector<long>> got(rays.begin(), rays.end());
    const std::set<std::vector<long>> want = {{1, 0, -1}, {-1, -5, -1}, {1, -5, 1}};
    EXPECT_EQ(got, want);
    EXPECT_EQ(c.cone.closure.lines.rows(), 0);
    // Exactly one open face: the one spanned by the two friction edges g2, g3 (z1 = -a2n > 0).
    ASSERT_EQ(c.cone.open_faces.size(), 1u);
    std::set<std::vector<long>> open;
    for (Eigen::Index i : c.cone.open_faces[0]) open.insert(rays[static_cast<std::size_t>(i)]);
    EXPECT_EQ(open, (std::set<std::vector<long>>{{-1, -5, -1}, {1, -5, 1}}));
    // The origin is excluded, a point of the open face is excluded, g1 and interior points are in.
    EXPECT_FALSE(geometry::contains_point(c.cone.face, Vec<Q>(Vec<Q>::Zero(3))));
    EXPECT_FALSE(geometry::contains_point(c.cone.face, Vec<Q>((Vec<Q>(3) << 0, -10, 0).finished())));
    EXPECT_TRUE(geometry::contains_point(c.cone.face, Vec<Q>((Vec<Q>(3) << 1, 0, -1).finished())));
    EXPECT_TRUE(geometry::contains_point(c.cone.face, Vec<Q>((Vec<Q>(3) << 1, -10, -1).finished())));
    EXPECT_EQ(c.cone.face.inequalities.rows() + c.cone.face.strict.rows(), 3);
    EXPECT_EQ(c.cone.face.strict.rows(), 1);
  }
}

TEST(Section4Cone, FloatPathAgreesWithTheExactCone) {
  const PlanarScene s = load("bt2002_section4_disk.json");
  const WrenchCone<double> c = wrench_cone<double>(s, mode_of(s, "na"), Route::kPaper);
  ASSERT_EQ(c.status, ConeStatus::kNonEmpty);
  EXPECT_EQ(c.cone.closure.rays.rows(), 3);
  EXPECT_EQ(c.cone.face.strict.rows(), 1);
}

TEST(Section4Cone, MinimumAccelerationCutsTheConeAtTheRequestedAcceleration) {
  const PlanarScene s = parse(R"({"kind":"planar",
    "workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1},"mass":1,"inertia":1},
    "fixels":[{"position":[0,-1]},{"point":[1,0],"normal":[-1,0],"gap":"1/10"}],"mu_s":"0.2"})");
  const geometry::AffineFace<Q> set = wrench_set_with_minimum_acceleration<Q>(s, mode_of(s, "na"), Q(1));
  auto inside = [&](Vec<Q> g) {
    for (Eigen::Index i = 0; i < set.A.rows(); ++i)
      if (Q(set.A.row(i).dot(g)) > set.b(i)) return false;
    for (Eigen::Index i = 0; i < set.C.rows(); ++i)
      if (Q(set.C.row(i).dot(g)) != set.c(i)) return false;
    return true;
  };
  // g = z1 g1 with g1 = (1, 0, -1): the approach acceleration -a2n is z1.
  EXPECT_TRUE(inside((Vec<Q>(3) << 2, 0, -2).finished()));
  EXPECT_TRUE(inside((Vec<Q>(3) << 1, 0, -1).finished()));
  EXPECT_FALSE(inside((Vec<Q>(3) << Q(1, 2), 0, Q(-1, 2)).finished()));
}

TEST(Routes, BothRoutesWithAndWithoutRowReductionAgreeOnEveryModeOfThreeFixelScenes) {
  const std::vector<PlanarScene> scenes = {
      parse(R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1}},
        "fixels":[{"position":[0,-1]},{"position":[1,0]},{"position":["-3/5","4/5"]}],"mu_s":"1/2","mu_k":"2/5"})"),
      load("bt2002_fig4a_lla.json"), load("bt2002_fig4b_nnn.json"), load("bt2002_fig4c_peg_lra.json")};
  int compared = 0, nonempty = 0;
  for (const PlanarScene& s : scenes) {
    const ContactModel<Q> m = contact_model<Q>(s);
    for (const ModeString& mode : all_modes(s)) {
      const geometry::FaceCone<Q> a = wrench_cone_face(s, m, mode, Route::kPaper);
      const geometry::FaceCone<Q> b = wrench_cone_face(s, m, mode, Route::kProject);
      EXPECT_TRUE(geometry::identical(a, b)) << mode.text();
      // The literal K and P of eqs. (15) and (17), without the row reduction, give the same cone.
      const geometry::FaceCone<Q> c = wrench_cone_face(s, m, mode, Route::kPaper, {}, Preconditioning::kNone);
      EXPECT_TRUE(geometry::identical(a, c)) << mode.text();
      nonempty += is_empty_cone(a) ? 0 : 1;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 125 + 75 + 125 + 75);
  EXPECT_GT(nonempty, 0);
  EXPECT_LT(nonempty, compared);
}

TEST(Routes, AgreeOnRandomScenesAndModes) {
  std::mt19937_64 rng(20260);
  std::uniform_int_distribution<int> coord(-6, 6), letter(0, 6), pick(0, 3);
  int compared = 0;
  for (int t = 0; t < 60; ++t) {
    // A random box with fixels on its edges (touching) or beyond its edges (gap).
    std::string fixels;
    const int n = 1 + t % 4;
    for (int i = 0; i < n; ++i) {
      const int side = pick(rng), along = 1 + (coord(rng) + 6) % 3, gap = letter(rng) % 2;
      int x = 0, y = 0;
      if (side == 0) {
        x = along;
        y = -gap;
      } else if (side == 1) {
        x = 4 + gap;
        y = along % 2 + 1;
      } else if (side == 2) {
        x = along;
        y = 3 + gap;
      } else {
        x = -gap;
        y = along % 2 + 1;
      }
      if (i) fixels += ",";
      fixels += "{\"position\":[";
      fixels += std::to_string(x);
      fixels += ",";
      fixels += std::to_string(y);
      fixels += "]}";
    }
    const PlanarScene s = parse(
        R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[4,0],[4,3],[0,3]]},"com":[)" +
        std::to_string(1 + t % 3) + ",1]},\"fixels\":[" + fixels + "],\"mu_s\":\"" + std::to_string(t % 5) +
        "/4\",\"mu_k\":\"1/3\"}");
    const ContactModel<Q> m = contact_model<Q>(s);
    const std::vector<ModeString> modes = all_modes(s);
    for (int k = 0; k < 6; ++k) {
      const ModeString& mode = modes[static_cast<std::size_t>(rng() % modes.size())];
      const geometry::FaceCone<Q> a = wrench_cone_face(s, m, mode, Route::kPaper);
      EXPECT_TRUE(geometry::identical(a, wrench_cone_face(s, m, mode, Route::kProject))) << t << " " << mode.text();
      EXPECT_TRUE(geometry::identical(a, wrench_cone_face(s, m, mode, Route::kProject, {}, Preconditioning::kNone)))
          << t << " " << mode.text();
      ++compared;
    }
  }
  EXPECT_EQ(compared, 360);
}

// Numbers that outgrow 64-bit integers part way (radius 10^3, mu with large denominators) or at once
// (radius 10^12): the exact path restarts in GMP integers and every route still agrees.
TEST(Routes, AgreeOnEveryModeWithHugeCoordinates) {
  // Fixels at (0, -r), (r, 0) and (-3r/5, 4r/5) on a disk of radius r.
  const std::vector<std::array<std::string, 3>> sizes = {{"1000", "-600", "800"},
                                                         {"1000000000000", "-600000000000", "800000000000"}};
  for (const auto& [r, x, y] : sizes) {
    const PlanarScene s = parse(R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":)" + r +
                                R"(}},"fixels":[{"position":[0,-)" + r + R"(]},{"position":[)" + r +
                                R"(,0]},{"position":[)" + x + "," + y + R"(]}],"mu_s":"123457/999983","mu_k":"2/5"})");
    const ContactModel<Q> m = contact_model<Q>(s);
    int nonempty = 0;
    for (const ModeString& mode : all_modes(s)) {
      const geometry::FaceCone<Q> a = wrench_cone_face(s, m, mode, Route::kPaper);
      EXPECT_TRUE(geometry::identical(a, wrench_cone_face(s, m, mode, Route::kProject))) << r << " " << mode.text();
      EXPECT_TRUE(geometry::identical(a, wrench_cone_face(s, m, mode, Route::kPaper, {}, Preconditioning::kNone)))
          << r << " " << mode.text();
      nonempty += is_empty_cone(a) ? 0 : 1;
    }
    EXPECT_GT(nonempty, 0);
  }
}

// A friction coefficient 3/2^62 against A_ii = 625: the integer K z = P g overflows std::int64_t as it
// is read from the (machine-integer) model, and the paper's route restarts in Z.
TEST(Routes, AgreeOnEveryModeWhenTheFrictionDenominatorOverflows) {
  const PlanarScene s = parse(R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":5}},
    "fixels":[{"position":[3,-4]},{"position":[-4,-3]},{"position":[5,0]}],
    "mu_s":"3/4611686018427387904","mu_k":"1/4611686018427387903"})");
  const ContactModel<Q> m = contact_model<Q>(s);
  EXPECT_FALSE(m.A.is_wide());
  int nonempty = 0;
  for (const ModeString& mode : all_modes(s)) {
    const geometry::FaceCone<Q> a = wrench_cone_face(s, m, mode, Route::kPaper);
    EXPECT_TRUE(geometry::identical(a, wrench_cone_face(s, m, mode, Route::kPaper, {}, Preconditioning::kNone)))
        << mode.text();
    EXPECT_TRUE(geometry::identical(a, wrench_cone_face(s, m, mode, Route::kProject))) << mode.text();
    nonempty += is_empty_cone(a) ? 0 : 1;
  }
  EXPECT_GT(nonempty, 0);
}

TEST(Invariance, ScalingAContactFrameLeavesEveryConeUnchanged) {
  const std::string base =
      R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[4,0],[4,2],[0,2]]}},"fixels":[)";
  const PlanarScene unit = parse(
      base +
      R"({"point":[1,0],"normal":[0,1],"gap":0},{"point":[4,1],"normal":[-1,0],"gap":0},{"point":[0,1],"normal":[1,0],"gap":"1/2"}],"mu_s":"1/3"})");
  const PlanarScene scaled = parse(
      base +
      R"({"point":[1,0],"normal":[0,"7/3"],"gap":0},{"point":[4,1],"normal":[-5,0],"gap":0},{"point":[0,1],"normal":["1/9",0],"gap":"1/2"}],"mu_s":"1/3"})");
  const ContactModel<Q> mu = contact_model<Q>(unit), ms = contact_model<Q>(scaled);
  int nonempty = 0;
  for (const ModeString& mode : all_modes(unit)) {
    const geometry::FaceCone<Q> a = wrench_cone_face(unit, mu, mode, Route::kPaper);
    EXPECT_TRUE(geometry::identical(a, wrench_cone_face(scaled, ms, mode, Route::kPaper))) << mode.text();
    EXPECT_TRUE(geometry::identical(a, wrench_cone_face(scaled, ms, mode, Route::kProject))) << mode.text();
    nonempty += is_empty_cone(a) ? 0 : 1;
  }
  EXPECT_GT(nonempty, 10);
}

TEST(Section7, TheKinematicallyFeasibleModesOfTheDiskAreThePapersList) {
  const PlanarScene s = load("bt2002_section7_disk.json");
  std::set<std::string> nonempty;
  for (Route route : {Route::kPaper, Route::kProject}) {
    nonempty.clear();
    for (char a : std::string("slrn"))
      for (char b : std::string("slrn")) {
        const std::string text{a, b};
        if (text == "nn") continue;
        if (wrench_cone<Q>(s, mode_of(s, text), route).status == ConeStatus::kNonEmpty) nonempty.insert(text);
      }
    EXPECT_EQ(nonempty, (std::set<std::string>{"ss", "sl", "sr", "sn", "ls", "ll", "rs", "rr", "ns"}));
  }
  // 'nn' holds the origin (a resting workpiece under no load).
  const WrenchCone<Q> nn = wrench_cone<Q>(s, mode_of(s, "nn"), Route::kPaper);
  EXPECT_EQ(nn.status, ConeStatus::kNonEmpty);
  EXPECT_TRUE(geometry::contains_point(nn.cone.face, Vec<Q>(Vec<Q>::Zero(3))));
}

TEST(Empty, KinematicallyImpossibleModesGiveEmptyCones) {
  const PlanarScene s = load("bt2002_section7_disk.json");
  for (const char* text : {"lr", "rl", "nl", "ln", "nr", "rn"}) {
    const WrenchCone<Q> c = wrench_cone<Q>(s, mode_of(s, text), Route::kPaper);
    EXPECT_EQ(c.status, ConeStatus::kEmpty) << text;
    EXPECT_TRUE(is_empty_cone(c.cone.face)) << text;
  }
}

}  // namespace
}  // namespace contactcert::solvers
