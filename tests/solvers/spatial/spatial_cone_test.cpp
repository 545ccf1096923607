// The wrench cone of a spatial contact mode (solvers/spatial/spatial_cone.h) on the bundled box on a plane: the
// all-separating cone by hand, every cone against the mode's LP (spatial_stability.h's system) at seeded wrenches,
// and its "spatial_cone" certificate (spatial_cone_certificate.h) verified by the independent checker
// (checker/spatial_cone_check.h), which must reject forged ones.
#include "solvers/spatial/spatial_cone.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>

#include "checker/spatial_cone_check.h"
#include "runtime/scenes.h"
#include "solvers/spatial/spatial_cone_certificate.h"
#include "solvers/spatial/spatial_stability.h"

namespace contactcert::solvers::spatial {
namespace {

std::string text(const std::string& scene) {
  return exact::JsonInput::read_text(runtime::bundled_scenes_dir() + "/" + scene + ".json");
}

geometry::SpatialScene parse(const std::string& text) {
  return geometry::read_spatial_scene(exact::JsonInput::parse(text, "scene"));
}

geometry::SpatialScene box() { return parse(text("spatial_box_on_plane")); }

std::string certificate(const std::string& scene, const std::string& mode) {
  const std::string t = text(scene);
  const geometry::SpatialScene s = parse(t);
  return spatial_cone_certificate(t, s, mode, spatial_wrench_cone(s, mode));
}

checker::SpatialConeCheck check_json(const nlohmann::json& c) {
  return checker::check_spatial_cone_certificate(exact::JsonInput::parse(c.dump(), "certificate.json"));
}

// ssss: no contact force, vdot = M^-1 g, and each corner lifts: a_z + y_i alpha_x - x_i alpha_y > 0 with a = f
// and alpha = I^-1 tau (I diagonal), at (x_i, y_i) = (+-1, +-1): four strict rows on (f_z, tau_x, tau_y), the
// facets of a square cone there, so the cone is open, 6-dimensional, and its lineality is (f_x, f_y, tau_z).
TEST(SpatialCone, AllSeparatingIsOpenWithFourStrictRows) {
  const geometry::NncForm<Q> cone = spatial_wrench_cone(box(), "ssss");
  EXPECT_EQ(cone.dimension(), 6);
  EXPECT_EQ(cone.face.strict.rows(), 4);
  EXPECT_EQ(cone.face.inequalities.rows(), 0);
  EXPECT_EQ(cone.closure.lines.rows(), 3);
  Vec<Q> up = Vec<Q>::Zero(6), down = Vec<Q>::Zero(6);
  up(2) = 1;
  down(2) = -1;
  EXPECT_TRUE(geometry::contains_point(cone.face, up));
  EXPECT_FALSE(geometry::contains_point(cone.face, down));
}

// Each cone holds exactly the wrenches for which its mode's system is feasible: seeded integer wrenches against one
// strict-feasibility LP each, on modes that stick, separate, tip and slide.
TEST(SpatialCone, ConesAgreeWithTheModesLps) {
  const geometry::SpatialScene s = box();
  const SpatialModel model = spatial_model(s);
  std::mt19937 rng(34);
  std::uniform_int_distribution<int> entry(-2, 2);
  for (const char* mode : {"ffff", "ssss", "ffss", "EEEE"}) {
    const geometry::NncForm<Q> cone = spatial_wrench_cone(s, mode);
    const exact::SparseStrictSystem<Q> sys = spatial_motion_system(s.body, model, mode);
    int inside = 0;
    for (int trial = 0; trial < 40; ++trial) {
      Vec<Q> g(6);
      for (Eigen::Index d = 0; d < 6; ++d) g(d) = entry(rng);
      if (trial == 0) g << 0, 0, -1, 0, 0, 0;        // gravity: in ffff's cone
      if (trial == 1) g << 0, 0, -1, 0, 2, 0;        // the weight at x = 2: in ffss's (the box tips)
      if (trial == 2) g << Q(3, 5), 0, -1, 0, 0, 0;  // past atan(mu): in EEEE's (it slides)
      Vec<Q> b = Vec<Q>::Zero(sys.rows);
      b.tail(6) = g;
      const bool feasible = exact::StrictSolver<Q>(sys).solve(b).status == exact::StrictStatus::kFeasible;
      EXPECT_EQ(geometry::contains_point(cone.face, g), feasible) << mode << " trial " << trial;
      inside += feasible;
    }
    EXPECT_GT(inside, 0) << mode;  // both sides of every cone are tested
    EXPECT_LT(inside, 40) << mode;
  }
}

// Certificates of cones that stick, separate (lines and strict rows), slide, tip, and of empty cones, on the three
// bundled scenes: each verifies, and the checker's counts are the cone's.
TEST(SpatialCone, CertificatesVerify) {
  const std::pair<const char*, const char*> cases[] = {
      {"spatial_box_on_plane", "ffff"},    {"spatial_box_on_plane", "ssss"},    {"spatial_box_on_plane", "ffss"},
      {"spatial_box_on_plane", "EEEE"},    {"spatial_box_on_plane", "sssA"},    {"spatial_box_on_plane", "sAsB"},
      {"spatial_box_in_corner", "sssssA"}, {"spatial_box_in_corner", "ssssss"}, {"spatial_peg_in_hole", "AACGAACG"}};
  for (const auto& [scene, mode] : cases) {
    const geometry::NncForm<Q> cone = spatial_wrench_cone(parse(text(scene)), mode);
    const checker::SpatialConeCheck c = check_json(nlohmann::json::parse(certificate(scene, mode)));
    EXPECT_TRUE(c.valid) << scene << " " << mode << ": " << c.reason;
    EXPECT_EQ(c.dimension, cone.dimension()) << mode;
    if (cone.dimension() >= 0) {
      EXPECT_EQ(c.rays, cone.closure.rays.rows()) << mode;
      EXPECT_EQ(c.inequalities + c.strict, cone.face.inequalities.rows() + cone.face.strict.rows()) << mode;
    }
  }
}

// A body whose certificate LPs have rows of seven digits: the float LP of one runs out of pivots, and the exact one
// decides (exact/strict_feasibility.h's rounded step gives way instead of reading the unfinished point).
TEST(SpatialCone, CertificateWithLargeRowsVerifies) {
  const std::string t = R"({"kind": "spatial", "mu": "1/2",
    "body": {"mass": 1, "inertia": [[1, 0, 0], [0, 2, 0], [0, 0, 3]], "com": [2, 1, -1]},
    "contacts": [{"point": [-1, 0, 0], "normal": [-1, 2, -1]}, {"point": [-1, 2, -2], "normal": [1, 2, 1]},
                 {"point": [-1, 2, 0], "normal": [-1, 1, -2]}]})";
  const geometry::SpatialScene s = parse(t);
  const geometry::NncForm<Q> cone = spatial_wrench_cone(s, "sFD");
  EXPECT_EQ(cone.face.strict.rows(), 2);
  const checker::SpatialConeCheck c = check_json(nlohmann::json::parse(spatial_cone_certificate(t, s, "sFD", cone)));
  EXPECT_TRUE(c.valid) << c.reason;
}

// A facet dropped with its proof (the checker's own enumeration of the span form's facets finds it missing), a ray
// dropped with its point, a point moved, the same numbers for another mode, and a strict row written as an
// inequality (the checker's own enumeration of the faces finds the facet without a point of the cone): INVALID.
TEST(SpatialCone, ForgedCertificatesFail) {
  const nlohmann::json ffff = nlohmann::json::parse(certificate("spatial_box_on_plane", "ffff"));
  nlohmann::json c = ffff;
  c["cone"]["face"]["inequalities"].erase(0);
  c["inequalities"].erase(0);
  checker::SpatialConeCheck r = check_json(c);
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.reason.find("is no row of the face form"), std::string::npos) << r.reason;

  c = ffff;
  c["cone"]["span"]["rays"].erase(3);
  c["rays"].erase(3);
  EXPECT_FALSE(check_json(c).valid);

  c = ffff;
  c["rays"][0][6] = "1";
  r = check_json(c);
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.reason.find("the point of ray 0"), std::string::npos) << r.reason;

  c = ffff;
  c["mode"] = "fffB";  // as many columns as ffff
  EXPECT_FALSE(check_json(c).valid);

  const nlohmann::json ssss = nlohmann::json::parse(certificate("spatial_box_on_plane", "ssss"));
  // A strict row written as an inequality, its proof moved along (a . g < 0 on the cone gives a . g <= 0 on the
  // closure): the face form would hold the facet's relative interior, which the cone does not meet.
  c = ssss;
  c["cone"]["face"]["inequalities"].push_back(c["cone"]["face"]["strict"][0]);
  c["inequalities"].push_back(c["strict"][0]);
  c["cone"]["face"]["strict"].erase(0);
  c["strict"].erase(0);
  c["cone"]["open_faces"].erase(3);  // [0, 1]: the face of strict row 0
  r = check_json(c);
  EXPECT_FALSE(r.valid);
  EXPECT_NE(r.reason.find("no point of the cone is given on the face of the closure through rays 0 1,"),
            std::string::npos)
      << r.reason;
}

}  // namespace
}  // namespace contactcert::solvers::spatial
