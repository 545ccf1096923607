// The pushed box of issue 32 (a 2 x 2 box on a floor, mu = 1, a frictionless finger at height h pushing along +x
// with speed 1, weight 1 at the centre): it slides for h < 1 (the push needed to slide, mu N = 1, is below the
// push that tips it about the front corner, 1 / h), tips for h > 1, and can do both at h = 1.
#include "solvers/motion/simulate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "checker/ucp_check.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "runtime/scenes.h"
#include "solvers/motion/bounded.h"
#include "solvers/motion/compare.h"
#include "solvers/ucp/certificate.h"

namespace contactcert::solvers::motion {
namespace {

using geometry::Vec2;

const char* kFloor = R"({"name": "floor", "vertices": [[-10, -1], [10, -1], [10, 0], [-10, 0]], "mu": 1})";

/// The pushed box with the finger at height h, extra obstacles, N steps of H.
MotionScene pushed_box(const std::string& h, const std::string& extra_obstacles = "", const std::string& dt = "1/10",
                       long steps = 5) {
  const std::string text = R"({"kind": "quasistatic_scene",
    "workpiece": {"shape": {"type": "polygon", "vertices": [[0, 0], [2, 0], [2, 2], [0, 2]]}, "com": [1, 1]},
    "gravity": [0, -1],
    "obstacles": [)" + std::string(kFloor) +
                           extra_obstacles + R"(],
    "fingers": [{"name": "pusher", "tip": [0, ")" +
                           h + R"("], "mu": 0, "schedule": [{"velocity": [1, 0]}]}],
    "motion": {"dt": ")" + dt +
                           R"(", "steps": )" + std::to_string(steps) + "}}";
  return read_motion_scene(exact::JsonInput::parse(text, "pushed_box.json"));
}

SimulateOptions exact_options(exact::Arith arith = exact::Arith::kVerified) {
  SimulateOptions o;
  o.arith = arith;
  return o;
}

/// A bundled motion scene (scenes/NAME).
MotionScene bundled(const std::string& name) {
  return read_motion_scene(exact::JsonInput::load(runtime::bundled_scenes_dir() + "/" + name));
}

/// Every step's certificate is accepted by the existing checker, and no recorded pose overlaps a shape.
void expect_certified_and_apart(const MotionScene& scene, const Trajectory<Q>& run) {
  const SceneGeometry<Q> g = scene_geometry<Q>(scene);
  for (const StepRecord<Q>& s : run.steps) {
    ASSERT_FALSE(s.certificate.empty()) << "step " << s.index;
    const checker::CertificateCheck c = checker::check_ucp_certificate(exact::JsonInput::parse(s.certificate, "step"));
    EXPECT_EQ(c.verdict, checker::CertificateVerdict::kValid) << "step " << s.index << ": " << c.reason;
    EXPECT_EQ(overlap(g, s.poses_after, s.tips_after), "") << "step " << s.index;
  }
}

TEST(PushedBox, LowPushSlidesByExactlyNHV) {
  const MotionScene scene = pushed_box("1/2", "", "1/10", 8);
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.status, RunStatus::kCompleted) << run.reason;
  ASSERT_EQ(run.steps.size(), 8u);
  for (const StepRecord<Q>& s : run.steps) {
    EXPECT_EQ(s.twists[0].v, (Vec2<Q>{Q(1), Q(0)}));
    EXPECT_EQ(s.twists[0].omega, Q(0));
    ASSERT_TRUE(s.uniqueness);
    EXPECT_EQ(s.uniqueness->status, UniquenessStatus::kUnique) << "step " << s.index;
    EXPECT_TRUE(s.cut_by.empty());
  }
  // N H v = 8 * 1/10 * 1, exactly; no rotation.
  EXPECT_EQ(run.final_poses[0].t, (Vec2<Q>{Q(4, 5), Q(0)}));
  EXPECT_EQ(run.final_poses[0].c, Q(1));
  EXPECT_EQ(run.final_time, Q(4, 5));
  // The three contacts at every step: both floor corners slide along -t (t = (-20, 0)), the finger slides.
  EXPECT_EQ(run.steps[0].contacts.size(), 3u);
  for (const ContactRecord<Q>& c : run.steps[3].contacts) {
    if (c.name.rfind("body vertex", 0) == 0) {
      EXPECT_EQ(c.mode, '-') << c.name;
    }
  }
  // Forces in world coordinates: the floor carries the weight, friction mu N = 1 balances the push.
  Q fx(0), fy(0);
  for (const ContactRecord<Q>& c : run.steps[0].contacts) {
    fx += c.force().x;
    fy += c.force().y;
  }
  EXPECT_EQ(fx, Q(0));
  EXPECT_EQ(fy, Q(1));
  expect_certified_and_apart(scene, run);
}

TEST(PushedBox, HighPushTipsAboutTheFrontCorner) {
  const MotionScene scene = pushed_box("3/2", "", "1/10", 6);
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.status, RunStatus::kCompleted) << run.reason;
  ASSERT_EQ(run.steps.size(), 6u);
  const Vec2<Q> corner{Q(2), Q(0)}, body_corner{Q(2), Q(0)};
  for (const StepRecord<Q>& s : run.steps) {
    EXPECT_LT(s.twists[0].omega, 0) << "step " << s.index;  // clockwise
    EXPECT_EQ(s.poses_after[0].apply(body_corner), corner) << "step " << s.index;
    EXPECT_EQ(s.poses_after[0].c * s.poses_after[0].c + s.poses_after[0].s * s.poses_after[0].s, Q(1));
    ASSERT_TRUE(s.uniqueness);
    EXPECT_EQ(s.uniqueness->status, UniquenessStatus::kUnique) << "step " << s.index;
  }
  // The first step: omega = -2/3 (the finger's speed 1 at lever 3/2), the rear corner lifts (broken at step 1).
  EXPECT_EQ(run.steps[0].twists[0].omega, Q(-2, 3));
  EXPECT_EQ(run.steps[1].broken, std::vector<std::string>{"body vertex 0 on floor edge 2"});
  for (const ContactRecord<Q>& c : run.steps[0].contacts) {
    if (c.name == "body vertex 0 on floor edge 2") {
      EXPECT_EQ(c.mode, 's');
    }
    if (c.name == "body vertex 1 on floor edge 2") {
      EXPECT_EQ(c.mode, 'r');
    }
  }
  expect_certified_and_apart(scene, run);
}

TEST(PushedBox, PushAtHeightOneHasTwoMotions) {
  const MotionScene scene = pushed_box("1", "", "1/10", 1);
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.steps.size(), 1u);
  const auto& u = run.steps[0].uniqueness;
  ASSERT_TRUE(u);
  EXPECT_EQ(u->status, UniquenessStatus::kNotUnique);
  // Sliding (q_dot = (1, 0, 0)) and tipping about (2, 0) with omega = -1 (q_dot = (0, 2, -1)) are both solutions.
  const auto has = [&](const Q& a, const Q& b, const Q& c) {
    for (const exact::Vec<Q>& m : u->motions)
      if (m(0) == a && m(1) == b && m(2) == c) return true;
    return false;
  };
  EXPECT_TRUE(has(Q(1), Q(0), Q(0)));
  EXPECT_TRUE(has(Q(0), Q(2), Q(-1)));
  for (const exact::Vec<Q>& m : u->motions)
    std::cout << "motion " << exact::to_string(m(0)) << " " << exact::to_string(m(1)) << " " << exact::to_string(m(2))
              << "\n";
  expect_certified_and_apart(scene, run);
}

TEST(PushedBox, BlockIntoAWallStopsWithAJammingProof) {
  // A wall 1 away: the third step is cut exactly when the box's front face reaches it (t = 1), then the box jams.
  const MotionScene scene =
      pushed_box("1/2", R"(, {"name": "wall", "vertices": [[3, -1], [5, -1], [5, 5], [3, 5]], "mu": 1})", "2/5", 10);
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.status, RunStatus::kJammed) << run.reason;
  ASSERT_EQ(run.steps.size(), 4u);
  EXPECT_EQ(run.steps[2].h, Q(1, 5));
  EXPECT_TRUE(run.steps[2].cut_exact);
  EXPECT_NE(run.steps[2].cut_by.find("wall"), std::string::npos);
  EXPECT_EQ(run.steps[3].time, Q(1));
  EXPECT_EQ(run.steps[3].made.size(), 2u);  // both front corners on the wall
  EXPECT_EQ(run.steps[3].verdict, ucp::UcpStatus::kJammed);
  const checker::CertificateCheck c =
      checker::check_ucp_certificate(exact::JsonInput::parse(run.steps[3].certificate, "jam"));
  EXPECT_EQ(c.verdict, checker::CertificateVerdict::kValid) << c.reason;
  EXPECT_EQ(c.kind, "ucp_jammed");
  expect_certified_and_apart(scene, run);
}

TEST(PushedBox, ExactAndVerifiedAgree) {
  const MotionScene scene = pushed_box("3/2", "", "1/10", 3);
  SimulateOptions fast = exact_options(exact::Arith::kExact);
  fast.uniqueness = false;
  const Trajectory<Q> a = simulate<Q>(scene, fast);
  const Trajectory<Q> b = simulate<Q>(scene, exact_options());
  ASSERT_EQ(a.steps.size(), b.steps.size());
  EXPECT_EQ(a.final_poses[0].t, b.final_poses[0].t);
  EXPECT_EQ(a.final_poses[0].s, b.final_poses[0].s);
}

TEST(FloatDrift, SlidingBoxDriftsOnlyByRounding) {
  // The float path's least-squares twist has |v_y|, |omega| ~ 1e-18: its poses, checked exactly, dip into the floor
  // by rounding (the report says so), but every verdict, contact and mode agrees with the exact run.
  const MotionScene scene = pushed_box("1/2", "", "1/10", 5);
  const Trajectory<Q> ex = simulate<Q>(scene, exact_options());
  const Trajectory<double> fl = simulate<double>(scene, exact_options(exact::Arith::kFloat));
  for (const Divergence& d : compare_runs(scene, ex, fl)) {
    EXPECT_EQ(d.kind, "penetration") << d.what;
    EXPECT_LT(d.pose_distance, 1e-12);
  }
  ASSERT_EQ(fl.status, RunStatus::kCompleted);
  EXPECT_NEAR(fl.final_poses[0].t.x, 0.5, 1e-12);
}

TEST(FloatDrift, TheFloatRunUsesTheNearestDoubles) {
  // The scene's rationals rounded to nearest (GMP's get_d truncates 1/10 to 0.09999999999999999, a float step
  // that no float simulator given "0.1" would take).
  const Trajectory<double> fl = simulate<double>(pushed_box("1/2", "", "1/10", 2), exact_options(exact::Arith::kFloat));
  ASSERT_EQ(fl.steps.size(), 2u);
  EXPECT_EQ(fl.steps[0].h, 0.1);
  EXPECT_EQ(fl.steps[1].time, 0.1);
  EXPECT_EQ(exact::nearest_double(Q(2, 3)), 2.0 / 3.0);
  EXPECT_EQ(exact::nearest_double(Q(-1, 10)), -0.1);
}

TEST(FloatDrift, GrazingCeilingIsAPhantomContactInFloat) {
  // A ceiling 10^-12 above the box's top: exactly, the box slides under it untouched; the float path's sign
  // tolerance (1e-9) takes the gap for a contact.
  const MotionScene scene = pushed_box(
      "1/2",
      R"(, {"name": "ceiling", "vertices": [[-1, "2.000000000001"], [9, "2.000000000001"], [9, 3], [-1, 3]], "mu": 1})",
      "1/10", 3);
  const Trajectory<Q> ex = simulate<Q>(scene, exact_options());
  ASSERT_EQ(ex.status, RunStatus::kCompleted) << ex.reason;
  const Trajectory<double> fl = simulate<double>(scene, exact_options(exact::Arith::kFloat));
  const std::vector<Divergence> d = compare_runs(scene, ex, fl);
  ASSERT_FALSE(d.empty());
  EXPECT_EQ(d[0].step, 0);
  EXPECT_EQ(d[0].kind, "contacts");
  EXPECT_EQ(d[0].what, "phantom contact: body vertex 2 on ceiling edge 0");
}

}  // namespace
}  // namespace contactcert::solvers::motion

namespace contactcert::solvers::motion {
namespace {

// The tipping box (h = 3/2, omega = -2/3 about the front corner (2, 0)) caught by a post. Its top-right corner
// (2, 2) is at (2 + 2 s, 2 c) with s = 2|u|/(1 + u^2), c = (1 - u^2)/(1 + u^2), u = omega tau / 2 = -tau / 3.
TEST(TippingBox, CaughtByAPostAtTheDerivedTime) {
  // Post face at x = 16/5: 4|u|/(1 + u^2) = 6/5, |u| = 1/3 (or 3): tau = 1 exactly, the corner at (16/5, 8/5).
  const MotionScene scene = pushed_box(
      "3/2", R"(, {"name": "post", "vertices": [["16/5", 0], [5, 0], [5, 3], ["16/5", 3]], "mu": 1})", "6/5", 4);
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_GE(run.steps.size(), 2u) << run.reason;
  EXPECT_EQ(run.steps[0].h, Q(1));
  EXPECT_TRUE(run.steps[0].cut_exact);
  EXPECT_EQ(run.steps[0].cut_by, "body vertex 2 on post edge 3");
  EXPECT_EQ(run.steps[0].poses_after[0].apply(Vec2<Q>{Q(2), Q(2)}), (Vec2<Q>{Q(16, 5), Q(8, 5)}));
  // Step 1: the post contact is made, the rear corner's floor contact is broken; pinned, the box jams.
  EXPECT_EQ(run.steps[1].made, std::vector<std::string>{"body vertex 2 on post edge 3"});
  EXPECT_EQ(run.steps[1].broken, std::vector<std::string>{"body vertex 0 on floor edge 2"});
  EXPECT_EQ(run.status, RunStatus::kJammed) << run.reason;
  expect_certified_and_apart(scene, run);
}

TEST(TippingBox, IrrationalFirstContactStopsJustBeforeIt) {
  // Post face at x = 3: u^2 - 4|u| + 1 = 0, |u| = 2 - sqrt(3), tau = 3 (2 - sqrt(3)) = 0.80384...
  const MotionScene scene =
      pushed_box("3/2", R"(, {"name": "post", "vertices": [[3, 0], [5, 0], [5, 3], [3, 3]], "mu": 1})", "1", 3);
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.status, RunStatus::kIrrationalContactTime) << run.reason;
  ASSERT_EQ(run.steps.size(), 1u);
  EXPECT_FALSE(run.steps[0].cut_exact);
  const double tau = 3 * (2 - std::sqrt(3.0));
  EXPECT_LT(run.steps[0].h, Q(tau));
  EXPECT_GT(run.steps[0].h, Q(tau - 1e-9));
  // Just before: the corner is left of the post face, exactly.
  EXPECT_LT(run.steps[0].poses_after[0].apply(Vec2<Q>{Q(2), Q(2)}).x, Q(3));
  expect_certified_and_apart(scene, run);
}

}  // namespace
}  // namespace contactcert::solvers::motion

namespace contactcert::solvers::motion {
namespace {

TEST(TippingBox, FingerSlidingToTheBodysCornerCutsTheStep) {
  // The carried finger slides down the rear face at 4/3 relative to it (from height 3/2): it reaches the bottom-left
  // body vertex 0 after 9/8 (in the body's frame the slide is linear); there the contact normal is not determined.
  const MotionScene scene = pushed_box("3/2", "", "2", 3);
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.steps.size(), 1u);
  EXPECT_EQ(run.steps[0].h, Q(9, 8));
  EXPECT_EQ(run.steps[0].cut_by, "finger pusher reaches body vertex 0");
  EXPECT_EQ(run.steps[0].tips_after[0], run.steps[0].poses_after[0].apply(Vec2<Q>{Q(0), Q(0)}));
  EXPECT_EQ(run.status, RunStatus::kUnsupportedContact) << run.reason;
}

TEST(FloatDrift, NearThresholdPush) {
  // h = 1 + 10^-12: exactly, the box tips about its front corner, and that is its only motion. Tipping, the carried
  // finger slides down the tilting face (relative velocity 2 along it) to below height 1, where neither tipping
  // (friction 1.002 N needed at the pivot) nor sliding (the rear corner is off the floor) balances: step 1 has no
  // quasistatic equilibrium, proven (Y is empty).
  const MotionScene scene = pushed_box("1.000000000001", "", "1/10", 3);
  const Trajectory<Q> ex = simulate<Q>(scene, exact_options());
  ASSERT_EQ(ex.steps.size(), 2u) << ex.reason;
  EXPECT_LT(ex.steps[0].twists[0].omega, 0);
  ASSERT_TRUE(ex.steps[0].uniqueness);
  EXPECT_EQ(ex.steps[0].uniqueness->status, UniquenessStatus::kUnique);
  EXPECT_EQ(ex.status, RunStatus::kJammed);
  EXPECT_EQ(ex.steps[1].reason, "Y is empty");
  expect_certified_and_apart(scene, ex);
  // The float run, step by step against the exact one.
  const Trajectory<double> fl = simulate<double>(scene, exact_options(exact::Arith::kFloat));
  const std::vector<Divergence> d = compare_runs(scene, ex, fl);
  for (const Divergence& x : d) {
    std::cout << "near threshold, float vs exact: step " << x.step << " " << x.kind << ": " << x.what
              << "; pose distance " << x.pose_distance << "\n";
    EXPECT_LT(x.pose_distance, 1e-12);
  }
}

TEST(MotionScene, BadInputNamesTheField) {
  const auto read = [](const std::string& obstacles, const std::string& schedule) {
    const std::string text = R"({"kind": "quasistatic_scene",
      "workpiece": {"shape": {"type": "polygon", "vertices": [[0, 0], [2, 0], [2, 2], [0, 2]]}},
      "obstacles": [)" + obstacles +
                             R"(], "fingers": [{"tip": [0, 1], "mu": 0, "schedule": )" + schedule + R"(}],
      "motion": {"dt": "1/10", "steps": 3}})";
    try {
      read_motion_scene(exact::JsonInput::parse(text, "s.json"));
    } catch (const exact::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string floor = kFloor;
  EXPECT_EQ(read(floor, R"([{"velocity": [1, 0]}])"), "");
  EXPECT_NE(
      read(R"({"vertices": [[0, -1], [4, -1], [2, "-1/2"], [4, 0], [0, 0]], "mu": 1})", R"([{"velocity": [1, 0]}])")
          .find("$.obstacles[0].vertices"),
      std::string::npos);
  EXPECT_NE(read(floor, R"([{"velocity": [1, 0]}, {"force": [1, 0]}])").find("$.fingers[0].schedule[0]"),
            std::string::npos);
  EXPECT_NE(read(floor, R"([{"velocity": [1, 0], "force": [1, 0]}])").find("exactly one of"), std::string::npos);
}

TEST(PushedBox, ACorruptedStepCertificateIsRefused) {
  const MotionScene scene =
      pushed_box("1/2", R"(, {"name": "wall", "vertices": [[3, -1], [5, -1], [5, 5], [3, 5]], "mu": 1})", "1", 3);
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.status, RunStatus::kJammed);
  nlohmann::json cert = nlohmann::json::parse(run.steps.back().certificate);
  auto& farkas = cert["nodes"][0]["farkas"];
  ASSERT_TRUE(farkas.is_array());
  farkas[0] = farkas[0].is_string() ? nlohmann::json(std::to_string(std::stol(farkas[0].get<std::string>()) + 1))
                                    : nlohmann::json(farkas[0].get<long>() + 1);
  const checker::CertificateCheck c = checker::check_ucp_certificate(exact::JsonInput::parse(cert.dump(), "forged"));
  EXPECT_EQ(c.verdict, checker::CertificateVerdict::kInvalid);
}

}  // namespace
}  // namespace contactcert::solvers::motion

namespace contactcert::solvers::motion {
namespace {

TEST(Schedule, AStepIsCutAtTheScheduleChangeAndAForceFingerHolds) {
  // Velocity 1 for 3/20, then a force 1/2 (below the friction mu N = 1): the box slides 3/20, then rests.
  const std::string text = R"({"kind": "quasistatic_scene",
    "workpiece": {"shape": {"type": "polygon", "vertices": [[0, 0], [2, 0], [2, 2], [0, 2]]}, "com": [1, 1]},
    "gravity": [0, -1], "obstacles": [)" +
                           std::string(kFloor) + R"(],
    "fingers": [{"name": "pusher", "tip": [0, "1/2"], "mu": 0,
                 "schedule": [{"duration": "3/20", "velocity": [1, 0]}, {"force": ["1/2", 0]}]}],
    "motion": {"dt": "1/10", "steps": 4}})";
  const MotionScene scene = read_motion_scene(exact::JsonInput::parse(text, "schedule.json"));
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.status, RunStatus::kCompleted) << run.reason;
  ASSERT_EQ(run.steps.size(), 4u);
  EXPECT_EQ(run.steps[0].h, Q(1, 10));
  EXPECT_EQ(run.steps[1].h, Q(1, 20));  // cut at the schedule change, 3/20
  EXPECT_EQ(run.steps[1].cut_by, "schedule change of finger pusher");
  EXPECT_EQ(run.steps[1].twists[0].v, (Vec2<Q>{Q(1), Q(0)}));
  for (std::size_t k = 2; k < 4; ++k) {
    EXPECT_EQ(run.steps[k].twists[0].v, (Vec2<Q>{Q(0), Q(0)}));
    EXPECT_EQ(run.steps[k].twists[0].omega, Q(0));
    ASSERT_TRUE(run.steps[k].uniqueness);
    EXPECT_EQ(run.steps[k].uniqueness->status, UniquenessStatus::kUnique);
  }
  EXPECT_EQ(run.final_poses[0].t, (Vec2<Q>{Q(3, 20), Q(0)}));
  EXPECT_EQ(run.final_time, Q(7, 20));
  // The force finger pushes with 1/2 (world force on the body), friction holds it.
  for (const ContactRecord<Q>& c : run.steps[2].contacts)
    if (c.name == "finger pusher on body edge 3") {
      EXPECT_EQ(c.force(), (Vec2<Q>{Q(1, 2), Q(0)}));
    }
  expect_certified_and_apart(scene, run);
}

}  // namespace
}  // namespace contactcert::solvers::motion

namespace contactcert::solvers::motion {
namespace {

TEST(BundledScene, PushedBoxTipsForFiveSteps) {
  const MotionScene scene = bundled("motion_pushed_box.json");
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.status, RunStatus::kCompleted) << run.reason;
  ASSERT_EQ(run.steps.size(), 5u);
  EXPECT_EQ(run.final_poses[0].apply(Vec2<Q>{Q(2), Q(0)}), (Vec2<Q>{Q(2), Q(0)}));
  EXPECT_EQ(run.final_time, Q(1, 2));
  expect_certified_and_apart(scene, run);
}

}  // namespace
}  // namespace contactcert::solvers::motion

namespace contactcert::solvers::motion {
namespace {

TEST(Budget, TheTimeLimitEndsTheRunUnknownWithTheStepsDone) {
  SimulateOptions o = exact_options();
  o.time_limit = 1e-9;  // passed before the first step
  const Trajectory<Q> run = simulate<Q>(pushed_box("1/2", "", "1/10", 1000), o);
  EXPECT_EQ(run.status, RunStatus::kUnknown);
  EXPECT_EQ(run.reason, "time limit after 0 steps");
  EXPECT_TRUE(run.steps.empty());
}

}  // namespace
}  // namespace contactcert::solvers::motion

namespace contactcert::solvers::motion {
namespace {

TEST(FirstContact, AnObstacleVertexMeetsTheSlidingFace) {
  // A frictionless wedge whose tip (3, 1) points at the box's front face (x = 2 + t): it closes at t = 1 (a cut
  // step of 1/10). Pushed low and held high, the box then turns up (omega = 2 about (1, 1)): its rear corner slides
  // on the floor, the wedge tip slides down its face (both kept exactly on their lines), and its front corner
  // rises to the wedge's lower edge at an irrational time, where the run stops just before.
  const MotionScene scene =
      pushed_box("1/2", R"(, {"name": "wedge", "vertices": [[3, 1], [5, 0], [5, 2]], "mu": 0})", "3/10", 10);
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.steps.size(), 5u) << run.reason;
  EXPECT_EQ(run.steps[3].h, Q(1, 10));
  EXPECT_EQ(run.steps[3].cut_by, "wedge vertex 0 on body edge 1");
  EXPECT_EQ(run.steps[4].made, std::vector<std::string>{"wedge vertex 0 on body edge 1"});
  EXPECT_EQ(run.steps[4].twists[0].omega, Q(2));
  EXPECT_EQ(run.steps[4].twists[0].v, (Vec2<Q>{Q(2), Q(-2)}));
  EXPECT_EQ(run.steps[4].cut_by, "body vertex 1 on wedge edge 0");
  EXPECT_EQ(run.status, RunStatus::kIrrationalContactTime);
  const Pose<Q>& p = run.steps[4].poses_after[0];
  const Vec2<Q> a = p.apply(Vec2<Q>{Q(2), Q(0)}), b = p.apply(Vec2<Q>{Q(2), Q(2)});
  EXPECT_EQ(cross2(Vec2<Q>{b.x - a.x, b.y - a.y}, Vec2<Q>{Q(3) - a.x, Q(1) - a.y}), Q(0));  // tip on the face
  EXPECT_EQ(p.apply(Vec2<Q>{Q(0), Q(0)}).y, Q(0));                                          // rear corner on the floor
  expect_certified_and_apart(scene, run);
}

TEST(FirstContact, AFreeFingerMeetsTheBody) {
  // A second finger at (3, 1) moving left at 1 meets the box's front face (moving right at 1) at t = 1/2 (a cut
  // step of 1/10). Squeezed, the box turns up (omega = 4) and the stopper slides down its face to the body's
  // corner (2, 0) after 1/8, where the contact normal is not determined: the run stops there.
  const std::string text = R"({"kind": "quasistatic_scene",
    "workpiece": {"shape": {"type": "polygon", "vertices": [[0, 0], [2, 0], [2, 2], [0, 2]]}, "com": [1, 1]},
    "gravity": [0, -1], "obstacles": [)" +
                           std::string(kFloor) + R"(],
    "fingers": [{"name": "pusher", "tip": [0, "1/2"], "mu": 0, "schedule": [{"velocity": [1, 0]}]},
                {"name": "stopper", "tip": [3, 1], "mu": 0, "schedule": [{"velocity": [-1, 0]}]}],
    "motion": {"dt": "1/5", "steps": 10}})";
  const MotionScene scene = read_motion_scene(exact::JsonInput::parse(text, "two_fingers.json"));
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.steps.size(), 4u) << run.reason;
  EXPECT_EQ(run.steps[2].h, Q(1, 10));
  EXPECT_EQ(run.steps[2].cut_by, "finger stopper on body edge 1");
  EXPECT_EQ(run.steps[3].made, std::vector<std::string>{"finger stopper on body edge 1"});
  EXPECT_EQ(run.steps[3].twists[0].omega, Q(4));
  EXPECT_EQ(run.steps[3].h, Q(1, 8));
  EXPECT_EQ(run.steps[3].cut_by, "finger stopper reaches body vertex 1");
  EXPECT_EQ(run.steps[3].tips_after[1], run.steps[3].poses_after[0].apply(Vec2<Q>{Q(2), Q(0)}));
  EXPECT_EQ(run.status, RunStatus::kUnsupportedContact);
  expect_certified_and_apart(scene, run);
}

}  // namespace
}  // namespace contactcert::solvers::motion

namespace contactcert::solvers::motion {
namespace {

/// The names of the contacts of a step whose name contains `part`.
std::vector<std::string> contacts_with(const StepRecord<Q>& s, const std::string& part) {
  std::vector<std::string> out;
  for (const ContactRecord<Q>& c : s.contacts)
    if (c.name.find(part) != std::string::npos) out.push_back(c.name);
  return out;
}

TEST(PegInChamferedHole, MakesAndBreaksContactsAtTheDerivedSteps) {
  // scenes/motion_peg_chamfer.json: the peg [0, 2] x [2, 6] is lowered by the gripper's fingers at speed 1, so its
  // bottom is at y = 2 - t and its sides stay at x = 0 and 2, 1/4 inside the hole's walls (x = -1/4, 9/4) and
  // clear of the chamfers (which lie outside the walls' lines). The bottom y = -6 is reached at t = 8. Steps of
  // H = 3/4 start at 3k/4: k = 10 starts at 15/2 and is cut at 8 (h = 1/2) by the first corner found, vertex 0;
  // from step 11 (t = 8) both bottom corners rest on the bottom edge and the peg stays still (the fingers slide
  // down its faces, 1/2 below their start by t = 9, far from its corners). The gripper opens at t = 9: step 12
  // (t = 35/4) is cut at 9 (h = 1/4) by the schedule; in step 13 both fingers move away (v_n > 0, mode s); from
  // step 14 (t = 39/4) their contacts are gone. The final pose is the translation (0, -8), exactly.
  const MotionScene scene = bundled("motion_peg_chamfer.json");
  const Trajectory<Q> run = simulate<Q>(scene, exact_options());
  ASSERT_EQ(run.status, RunStatus::kCompleted) << run.reason;
  ASSERT_EQ(run.steps.size(), 16u);
  const std::vector<std::string> bottom{"body vertex 0 on bottom edge 2", "body vertex 1 on bottom edge 2"},
      fingers{"finger left on body edge 3", "finger right on body edge 1"}, none;
  for (const StepRecord<Q>& s : run.steps) {
    const long k = s.index;
    // t = 3k/4 up to the cut at 8, then 8 + 3(k - 11)/4 up to the cut at 9, then 9 + 3(k - 13)/4.
    const Q start = k <= 10 ? Q(0) : (k <= 12 ? Q(8) : Q(9)), first = k <= 10 ? 0 : (k <= 12 ? 11 : 13);
    EXPECT_EQ(s.time, Q(start + Q(3 * (k - first)) / 4)) << "step " << k;
    EXPECT_EQ(contacts_with(s, "bottom"), k >= 11 ? bottom : none) << "step " << k;
    EXPECT_EQ(contacts_with(s, "finger"), k <= 13 ? fingers : none) << "step " << k;
    EXPECT_EQ(contacts_with(s, "left edge"), none) << "step " << k;  // the chamfers and walls: never touched
    EXPECT_EQ(contacts_with(s, "right edge"), none) << "step " << k;
    EXPECT_EQ(s.made, k == 0 ? fingers : (k == 11 ? bottom : none)) << "step " << k;
    EXPECT_EQ(s.broken, k == 14 ? fingers : none) << "step " << k;
    EXPECT_EQ(s.twists[0].omega, Q(0)) << "step " << k;
    EXPECT_EQ(s.twists[0].v, (Vec2<Q>{Q(0), Q(k <= 10 ? -1 : 0)})) << "step " << k;
  }
  EXPECT_EQ(run.steps[10].h, Q(1, 2));
  EXPECT_EQ(run.steps[10].cut_by, "body vertex 0 on bottom edge 2");
  EXPECT_EQ(run.steps[12].h, Q(1, 4));
  EXPECT_EQ(run.steps[12].cut_by, "schedule change of finger left");
  for (const ContactRecord<Q>& c : run.steps[13].contacts) {
    if (c.name.rfind("finger", 0) == 0) {
      EXPECT_EQ(c.mode, 's') << c.name;
    }
  }
  EXPECT_EQ(run.final_poses[0].t, (Vec2<Q>{Q(0), Q(-8)}));
  EXPECT_EQ(run.final_poses[0].c, Q(1));
  expect_certified_and_apart(scene, run);
}

TEST(Bounded, OnGridRoundsToTheNearestMultipleOfTwoToMinus40) {
  const Q unit(1, exact::Z(1) << 40);
  EXPECT_EQ(on_grid(Q(1, 3)), 366503875925 * unit);  // 2^40 / 3 = 366503875925.33...
  EXPECT_EQ(on_grid(Q(-1, 3)), -366503875925 * unit);
  EXPECT_EQ(on_grid(unit / 2), unit);  // a tie rounds up
  EXPECT_EQ(on_grid(-unit / 2), 0);
  EXPECT_EQ(on_grid(Q(5, 4)), Q(5, 4));
  EXPECT_EQ(on_grid(Q(-3)), Q(-3));
  // In lowest terms, as every rational of the library (== compares numerators and denominators).
  for (const Q& x : {Q(1, 3), Q(5, 4), Q(-7, 8), Q(0), Q(6), Q(-1, 3)}) {
    const Q y = on_grid(x);
    Q canonical = y;
    canonical.canonicalize();
    EXPECT_EQ(y.get_num(), canonical.get_num());
    EXPECT_EQ(y.get_den(), canonical.get_den());
  }
  const Q big(exact::Z(1) << 100, (exact::Z(1) << 100) - 1);  // 202 bits: to the grid
  EXPECT_EQ(bounded(big), 1);
  EXPECT_EQ(bounded(Q(3, 7)), Q(3, 7));
}

}  // namespace
}  // namespace contactcert::solvers::motion
