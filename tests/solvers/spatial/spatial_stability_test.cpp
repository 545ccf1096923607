// Strong stability of a body in space (solvers/spatial/spatial_stability.h), hand-derived on the bundled box on a
// plane (a 2 x 2 x 1 box of mass 1, its 4 bottom corners at x, y = +-1 on the plane z = 0, com at height 1/2, square
// pyramids with mu = 1/2 along x and y), and extruded planar scenes against the planar verdicts; every certificate
// verified by the independent checker (checker/spatial_stability_check.h).
#include "solvers/spatial/spatial_stability.h"

#include <gtest/gtest.h>

#include "checker/spatial_stability_check.h"
#include "geometry/scene_json.h"
#include "runtime/scenes.h"
#include "solvers/spatial/spatial_stability_certificate.h"
#include "tests/solvers/spatial/extruded_scene.h"

namespace contactcert::solvers::spatial {
namespace {

using geometry::SpatialScene;

std::string box_text() {
  return exact::JsonInput::read_text(runtime::bundled_scenes_dir() + "/spatial_box_on_plane.json");
}

Vec<Q> wrench(const std::vector<Q>& g) {
  Vec<Q> v(6);
  for (Eigen::Index i = 0; i < 6; ++i) v(i) = g[static_cast<std::size_t>(i)];
  return v;
}

// The verdict on the box, its certificate checked.
SpatialStability on_box(const Vec<Q>& g) {
  const std::string text = box_text();
  const SpatialScene s = geometry::read_spatial_scene(exact::JsonInput::parse(text, "box"));
  SpatialStability r = spatial_stability(s, g);
  const auto check = checker::check_spatial_stability_certificate(
      checker::CertificateLines(spatial_stability_certificate(s, text, g, r), "certificate.json"));
  EXPECT_TRUE(check.valid) << check.reason;
  return r;
}

// Gravity g = (0, 0, -1) (no torque about the com): normal forces at the corners balance it (1/4 each, or any
// balanced split), and no mode moves: a moving solution has vdot^T M vdot = -a_z + sum_i c_i . A_i vdot with each
// contact term <= 0 (c_n a_n = 0, friction opposes sliding), so -a_z > 0; but every corner has a_n = a_z + (alpha x
// r)_z >= 0 and the four (alpha x r)_z sum to zero, so a_z >= 0. Strongly stable, with a proof for each of the 339
// feasible moving modes of the box (its 340 modes but f..f) and its dead prefixes.
TEST(SpatialStability, BoxUnderGravityIsStronglyStable) {
  const SpatialStability r = on_box(wrench({0, 0, -1, 0, 0, 0}));
  EXPECT_EQ(r.verdict, StabilityVerdict::kStronglyStable);
  EXPECT_FALSE(r.has_moving);
  EXPECT_EQ(r.modes_kinematically_feasible, 339);
  EXPECT_EQ(r.proofs.size(), 339u);
  EXPECT_EQ(r.tree.dead.size(), static_cast<std::size_t>(r.dead_prefixes));
  // Most moving modes take a recent mode's Motzkin vector moved to their rows (the certificate checks above).
  EXPECT_GT(r.modes_by_reuse, 339 / 2);
  EXPECT_LT(r.modes_by_reuse, r.modes_checked);
}

// The certificate in lines (docs/formats.md section 5c) names each Motzkin vector once: the box's 2 199 dead prefixes
// (by parent) and 339 modes share 186 vectors, and a vector applied to rows it does not prove is INVALID: the last
// mode's vector named by the first dead prefix (it weighs Newton-Euler rows a prefix does not have), or a dead
// prefix's vector named by a mode whose rows lack the functionals it weighs.
TEST(SpatialStability, CertificateNamesEachVectorOnce) {
  const std::string text = box_text();
  const SpatialScene s = geometry::read_spatial_scene(exact::JsonInput::parse(text, "box"));
  const Vec<Q> g = wrench({0, 0, -1, 0, 0, 0});
  const SpatialStability r = spatial_stability(s, g);
  const std::string cert = spatial_stability_certificate(s, text, g, r);
  const checker::CertificateLines c(cert, "certificate.json");
  std::size_t dead = 0;
  for (std::size_t i = 0; i < c.size("dead"); ++i) dead += c.element("dead", i).at("letters").string().size();
  EXPECT_EQ(dead, static_cast<std::size_t>(r.dead_prefixes));
  EXPECT_EQ(c.size("modes"), 339u);
  EXPECT_EQ(c.size("vectors"), 186u);
  // Edits of one index in the text, each checked.
  auto checked = [&](const std::string& from, const std::string& to) {
    std::string t = cert;
    const std::size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) t.replace(at, from.size(), to);
    return checker::check_spatial_stability_certificate(checker::CertificateLines(t, "forged.json"));
  };
  const std::string last_mode = c.element("modes", 338).at("mode").string();
  const long mode_vector = c.element("modes", 338).at("vector").integer(0, 185);
  const long dead_vector = c.element("dead", 0).at("vectors").at(0).integer(0, 185);
  const std::string first_dead = "\"vectors\":[" + std::to_string(dead_vector);
  auto bad = checked(first_dead, "\"vectors\":[" + std::to_string(mode_vector));
  EXPECT_FALSE(bad.valid);
  EXPECT_NE(bad.reason.find("the kinematic proof for prefix"), std::string::npos) << bad.reason;
  const std::string mode_line = "{\"mode\":\"" + last_mode + "\",\"vector\":" + std::to_string(mode_vector) + "}";
  bad = checked(mode_line, "{\"mode\":\"" + last_mode + "\",\"vector\":" + std::to_string(dead_vector) + "}");
  EXPECT_FALSE(bad.valid);
  EXPECT_EQ(bad.reason, "the proof for mode " + last_mode + " does not verify");
}

// The verdict keeps the tree's sparse proofs and the certificate writes each proof's line once, from the first
// prefix it proves (no dense vector per dead prefix): that is the line of every prefix it proves, as each prefix's
// vector is the first one's moved by functional (move_rows). Box under gravity: 2 199 dead prefixes, fewer proofs.
TEST(SpatialStability, EachTreeProofIsOneVectorOnEveryPrefixItProves) {
  const SpatialScene s = geometry::read_spatial_scene(exact::JsonInput::parse(box_text(), "box"));
  const SpatialStability r = spatial_stability(s, wrench({0, 0, -1, 0, 0, 0}));
  const SpatialModel model = spatial_model(s);
  ASSERT_EQ(r.tree.dead.size(), static_cast<std::size_t>(r.dead_prefixes));
  std::vector<const SpatialDeadPrefix*> first(r.tree.proofs.size(), nullptr);
  std::size_t shared = 0;
  for (const SpatialDeadPrefix& d : r.tree.dead) {
    ASSERT_LT(d.proof, first.size());
    if (!first[d.proof]) {
      first[d.proof] = &d;
      continue;
    }
    ++shared;
    const SpatialDeadPrefix& f = *first[d.proof];
    ASSERT_EQ(f.prefix.size(), d.prefix.size());
    EXPECT_EQ(move_rows(model, f.prefix, dead_motzkin(r.tree, f), d.prefix), dead_motzkin(r.tree, d)) << d.prefix;
  }
  EXPECT_GT(shared, r.tree.dead.size() / 2);
  EXPECT_TRUE(r.tree.modes.empty());
}

// move_rows: a weight goes to the row of the same functional at its contact (s's a_n > 0 onto f's a_n = 0; the
// trailing rows copied), or nowhere if the target letter lacks it (f's t1 row under s).
TEST(SpatialStability, MotzkinRowsMoveByFunctional) {
  const SpatialModel model = spatial_model(geometry::read_spatial_scene(exact::JsonInput::parse(box_text(), "box")));
  Vec<Q> y = Vec<Q>::Zero(4 + 2);  // ssss: one row per contact, then two rows of another kind
  y(1) = -1;
  y(5) = 3;
  const Vec<Q> moved = move_rows(model, "ssss", y, "sfss");  // rows s | f f f | s | s | 2 more
  ASSERT_EQ(moved.size(), 1 + 3 + 1 + 1 + 2);
  EXPECT_EQ(moved(1), Q(-1));
  EXPECT_EQ(moved(7), Q(3));
  EXPECT_EQ(moved.head(7).cwiseAbs().sum(), Q(1));
  Vec<Q> t1 = Vec<Q>::Zero(3 + 3);  // fss s: the t1 row of contact 0 weighed
  t1(1) = 1;
  EXPECT_EQ(move_rows(model, "fsss", t1, "ssss").size(), 0);
}

// Gravity with a horizontal part 3/5 > mu x 1 (the plane tilted past atan(1/2)): friction holds at most 1/2 of the
// normal load 1, so no resting solution; the box slides along +x in mode EEEE (friction along edge 2, -t1, at every
// corner) with a_x = 3/5 - 1/2 = 1/10 and no rotation (friction c_n / 2 per corner, sum c_n = 1; the friction's
// torque about the com, at r_z = -1/2, is balanced by more normal force at x = 1 than at x = -1).
TEST(SpatialStability, BoxOnATiltedPlaneSlides) {
  const SpatialStability r = on_box(wrench({Q(3, 5), 0, -1, 0, 0, 0}));
  EXPECT_EQ(r.verdict, StabilityVerdict::kUnstable);
  ASSERT_TRUE(r.has_moving);
  EXPECT_EQ(r.moving.mode, "EEEE");
  EXPECT_EQ(r.moving.acceleration, wrench({Q(1, 10), 0, 0, 0, 0, 0}));
  // Below atan(mu): 2/5 < 1/2, the box rests and nothing moves.
  EXPECT_EQ(on_box(wrench({Q(2, 5), 0, -1, 0, 0, 0})).verdict, StabilityVerdict::kStronglyStable);
}

// The weight applied at x = 2 (com outside the support square [-1, 1]^2): g = (0, 0, -1) with torque
// (2, 0, 0) x (0, 0, -1) = (0, 2, 0) about the com. No forces at the corners balance it (their torques about the com
// in y are at most the weight times 1); the box tips about its edge x = 1: the corners at x = 1 stick (f), those at
// x = -1 lift (s), alpha_y > 0.
TEST(SpatialStability, BoxWithItsWeightOutsideTheSupportTips) {
  const SpatialStability r = on_box(wrench({0, 0, -1, 0, 2, 0}));
  EXPECT_EQ(r.verdict, StabilityVerdict::kUnstable);
  ASSERT_TRUE(r.has_moving);
  EXPECT_EQ(r.moving.mode, "ffss");
  EXPECT_GT(r.moving.acceleration(4), 0);
}

// A planar scene extruded (extruded_scene.h: its touching fixels, with the scene's mu) under the planar wrench (fx, fy,
// 0, 0, 0, tz) has the planar verdict, for scenes with mu_s = mu_k > 0.
TEST(SpatialStability, ExtrudedPlanarScenesHaveThePlanarVerdicts) {
  const std::vector<std::vector<Q>> wrenches = {{0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, -1, 1}, {1, -2, -1}};
  for (const char* name : {"bt2002_fig4d_peg_nn", "bt2002_section7_disk", "bt2002_fig10_pentagon_insert"}) {
    const geometry::PlanarScene full =
        geometry::load_planar_scene(runtime::bundled_scenes_dir() + "/" + name + ".json");
    const geometry::PlanarScene ps = touching_scene(full);
    const SpatialScene s = extruded(ps, /*mu_of_fixels=*/true);
    for (const std::vector<Q>& g : wrenches) {
      Vec<Q> g3(3), g6 = Vec<Q>::Zero(6);
      g3 << g[0], g[1], g[2];
      g6 << g[0], g[1], 0, 0, 0, g[2];
      EXPECT_EQ(spatial_stability(s, g6).verdict, strong_stability<Q>(full, g3).verdict)
          << name << " g = (" << g[0] << ", " << g[1] << ", " << g[2] << ")";
    }
  }
}

}  // namespace
}  // namespace contactcert::solvers::spatial
