// Several movable bodies (docs/motion.md, "Several bodies"): each step is the assembly's quasistatic problem of the
// contacts found, body-body contacts are made when a vertex of one body reaches an edge of another (the step cut
// there), and every step's certificate embeds the step's assembly. The expectations are derived by hand below.
#include <gtest/gtest.h>

#include <algorithm>

#include "checker/ucp_check.h"
#include "checker/uniqueness_check.h"
#include "exact/json_input.h"
#include "runtime/scenes.h"
#include "solvers/motion/simulate.h"
#include "solvers/motion/uniqueness_certificate.h"

namespace contactcert::solvers::motion {
namespace {

using geometry::Vec2;

/// A floor (mu = 1/5), a frictionless finger at (0, 1/2) pushing along +x at speed 1, and the bodies `bodies`
/// (JSON), with extra obstacles; N steps of H.
MotionScene scene_of(const std::string& bodies, const std::string& extra_obstacles, const std::string& dt, long steps) {
  const std::string text = R"({"kind": "quasistatic_scene", "bodies": [)" + bodies + R"(], "gravity": [0, -1],
    "obstacles": [{"name": "floor", "vertices": [[-10, -1], [20, -1], [20, 0], [-10, 0]], "mu": "1/5"})" +
                           extra_obstacles + R"(],
    "fingers": [{"name": "pusher", "tip": [0, "1/2"], "mu": 0, "schedule": [{"velocity": [1, 0]}]}],
    "motion": {"dt": ")" + dt +
                           R"(", "steps": )" + std::to_string(steps) + "}}";
  return read_motion_scene(exact::JsonInput::parse(text, "bodies.json"));
}

/// The unit box [0, 1]^2, and a pointed box whose rear face is the vertex (x, 1/2): (x, 1/2), (x + 1/4, 0),
/// (x + 1, 0), (x + 1, 1), (x + 1/4, 1) (so that no two vertices of a row meet).
std::string unit_box() {
  return R"({"name": "box 0", "shape": {"type": "polygon", "vertices": [[0, 0], [1, 0], [1, 1], [0, 1]]}, "mu": "1/2"})";
}
std::string pointed_box(int k, const Q& x) {
  const auto s = [](const Q& q) { return std::string("\"") + q.get_str() + "\""; };
  return R"(, {"name": "box )" + std::to_string(k) + R"(", "shape": {"type": "polygon", "vertices": [[)" + s(x) +
         R"(, "1/2"], [)" + s(x + Q(1, 4)) + ", 0], [" + s(x + 1) + ", 0], [" + s(x + 1) + ", 1], [" + s(x + Q(1, 4)) +
         R"(, 1]]}, "mu": "1/2"})";
}

SimulateOptions options() {
  SimulateOptions o;
  o.uniqueness = false;
  return o;
}

/// Every step's certificate (an assembly ucp certificate) is valid, and no recorded pose overlaps.
void expect_certified_and_apart(const MotionScene& scene, const Trajectory<Q>& run) {
  const SceneGeometry<Q> g = scene_geometry<Q>(scene);
  for (const StepRecord<Q>& s : run.steps) {
    ASSERT_FALSE(s.certificate.empty()) << "step " << s.index;
    EXPECT_NE(s.certificate.find("bodies"), std::string::npos) << "the assembly is embedded";
    const checker::CertificateCheck c = checker::check_ucp_certificate(exact::JsonInput::parse(s.certificate, "step"));
    EXPECT_EQ(c.verdict, checker::CertificateVerdict::kValid) << "step " << s.index << ": " << c.reason;
    EXPECT_EQ(overlap(g, s.poses_after, s.tips_after), "") << "step " << s.index;
  }
}

// Three boxes touching in a row (the rear vertex of each on the front face of the one before), pushed by the
// finger: the finger's contact keeps v_n = 0, so box 0 moves at the finger's speed 1; a box ahead cannot move slower
// (v_n >= 0 at its rear vertex) and cannot move faster (then that contact separates, c_n = 0, and floor friction
// alone acts on it: no equilibrium while it moves); nothing lifts or turns (each box is pushed at half height, and
// a push of mu = 1/5 its weight is far below the 1/2 that would tip it). So every step all three have q_dot =
// (1, 0, 0), and after N steps of H each has moved by N H exactly: 4 steps of 1/4, by (1, 0).
TEST(SeveralBodies, ThreeBoxesPushedInARowSlideTogether) {
  const MotionScene scene = scene_of(unit_box() + pointed_box(1, Q(1)) + pointed_box(2, Q(2)), "", "1/4", 4);
  const Trajectory<Q> run = simulate<Q>(scene, options());
  ASSERT_EQ(run.status, RunStatus::kCompleted) << run.reason;
  ASSERT_EQ(run.steps.size(), 4u);
  for (const StepRecord<Q>& s : run.steps) {
    EXPECT_EQ(s.verdict, ucp::UcpStatus::kSolvable);
    EXPECT_TRUE(s.cut_by.empty()) << s.cut_by;
    ASSERT_EQ(s.twists.size(), 3u);
    for (const Twist<Q>& tw : s.twists) {
      EXPECT_EQ(tw.v, (Vec2<Q>{Q(1), Q(0)})) << "step " << s.index;
      EXPECT_EQ(tw.omega, Q(0)) << "step " << s.index;
    }
    // 2 floor contacts per box, 2 rear vertices on the box before, the finger: 9.
    EXPECT_EQ(s.contacts.size(), 9u);
  }
  for (const Pose<Q>& p : run.final_poses) {
    EXPECT_EQ(p.t, (Vec2<Q>{Q(1), Q(0)}));
    EXPECT_EQ(p.c, Q(1));
  }
  EXPECT_EQ(run.final_tips[0], (Vec2<Q>{Q(1), Q(1, 2)}));
  expect_certified_and_apart(scene, run);
}

// The bundled row (scenes/motion_pushed_row.json): four boxes 1/2 apart, steps of 1/3. Box 0 moves at speed 1 alone
// and reaches box 1's rear vertex at t = 1/2 (the step from 1/3 is cut there, exactly: a translation's gap is linear
// in time); boxes 0 and 1 then reach box 2 at t = 1, and three boxes reach box 3 at t = 3/2 (the steps from 5/6 and
// 4/3 are cut likewise; the step from 1/2 is a full one, to 5/6). Box k starts moving at t = k / 2, so at the end
// (t = 13/6 + 1/3 = 5/2, 9 steps) it has moved by 5/2 - k/2.
TEST(SeveralBodies, BundledRowMakesEachContactAtTheDerivedTime) {
  const MotionScene scene =
      read_motion_scene(exact::JsonInput::load(runtime::bundled_scenes_dir() + "/motion_pushed_row.json"));
  ASSERT_EQ(scene.bodies.size(), 4u);
  const Trajectory<Q> run = simulate<Q>(scene, options());
  ASSERT_EQ(run.status, RunStatus::kCompleted) << run.reason;
  ASSERT_EQ(run.steps.size(), 9u);
  const std::vector<Q> times{Q(0), Q(1, 3), Q(1, 2), Q(5, 6), Q(1), Q(4, 3), Q(3, 2), Q(11, 6), Q(13, 6)};
  for (std::size_t k = 0; k < times.size(); ++k) EXPECT_EQ(run.steps[k].time, times[k]) << "step " << k;
  EXPECT_EQ(run.steps[1].cut_by, "box 1 vertex 0 on box 0 edge 1");
  EXPECT_EQ(run.steps[3].cut_by, "box 2 vertex 0 on box 1 edge 2");
  EXPECT_EQ(run.steps[5].cut_by, "box 3 vertex 0 on box 2 edge 2");
  EXPECT_EQ(run.steps[2].made, std::vector<std::string>{"box 1 vertex 0 on box 0 edge 1"});
  EXPECT_EQ(run.steps[6].made, std::vector<std::string>{"box 3 vertex 0 on box 2 edge 2"});
  EXPECT_EQ(run.final_time, Q(5, 2));
  for (std::size_t b = 0; b < 4; ++b)
    EXPECT_EQ(run.final_poses[b].t, (Vec2<Q>{Q(5, 2) - Q(static_cast<long>(b), 2), Q(0)})) << "box " << b;
  for (const Twist<Q>& tw : run.steps[8].twists) EXPECT_EQ(tw.v, (Vec2<Q>{Q(1), Q(0)}));
  expect_certified_and_apart(scene, run);
}

// Uniqueness on the bundled row: 9 to 12 contacts per step, past the 4^nc enumeration's reach (4096 modes); the
// prefix tree over the contacts (ucp::solution_modes_by_prefix) decides every step within the same LP budget, and the
// motion derived above (each box at the finger's speed or still) is the only one.
TEST(SeveralBodies, BundledRowMotionIsUniqueAtEveryStep) {
  const MotionScene scene =
      read_motion_scene(exact::JsonInput::load(runtime::bundled_scenes_dir() + "/motion_pushed_row.json"));
  SimulateOptions o;
  o.certificates = false;
  const Trajectory<Q> run = simulate<Q>(scene, o);
  ASSERT_EQ(run.steps.size(), 9u);
  for (const StepRecord<Q>& s : run.steps) {
    ASSERT_TRUE(s.uniqueness) << "step " << s.index;
    EXPECT_EQ(s.uniqueness->status, UniquenessStatus::kUnique) << "step " << s.index;
    EXPECT_EQ(s.uniqueness->motions.size(), 1u) << "step " << s.index;
  }
}

/// The verdict of `check` on a step's motion_uniqueness certificate.
checker::UniquenessCertificateCheck checked_uniqueness(const std::string& text) {
  return checker::check_uniqueness_certificate(exact::JsonInput::parse(text, "step-K-uniqueness.json"));
}

// The row's first step with certificates: its `unique` is certified (the prefix tree's dead prefixes and solution
// modes, the widest faces' duals) and `check` verifies it with the assembly embedded.
TEST(SeveralBodies, BundledRowUniquenessIsCertified) {
  const MotionScene scene =
      read_motion_scene(exact::JsonInput::load(runtime::bundled_scenes_dir() + "/motion_pushed_row.json"));
  SimulateOptions o;
  o.steps = 1;
  const Trajectory<Q> run = simulate<Q>(scene, o);
  ASSERT_EQ(run.steps.size(), 1u);
  EXPECT_FALSE(run.steps[0].uniqueness->evidence) << "the evidence is dropped once written";
  const checker::UniquenessCertificateCheck c = checked_uniqueness(run.steps[0].uniqueness_certificate);
  EXPECT_TRUE(c.valid) << c.reason;
  EXPECT_EQ(c.verdict, "unique");
  EXPECT_EQ(c.solution_modes, 81);
  EXPECT_GT(c.dead, 0);
}

// Two bodies, one at its threshold: a 1/5 x 1 box on the floor (mu = 1/5), pushed at height 1/2 by the frictionless
// finger, slides when the push is mu W = W / 5 and tips about its front corner (1/5, 0) when the push's moment
// about it, F / 2, is the weight's, W / 10: F = W / 5 both ways, so both solve the step. Sliding is q_dot = (1, 0, 0);
// tipping turns about c = (1/5, 0) with the finger point's v_x = -omega / 2 = 1, omega = -2, and the origin's velocity
// omega J(0 - c) = (0, 2/5). A pointed box far ahead stays still (0, 0, 0) in both.
TEST(SeveralBodies, BoxAtItsTippingThresholdBesideAnotherHasTwoMotions) {
  const std::string narrow =
      R"({"name": "box 0", "shape": {"type": "polygon", "vertices": [[0, 0], ["1/5", 0], ["1/5", 1], [0, 1]]}, "mu": "1/2"})";
  const MotionScene scene = scene_of(narrow + pointed_box(1, Q(3)), "", "1/10", 1);
  SimulateOptions o;
  o.certificates = false;
  const Trajectory<Q> run = simulate<Q>(scene, o);
  ASSERT_EQ(run.steps.size(), 1u);
  const auto& u = run.steps[0].uniqueness;
  ASSERT_TRUE(u);
  EXPECT_EQ(u->status, UniquenessStatus::kNotUnique);
  const auto has = [&](const std::vector<Q>& q) {
    for (const exact::Vec<Q>& m : u->motions)
      if (m.size() == 6 && std::equal(q.begin(), q.end(), m.data())) return true;
    return false;
  };
  EXPECT_TRUE(has({Q(1), Q(0), Q(0), Q(0), Q(0), Q(0)}));
  EXPECT_TRUE(has({Q(0), Q(2, 5), Q(-2), Q(0), Q(0), Q(0)}));
}

// The same step with certificates: its `not_unique` carries two solutions whose q_dot are the two motions derived
// above, and `check` verifies them; `unique` written over the same problem, with the genuine prefix tree and every
// solution mode's genuine duals, is refused (the duals bound q_dot to different values in different modes).
TEST(SeveralBodies, TwoMotionsAtTheTippingThresholdAreCertifiedAndAForgedUniqueIsRefused) {
  const std::string narrow =
      R"({"name": "box 0", "shape": {"type": "polygon", "vertices": [[0, 0], ["1/5", 0], ["1/5", 1], [0, 1]]}, "mu": "1/2"})";
  const Trajectory<Q> run = simulate<Q>(scene_of(narrow + pointed_box(1, Q(3)), "", "1/10", 1), SimulateOptions{});
  ASSERT_EQ(run.steps.size(), 1u);
  const std::string& text = run.steps[0].uniqueness_certificate;
  const checker::UniquenessCertificateCheck c = checked_uniqueness(text);
  EXPECT_TRUE(c.valid) << c.reason;
  EXPECT_EQ(c.verdict, "not_unique");
  const exact::JsonInput cert = exact::JsonInput::parse(text, "step-0-uniqueness.json");
  std::vector<exact::Vec<Q>> q;
  for (const exact::JsonInput& w : cert.at("witnesses").elements()) q.push_back(w.at("u").rational_vector().head(6));
  ASSERT_EQ(q.size(), 2u);
  exact::Vec<Q> slide(6), tip(6);
  slide << 1, 0, 0, 0, 0, 0;
  tip << 0, Q(2, 5), -2, 0, 0, 0;
  EXPECT_TRUE((q[0] == slide && q[1] == tip) || (q[0] == tip && q[1] == slide));

  const ucp::UcpProblem problem = ucp::read_ucp_problem(cert.at("problem"));
  MotionUniqueness forged = motion_uniqueness(problem, exact::Arith::kExact, 1L << 12, true);
  ASSERT_EQ(forged.status, UniquenessStatus::kNotUnique);
  forged.status = UniquenessStatus::kUnique;
  forged.motions.resize(1);
  const checker::UniquenessCertificateCheck f = checked_uniqueness(uniqueness_certificate(problem, forged));
  EXPECT_FALSE(f.valid);
  EXPECT_NE(f.reason.find("bound of mode"), std::string::npos) << f.reason;
}

// Box 0 pushed into box 1, which stands against a wall (its front face on the wall's face x = 5/2, the wall's foot
// at y = 1/4 so that only box 1's top front corner (5/2, 1) touches it, strictly inside its edge): the step from 1/3
// is cut at t = 1/2 when box 0 reaches box 1's rear vertex (3/2, 1/2). Then box 0 must move at the finger's speed 1,
// so box 1's rear vertex moves with v_x >= 1 while its top front corner has v_x <= 0: box 1 would have to turn
// counter-clockwise (omega >= 2) about a point at height >= 1/2, pushed at half height by a force its floor friction
// (mu = 1/5) and weight cannot balance: no solution, and the run stops jammed with the proof (a ucp_jammed
// certificate embedding the assembly) as the last step's certificate.
TEST(SeveralBodies, BoxPushedIntoABoxAgainstAWallJams) {
  const MotionScene scene = scene_of(
      unit_box() + pointed_box(1, Q(3, 2)),
      R"(, {"name": "wall", "vertices": [["5/2", "1/4"], [4, "1/4"], [4, 5], ["5/2", 5]], "mu": "1/5"})", "1/3", 5);
  const Trajectory<Q> run = simulate<Q>(scene, options());
  ASSERT_EQ(run.status, RunStatus::kJammed) << run.reason;
  ASSERT_EQ(run.steps.size(), 3u);
  EXPECT_EQ(run.steps[1].h, Q(1, 6));
  EXPECT_EQ(run.steps[1].cut_by, "box 1 vertex 0 on box 0 edge 1");
  EXPECT_EQ(run.steps[2].verdict, ucp::UcpStatus::kJammed);
  EXPECT_EQ(run.steps[2].made, std::vector<std::string>{"box 1 vertex 0 on box 0 edge 1"});
  EXPECT_NE(run.steps[2].certificate.find("ucp_jammed"), std::string::npos);
  EXPECT_EQ(run.final_poses[0].t, (Vec2<Q>{Q(1, 2), Q(0)}));
  EXPECT_EQ(run.final_poses[1].t, (Vec2<Q>{Q(0), Q(0)}));
  expect_certified_and_apart(scene, run);
}

// A turning body meets a still one: the 2 x 2 box pushed at height 3/2 tips about its front corner (2, 0) with
// omega = -2/3 (simulate_test.cpp, TippingBox); its top-right corner is at (2 + 2 s, 2 c), s = 2|u|/(1 + u^2),
// c = (1 - u^2)/(1 + u^2), u = -tau / 3. A post standing on the floor as a second body, its face at x = 16/5, is
// reached when 4|u|/(1 + u^2) = 6/5: |u| = 1/3, tau = 1 exactly, the corner at (16/5, 8/5) (the same time as an
// obstacle post): the gap polynomial of two bodies is exact here too.
TEST(SeveralBodies, TurningBodyMeetsAStillBodyAtTheDerivedTime) {
  const std::string text = R"({"kind": "quasistatic_scene", "bodies": [
      {"name": "box", "shape": {"type": "polygon", "vertices": [[0, 0], [2, 0], [2, 2], [0, 2]]}, "com": [1, 1]},
      {"name": "post", "shape": {"type": "polygon", "vertices": [["16/5", 0], [5, 0], [5, 3], ["16/5", 3]]}}],
    "gravity": [0, -1],
    "obstacles": [{"name": "floor", "vertices": [[-10, -1], [10, -1], [10, 0], [-10, 0]], "mu": 1}],
    "fingers": [{"name": "pusher", "tip": [0, "3/2"], "mu": 0, "schedule": [{"velocity": [1, 0]}]}],
    "motion": {"dt": "6/5", "steps": 1}})";
  const MotionScene scene = read_motion_scene(exact::JsonInput::parse(text, "post.json"));
  const Trajectory<Q> run = simulate<Q>(scene, options());
  ASSERT_EQ(run.steps.size(), 1u) << run.reason;
  EXPECT_EQ(run.steps[0].twists[0].omega, Q(-2, 3));
  EXPECT_EQ(run.steps[0].twists[1].omega, Q(0));
  EXPECT_EQ(run.steps[0].h, Q(1));
  EXPECT_TRUE(run.steps[0].cut_exact);
  EXPECT_EQ(run.steps[0].cut_by, "box vertex 2 on post edge 3");
  EXPECT_EQ(run.steps[0].poses_after[0].apply(Vec2<Q>{Q(2), Q(2)}), (Vec2<Q>{Q(16, 5), Q(8, 5)}));
  EXPECT_EQ(run.steps[0].poses_after[0].apply(Vec2<Q>{Q(2), Q(0)}), (Vec2<Q>{Q(2), Q(0)}));  // the pivot
  expect_certified_and_apart(scene, run);
}

/// The gap of body a's vertex i on body b's edge k at `poses` (cross(e, p - q) with e the edge, q its start; > 0:
/// outside b).
Q vertex_edge_gap(const SceneGeometry<Q>& g, const Poses<Q>& poses, std::size_t a, std::size_t i, std::size_t b,
                  std::size_t k) {
  const std::vector<Vec2<Q>>& B = g.bodies[b];
  const Vec2<Q> q = poses[b].apply(B[k]), e = poses[b].apply(B[(k + 1) % B.size()]) - q;
  return cross2(poses[a].apply(g.bodies[a][i]) - q, e);
}

// Two bodies that both turn, one sliding on the other (scenes/motion_tipping_stack.json): the lower 2 x 2 box,
// pushed at height 3/2 at speed 1, tips about its front corner (2, 0): omega = -2/3 (the finger point's v_x =
// -omega 3/2 = 1). The upper box's two bottom vertices on the lower's top (v_n = 0 at both) give it the same omega;
// the lower's top point (x, 2) moves by omega J((x, 2) - (2, 0)) = (4/3, -2(x - 2)/3), the upper's by (v_x + 4/3,
// v_y - 2x/3), so v_y = 4/3; the still finger at (7/4, 9/4) on its right face (v_n = 0) gives v_x + (2/3)(9/4) = 0:
// q_dot = (-3/2, 4/3, -2/3), sliding back along the top at 3/2 (mode +). Both turn, so each step's Cayley rotations
// about different centres move the upper's vertices off the lower's top by O(h^2) (the base stopped after step 0:
// "the lower overlaps the upper"); the coupled translation correction keeps both exactly on it: at every step the
// gap is exactly 0, the contacts are maintained to the next step, no pose overlaps and every certificate checks.
TEST(SeveralBodies, StackedBoxesBothTurnAndTheSlidingContactsStayExactlyClosed) {
  const MotionScene scene =
      read_motion_scene(exact::JsonInput::load(runtime::bundled_scenes_dir() + "/motion_tipping_stack.json"));
  const Trajectory<Q> run = simulate<Q>(scene, options());
  ASSERT_EQ(run.status, RunStatus::kCompleted) << run.reason;
  ASSERT_EQ(run.steps.size(), 4u);
  EXPECT_EQ(run.steps[0].twists[0].v, (Vec2<Q>{Q(0), Q(4, 3)}));
  EXPECT_EQ(run.steps[0].twists[0].omega, Q(-2, 3));
  EXPECT_EQ(run.steps[0].twists[1].v, (Vec2<Q>{Q(-3, 2), Q(4, 3)}));
  EXPECT_EQ(run.steps[0].twists[1].omega, Q(-2, 3));
  const SceneGeometry<Q> g = scene_geometry<Q>(scene);
  for (const StepRecord<Q>& s : run.steps) {
    EXPECT_LT(s.twists[0].omega, 0) << "step " << s.index;
    EXPECT_EQ(s.twists[1].omega, s.twists[0].omega) << "step " << s.index;
    EXPECT_TRUE(s.cut_by.empty()) << s.cut_by;
    for (std::size_t i : {0u, 1u}) {
      const std::string name = "upper vertex " + std::to_string(i) + " on lower edge 2";
      const auto c = std::find_if(s.contacts.begin(), s.contacts.end(), [&](const auto& r) { return r.name == name; });
      ASSERT_NE(c, s.contacts.end()) << name << " at step " << s.index;
      EXPECT_EQ(c->mode, '+') << name << " at step " << s.index;
      EXPECT_EQ(vertex_edge_gap(g, s.poses_after, 1, i, 0, 2), 0) << name << " after step " << s.index;
    }
  }
  expect_certified_and_apart(scene, run);
}

/// Bits of a rational: its numerator's and denominator's together.
std::size_t bits(const Q& x) { return mpz_sizeinbase(x.get_num_mpz_t(), 2) + mpz_sizeinbase(x.get_den_mpz_t(), 2); }

// The same stack over 14 steps of 1/40: the coupled correction puts the upper's translation on the grid along the
// contact lines (bounded.h), so its pose keeps the size of the lower's (about 170 bits a coordinate) instead of
// growing by about 150 bits a step (2 000 bits after 14 steps, exactly least-norm), while the contacts stay exact.
TEST(SeveralBodies, StackedBoxesPosesKeepABoundedSize) {
  const MotionScene scene =
      read_motion_scene(exact::JsonInput::load(runtime::bundled_scenes_dir() + "/motion_tipping_stack.json"));
  SimulateOptions o = options();
  o.steps = 14;
  o.dt = Q(1, 40);
  o.certificates = false;
  const Trajectory<Q> run = simulate<Q>(scene, o);
  ASSERT_EQ(run.status, RunStatus::kCompleted) << run.reason;
  const SceneGeometry<Q> g = scene_geometry<Q>(scene);
  for (const StepRecord<Q>& s : run.steps) {
    for (const Pose<Q>& p : s.poses_after) {
      EXPECT_LE(bits(p.t.x), 256u) << "step " << s.index;
      EXPECT_LE(bits(p.t.y), 256u) << "step " << s.index;
    }
    EXPECT_EQ(vertex_edge_gap(g, s.poses_after, 1, 0, 0, 2), 0) << "step " << s.index;
    EXPECT_EQ(vertex_edge_gap(g, s.poses_after, 1, 1, 0, 2), 0) << "step " << s.index;
  }
}

// The remaining limit, stated: the 2 x 2 box tipping about its front corner meets a 4/5 x 3 post, which then tips
// about its own front corner (4, 0) while the box's top corner slides down its rear face. Each body is pinned by its
// pivot's two rows, so no translation can keep the sliding contact between them (more independent rows than
// translation freedoms): it dips, and the run stops with `overlap`, its reason naming that contact.
TEST(SeveralBodies, TwoPivotingBodiesCannotKeepTheirContactAndTheOverlapSaysWhy) {
  const std::string text = R"({"kind": "quasistatic_scene", "bodies": [
      {"name": "box", "shape": {"type": "polygon", "vertices": [[0, 0], [2, 0], [2, 2], [0, 2]]}, "com": [1, 1]},
      {"name": "post", "shape": {"type": "polygon", "vertices": [["16/5", 0], [4, 0], [4, 3], ["16/5", 3]]}}],
    "gravity": [0, -1],
    "obstacles": [{"name": "floor", "vertices": [[-10, -1], [10, -1], [10, 0], [-10, 0]], "mu": 1}],
    "fingers": [{"name": "pusher", "tip": [0, "3/2"], "mu": 0, "schedule": [{"velocity": [1, 0]}]}],
    "motion": {"dt": "1/2", "steps": 6}})";
  const Trajectory<Q> run = simulate<Q>(read_motion_scene(exact::JsonInput::parse(text, "posts.json")), options());
  ASSERT_EQ(run.status, RunStatus::kOverlap) << run.reason;
  ASSERT_EQ(run.steps.size(), 3u);
  EXPECT_EQ(run.steps[1].cut_by, "box vertex 2 on post edge 3");
  EXPECT_LT(run.steps[2].twists[1].omega, 0);  // the post tips too
  EXPECT_NE(run.reason.find("the translation correction cannot keep box vertex 2 on post edge 3 closed"),
            std::string::npos)
      << run.reason;
}

// The float path steps the same scene (the assembly's problem in doubles): the same verdict at step 0.
TEST(SeveralBodies, FloatPathStepsTheRow) {
  const MotionScene scene = scene_of(unit_box() + pointed_box(1, Q(1)), "", "1/4", 2);
  const Trajectory<double> fl = simulate<double>(scene, options());
  ASSERT_GE(fl.steps.size(), 1u) << fl.reason;
  EXPECT_EQ(fl.steps[0].verdict, ucp::UcpStatus::kSolvable);
  EXPECT_NEAR(fl.steps[0].twists[1].v.x, 1.0, 1e-9);
}

}  // namespace
}  // namespace contactcert::solvers::motion
