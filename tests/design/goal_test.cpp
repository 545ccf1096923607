// G_goal's frictionless finger push requirement and the "goal_nonempty" certificate, on a case derived by hand.
//
// The square [-1, 1]^2 (com at 0, I/m = 2/3), mu_s = mu_k = 1/5, two fixels under its bottom edge at x1 < x2 (normal
// (0, 1)), a push down at (x, 1) on the top edge: g = (0, -1, -x). With fixel 1 maintained (c1 = (t, c1n)) and
// fixel 2 not in contact, a_1n = -1 + c1n + alpha x1 = 0 and a_2n - a_1n = alpha (x2 - x1); for x1 = -1/2,
// alpha = 3/2 (-x - c1n / 2 + t) = 2 (c1n - 1), so a_2n >= 0 needs c1n >= 1 and t = x + 11/6 c1n - 4/3 <= c1n / 5:
// x <= -1/2 + 1/5. So the push is in G_ms (state 10) iff x <= x1 + mu, by symmetry in G_sm (state 01) iff
// x >= x2 - mu, and never in G_su or G_us (separating from the only contact needs x x_i < -I/m). Hence the push
// at (x, 1) seats the square iff x1 + 1/5 < x < x2 - 1/5 (eq. 21): (-3/10, 3/10) for x = -1/2, 1/2 and
// (-3/10, -1/5) for x = -1/2, 0.
#include <gtest/gtest.h>

#include "checker/goal_check.h"
#include "solvers/design/evaluate.h"
#include "solvers/design/goal_certificate.h"
#include "solvers/design/problem.h"
#include "solvers/insertion/insertion.h"
#include "solvers/stability/finger_push.h"

namespace contactcert::solvers {
namespace {

using geometry::Point2;
using geometry::Q;

/// Candidates 0, 1, 2 at x = -1/2, 1/2, 0 under the bottom edge; the push points as given (on the top edge).
DesignProblem square_problem(const std::vector<Q>& push_x) {
  DesignProblem p;
  const std::vector<Point2> V{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  p.workpiece.shape = geometry::PolygonShape{V};
  p.workpiece.com = {0, 0};
  p.workpiece.inertia_per_mass = geometry::polygon_inertia_per_mass(V, p.workpiece.com);
  p.mu_s = p.mu_k = Q(1, 5);
  for (const Q& x : {Q(-1, 2), Q(1, 2), Q(0)}) p.candidates.push_back({{x, -1}, {0, 2}});
  for (const Q& x : push_x) p.pushes.push_back({{x, 1}, {0, -2}});
  p.fixels = 2;
  p.insertable = p.goal_push = true;
  p.rank = Rank::kGoalFraction;
  return p;
}

bool push_in_goal(const DesignProblem& p, const Placement& placement, const Q& x) {
  Vec<Q> at(2), n(2);
  at << x, 1;
  n << 0, -1;
  return insertion<Q>(placement_scene(p, placement)).in_goal(push_wrench<Q>(p.workpiece.com, at, n));
}

TEST(DesignGoalPush, TheHandDerivedIntervalOfSeatingPushes) {
  const DesignProblem p = square_problem({});
  for (const auto& [x, in] : std::vector<std::pair<Q, bool>>{{Q(0), true},
                                                             {Q(29, 100), true},
                                                             {Q(-29, 100), true},
                                                             {Q(3, 10), false},
                                                             {Q(-3, 10), false},
                                                             {Q(1, 2), false}})
    EXPECT_EQ(push_in_goal(p, {0, 1}, x), in) << x;  // (-3/10, 3/10), open: the limits are in G_ms and G_sm
  for (const auto& [x, in] : std::vector<std::pair<Q, bool>>{
           {Q(-1, 4), true}, {Q(-3, 10), false}, {Q(-1, 5), false}, {Q(0), false}, {Q(1, 10), false}})
    EXPECT_EQ(push_in_goal(p, {0, 2}, x), in) << x;  // (-3/10, -1/5)
}

TEST(DesignGoalPush, APushWorksForOnePlacementAndNoneForTheOther) {
  const DesignProblem p = square_problem({Q(1, 10), Q(1, 2)});
  const CandidateSymmetry none;
  PlacementEvidence ev;
  const Evaluation works = evaluate_placement(p, none, {0, 1}, &ev);
  EXPECT_EQ(works.status, PlacementStatus::kAccepted);
  EXPECT_EQ(works.figure, Q(1, 2));  // the push at x = 1/10 of the two
  EXPECT_EQ(ev.goal_push_point, 0);
  // G_goal of {0, 2} is not empty (the push at x = -1/4 is in it), but neither push point's push is.
  EXPECT_EQ(evaluate_placement(p, none, {0, 2}).status, PlacementStatus::kNoPushInGoal);
  DesignProblem any_wrench = p;
  any_wrench.goal_push = false;
  EXPECT_EQ(evaluate_placement(any_wrench, none, {0, 2}).status, PlacementStatus::kAccepted);
}

checker::GoalCertificateCheck check_text(const std::string& text) {
  return checker::check_goal_certificate(exact::JsonInput::parse(text, "goal.cert.json"));
}

TEST(DesignGoalCertificate, AWitnessPushChecksAndForgeriesDoNot) {
  const DesignProblem p = square_problem({Q(1, 10)});
  const std::string scene_text = placement_scene_text(p, {0, 1}, "square");
  const geometry::PlanarScene scene = placement_scene(p, {0, 1});
  Vec<Q> g(3);
  g << 0, -1, Q(-1, 10);
  const std::string cert = goal_certificate(scene_text, scene, g, Point2{Q(1, 10), 1});
  const checker::GoalCertificateCheck ok = check_text(cert);
  EXPECT_TRUE(ok.valid) << ok.reason;
  // Without the push: only the wrench is claimed; a scaled wrench is the same push.
  EXPECT_TRUE(check_text(goal_certificate(scene_text, scene, Vec<Q>(Q(10) * g), {})).valid);
  EXPECT_TRUE(check_text(goal_certificate(scene_text, scene, Vec<Q>(Q(10) * g), Point2{Q(1, 10), 1})).valid);
  // The witness is computed for a wrench inside some set's cone: the writer refuses.
  Vec<Q> tilting(3);
  tilting << 0, -1, Q(-1, 2);
  EXPECT_THROW(goal_certificate(scene_text, scene, tilting, {}), std::logic_error);
  // Claims the push at another point: not the wrench's push, or not on the boundary.
  auto forged = [&](const std::string& from, const std::string& to) {
    std::string t = cert;
    const std::size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return check_text(t.replace(at, from.size(), to));
  };
  EXPECT_EQ(forged("\"push\": [\n  \"1/10\"", "\"push\": [\n  \"1/5\"").reason,
            "the wrench is not a positive multiple of the push at the push point");
  EXPECT_FALSE(forged("\"push\": [\n  \"1/10\",\n  \"1\"", "\"push\": [\n  \"1/10\",\n  \"2\"").valid);
  // A wrench in G_sm with the certificate's vectors.
  EXPECT_FALSE(
      forged("\"wrench\": [\n  \"0\",\n  \"-1\",\n  \"-1/10\"", "\"wrench\": [\n  \"0\",\n  \"-1\",\n  \"-1/2\"")
          .valid);
}

// The checker rebuilds K and P from the embedded scene: Motzkin vectors computed for mu = 1/5 do not pass for a
// scene that says mu = 3/10, where the push at x = 1/4 lies in G_sm (x >= x2 - mu, as derived above), so that
// no vectors could.
TEST(DesignGoalCertificate, VectorsForAnotherFrictionCoefficientAreRefused) {
  const DesignProblem p = square_problem({});
  DesignProblem rougher = p;
  rougher.mu_s = rougher.mu_k = Q(3, 10);
  Vec<Q> g(3);
  g << 0, -1, Q(-1, 4);
  const geometry::PlanarScene scene = placement_scene(p, {0, 1});
  EXPECT_TRUE(check_text(goal_certificate(placement_scene_text(p, {0, 1}, "square"), scene, g, {})).valid);
  const checker::GoalCertificateCheck wrong =
      check_text(goal_certificate(placement_scene_text(rougher, {0, 1}, "square"), scene, g, {}));
  EXPECT_FALSE(wrong.valid);
  EXPECT_NE(wrong.reason.find("does not prove the wrench outside its cone"), std::string::npos) << wrong.reason;
}

}  // namespace
}  // namespace contactcert::solvers
