// Assembly stability from rest on hand-derived cases (Balkcom-Trinkle section 7 for N bodies). Every verdict's
// evidence is verified by the independent checker.
//
// The energy argument used below: in any solution of the model, every contact has c_n a_n = 0 (s: c = 0, else
// a_n = 0) and c_t a_t <= 0 (l r: friction opposes the sliding, n: a_t = 0), so
//   vdot^T M vdot = vdot^T (g + J c) = g^T vdot + sum_i (c_in a_in + c_it a_it) <= g^T vdot.
// Under gravity alone g^T vdot = -sum_b m_b ay_b(com_b), ay_b(x) = ay_b + alpha_b (x - cx_b) being the vertical
// acceleration of body b's points at abscissa x (from rest it does not depend on the height). If every
// acceleration that Table 2 allows (a_n >= 0 at every contact) has sum_b m_b ay_b(cx_b) >= 0, then
// vdot^T M vdot <= 0, so vdot = 0 in every solution: with a resting solution, strongly stable.
#include <gtest/gtest.h>

#include "checker/assembly_check.h"
#include "tests/solvers/assembly/assembly_fixtures.h"

namespace contactcert::solvers::assembly {
namespace {

using testing::body;
using testing::box;
using testing::ground;
using testing::mu;
using testing::obstacle;
using testing::point;
using testing::SceneText;
using testing::stack_box;

AssemblyStabilityResult decided(const geometry::Assembly& a) {
  const AssemblyStabilityResult r = assembly_stability(a);
  EXPECT_EQ(r.status, AssemblyStatus::kDecided);
  EXPECT_EQ(checker::check_assembly_stability(a, r), "");
  return r;
}

// Two unit-height boxes of width 2 stacked exactly, mu = 1/2. Resting: each interface carries the weight above it
// split evenly between its corners, no friction. Allowed accelerations: ay_0(0), ay_0(2) >= 0 (ground corners) and
// ay_1(x) - ay_0(x) >= 0 at x = 0, 2; all are linear in x, so ay_1(1) >= ay_0(1) >= 0 and the energy argument
// gives vdot = 0: strongly stable.
TEST(AssemblyStability, TwoStackedBoxesAreStronglyStable) {
  SceneText s;
  const std::size_t g = ground(s);
  const std::size_t b0 = stack_box(s, obstacle(g), 0, 0, 2, 1, 0, 2, "1/2");
  stack_box(s, body(b0), 0, 1, 2, 2, 0, 2, "1/2");
  const geometry::Assembly a = s.read();
  const AssemblyStabilityResult r = decided(a);
  EXPECT_EQ(r.verdict, AssemblyVerdict::kStronglyStable);
  ASSERT_TRUE(r.has_resting);
  // By symmetry and the LP's freedom the forces may differ, but the total normal force on the ground is the
  // weight of both boxes (masses 2 + 2) and on the interface the weight of the top box.
  EXPECT_EQ(r.resting_forces(0) + r.resting_forces(1), Q(4));
  EXPECT_EQ(r.resting_forces(2) + r.resting_forces(3), Q(2));
  EXPECT_FALSE(r.dead.empty());
}

// The top box [3/2, 7/2] x [1, 2] on [0, 2] x [0, 1]: its com at x = 5/2 lies past the lower box's edge x = 2.
// Resting, the top box: its weight has no torque about its com, the friction forces act at its bottom (height
// -1/2 from the com) and sum to zero, and the normal forces c_1, c_2 >= 0 act at x = 3/2 and x = 2, left of the
// com: torques c_1 (3/2 - 5/2) + c_2 (2 - 5/2) = 0 with c_1 + c_2 = 2 (its weight) is impossible. No resting
// solution: unstable, whatever mu.
TEST(AssemblyStability, OverhangingTopBoxIsUnstable) {
  for (const char* m : {"0", "1/2", "10"}) {
    SceneText s;
    const std::size_t g = ground(s);
    const std::size_t b0 = stack_box(s, obstacle(g), 0, 0, 2, 1, 0, 2, m);
    stack_box(s, body(b0), Q(3, 2), 1, Q(7, 2), 2, Q(3, 2), 2, m);
    const geometry::Assembly a = s.read();
    const AssemblyStabilityResult r = decided(a);
    EXPECT_EQ(r.verdict, AssemblyVerdict::kUnstable) << m;
    EXPECT_FALSE(r.has_resting);
    EXPECT_GT(r.resting_farkas.size(), 0);
  }
}

// A plank B (area 1, vertices (0,0), (3,4), (71/25,103/25), (-4/25,3/25), com (71/50, 103/50)) leans on the
// frictionless left face x = 3 of a box A = [3,5] x [0,6] (mass 12, mu = 1/2 with the ground), its foot on the
// ground with friction mu. Resting, B alone: the wall pushes (-H, 0) at (3,4), the ground (F, N) at (0,0);
// F = H, N = 1, and torques about the foot 4 H - 71/50 = 0, so H = 71/200 and the foot needs mu >= 71/200 (A
// holds: H is far below 1/2 * 12, and A does not tip since 12 * 1 > 4 H about its right corner). So mu below
// 71/200: unstable; at or above: a resting solution exists.
SceneText leaning_plank(const std::string& foot_mu) {
  SceneText s;
  const std::size_t g = ground(s);
  const std::string plank =
      "{\"type\": \"polygon\", \"vertices\": [[0, 0], [3, 4], [\"71/25\", \"103/25\"], "
      "[\"-4/25\", \"3/25\"]]}";
  const std::size_t B = s.body(plank);
  const std::size_t A = stack_box(s, obstacle(g), 3, 0, 5, 6, 3, 5, "1/2");
  s.contact(obstacle(g), body(B), point(0, 0), "[0, 1]", "\"mu\": \"" + foot_mu + "\"");
  s.contact(body(A), body(B), point(3, 4), "[-1, 0]", mu("0"));
  return s;
}

TEST(AssemblyStability, LeaningPlankAtTheFrictionThreshold) {
  {
    const geometry::Assembly a = leaning_plank("709/2000").read();  // 71/200 - 1/2000
    EXPECT_EQ(decided(a).verdict, AssemblyVerdict::kUnstable);
  }
  for (const char* m : {"71/200", "1/2"}) {
    const geometry::Assembly a = leaning_plank(m).read();
    const AssemblyStabilityResult r = decided(a);
    EXPECT_NE(r.verdict, AssemblyVerdict::kUnstable) << m;
    ASSERT_TRUE(r.has_resting);
    // The foot's force is the hand-derived one: N = 1, friction H = 71/200 (contact 2, t = (-1, 0) for n = (0, 1),
    // so c_t = -71/200), whatever else the LP chose.
    const Eigen::Index k = r.resting_forces.size() / 2;
    EXPECT_EQ(r.resting_forces(2), Q(1)) << m;
    EXPECT_EQ(r.resting_forces(k + 2), Q(-71, 200)) << m;
  }
}

// A corbel of three boxes of width 2 and height 1: [0,2] (on the ground), [1/2, 5/2], [1, 3]. Interfaces at
// x in [1/2, 2] and [1, 5/2]. Allowed accelerations: ay_0 >= 0 on [0, 2], ay_1 - ay_0 >= 0 on [1/2, 2],
// ay_2 - ay_1 >= 0 on [1, 5/2] (linear functions, so at the ends suffices). With masses 2 each:
//   sum m ay(com) = 2 ay_0(1) + 2 ay_1(3/2) + 2 ay_2(2) >= 2 ay_0(1) + 2 ay_1(3/2) + 2 ay_1(2) = 2 ay_0(1) + 4
//   ay_1(7/4)
//                 >= 2 ay_0(1) + 4 ay_0(7/4) = 6 ay_0(3/2) >= 0,
// and a resting solution exists (the com of the upper two, x = 7/4, and of the top one, x = 2, lie over their
// supports): strongly stable. Shifting the top box to [2, 4] puts its com (x = 3) past x = 5/2: unstable.
TEST(AssemblyStability, ThreeBlockCorbel) {
  for (const bool overhang : {false, true}) {
    SceneText s;
    const std::size_t g = ground(s);
    const std::size_t b0 = stack_box(s, obstacle(g), 0, 0, 2, 1, 0, 2, "1/2");
    const std::size_t b1 = stack_box(s, body(b0), Q(1, 2), 1, Q(5, 2), 2, Q(1, 2), 2, "1/2");
    if (overhang)
      stack_box(s, body(b1), 2, 2, 4, 3, 2, Q(5, 2), "1/2");
    else
      stack_box(s, body(b1), 1, 2, 3, 3, 1, Q(5, 2), "1/2");
    const geometry::Assembly a = s.read();
    EXPECT_EQ(decided(a).verdict, overhang ? AssemblyVerdict::kUnstable : AssemblyVerdict::kStronglyStable);
  }
}

// The box [0,2] x [0,1] (mass 2, com (1, 1/2)) on two ground contacts at its corners under the load (1, -2, 0).
// Resting (t = (-1, 0), so the force is (-c_t, c_n)): c_t0 + c_t1 = 1, c_n0 + c_n1 = 2, torques c_n1 - c_n0 -
// (c_t0 + c_t1)/2 = 0, so c_n = (3/4, 5/4) and the friction needs mu >= 1/2: with mu = 0 unstable. Moving, mu_s =
// mu_k = 1: tipping about either corner is against the load's torque about it (3/2 about (2,0), -5/2 about (0,0)),
// both contacts at a_n = 0 force a translation, and sliding right leaves 1 - mu_k * 2 < 0 to accelerate it right,
// sliding left is pushed right by friction and load: no moving solution, strongly stable. With mu_k = 1/10,
// sliding right (ax = (1 - 2/10)/2 = 2/5 > 0, mode rr) is a solution beside the resting one: weakly stable.
TEST(AssemblyStability, PushedBoxWeakAndStrong) {
  const auto verdict = [](const char* mu_s, const char* mu_k) {
    SceneText s;
    const std::size_t g = ground(s);
    s.body(box(0, 0, 2, 1), "\"load\": [1, -2, 0]");
    for (const Q& x : {Q(0), Q(2)})
      s.contact(obstacle(g), body(0), point(x, 0), "[0, 1]",
                std::string("\"mu_s\": \"") + mu_s + "\", \"mu_k\": \"" + mu_k + "\"");
    return decided(s.read());
  };
  EXPECT_EQ(verdict("0", "0").verdict, AssemblyVerdict::kUnstable);
  EXPECT_EQ(verdict("1", "1").verdict, AssemblyVerdict::kStronglyStable);
  const AssemblyStabilityResult weak = verdict("1", "1/10");
  EXPECT_EQ(weak.verdict, AssemblyVerdict::kWeaklyStable);
  ASSERT_TRUE(weak.has_moving);
  EXPECT_GT(weak.moving.acceleration(0), 0);  // it slides to the right
}

// Pivoting: the box [-1,1] x [0,1] (mass 2, I = 5/6) on one contact at (0,0) under the load (0, -2, 1). Resting
// needs -c_t = 0 (forces in x) and 1 - c_t/2 = 0 (torques): impossible, unstable. Modes (a_n = ay, a_t =
// -(ax + alpha/2)): s has ay = -1 < 0; l has c_t = -mu_k c_n = -1, ax = 1/2, alpha = 9/5, a_t < 0: infeasible; r has
// c_t = 1, ax = -1/2, alpha = 3/5, a_t = 1/5 > 0: infeasible; n (a = 0): c_n = 2, ax = -alpha/2, c_t = alpha,
// (5/6) alpha = 1 - alpha/2, alpha = 3/4, |c_t| = 3/4 <= mu_s c_n = 1: the box turns about the rolling contact.
TEST(AssemblyStability, PivotOnOneRollingContact) {
  SceneText s;
  const std::size_t g = ground(s);
  s.body(box(-1, 0, 1, 1), "\"load\": [0, -2, 1]");  // a pure torque besides the weight
  s.contact(obstacle(g), body(0), point(0, 0), "[0, 1]", mu("1/2"));
  const geometry::Assembly a = s.read();
  const AssemblyStabilityResult r = decided(a);
  EXPECT_EQ(r.verdict, AssemblyVerdict::kUnstable);
  ASSERT_TRUE(r.has_moving);
  EXPECT_EQ(r.moving.mode, "n");
  EXPECT_EQ(r.moving.acceleration(2), Q(3, 4));  // it turns counter-clockwise about the contact
}

// The budget is a status, not an exception: two stacked boxes under a sideways load need a walk over the contacts
// (their root system is feasible: the load can do work), which two prefixes do not finish.
TEST(AssemblyStability, NodeBudgetIsAStatus) {
  SceneText s = testing::box_stack(2);
  for (std::string& b : s.bodies) b.insert(b.size() - 1, ", \"load\": [\"1/2\", -2, 0]");
  const geometry::Assembly a = s.read();
  AssemblyStabilityOptions o;
  o.max_nodes = 2;
  const AssemblyStabilityResult r = assembly_stability(a, o);
  EXPECT_EQ(r.status, AssemblyStatus::kNodeLimit);
  EXPECT_TRUE(r.has_resting);
  EXPECT_FALSE(r.covered.empty());
  EXPECT_NE(checker::check_assembly_stability(a, r), "");
  EXPECT_EQ(decided(a).verdict, AssemblyVerdict::kStronglyStable);
}

// The walk's contact order (walk_order). A stack of three hangs off the ground: its boxes are peeled as leaves of the
// contact graph from the top, box 2's contacts with box 1 (4, 5), box 1's with box 0 (2, 3), box 0's with the ground
// (0, 1). The corbelled arch hangs nowhere (both piers stand on the ground, the keystone on both): its blocks go by
// their distance from the ground, course by course, left then right: block L0 takes its ground contacts 0, 1 and its
// interface with L1 4, 5, R0 takes 2, 3 and 6, 7, then L1 (8, 9), R1 (10, 11), ..., R3 the keystone's right pair
// 18, 19, and the keystone, last, has no contact left.
TEST(AssemblyStability, WalkOrderPeelsHangingBodiesThenGoesCourseByCourse) {
  EXPECT_EQ(walk_order(testing::box_stack(3).read()), (std::vector<std::size_t>{4, 5, 2, 3, 0, 1}));
  std::vector<std::size_t> arch{0, 1, 4, 5, 2, 3, 6, 7};
  for (std::size_t i = 8; i < 20; ++i) arch.push_back(i);
  EXPECT_EQ(walk_order(testing::corbel_arch().read()), arch);
}

}  // namespace
}  // namespace contactcert::solvers::assembly
