#include "solvers/stability/strong_stability.h"

#include <gtest/gtest.h>

#include <random>

#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/nnc_cone.h"
#include "geometry/span_cone.h"
#include "geometry/scene_json.h"
#include "solvers/stability/finger_push.h"
#include "solvers/stability/margin.h"
#include "solvers/stability/stable_region.h"
#include "tests/solvers/scene_fixtures.h"
#include "solvers/wrench_cone/wrench_cone.h"

namespace contactcert::solvers {
namespace {

using exact::Q;
using exact::Vec;

using testing::wrench;

geometry::PlanarScene section7(const char* mu) { return testing::scene_with_mu("bt2002_section7_disk.json", mu); }

TEST(StrongStability, Section7DiskPushedStraightDownIsStronglyStable) {
  // A moving solution from rest has vdot^T M vdot = a^T c + vdot^T g <= vdot^T g (friction opposes
  // sliding, separating contacts carry no force). For g = (0,-1,0), vdot^T g = -ydd, and the bottom
  // fixel's normal acceleration is a_1n = ydd >= 0, so vdot = 0: no solution moves.
  const auto scene = section7("1.2");
  for (exact::Arith arith : {exact::Arith::kExact, exact::Arith::kVerified}) {
    const auto r = strong_stability<Q>(scene, wrench(0, -1, 0), {arith});
    EXPECT_EQ(r.verdict, StabilityVerdict::kStronglyStable);
    EXPECT_EQ(r.proofs.size(), 15u);  // 4^2 - 1 moving modes, each with a proof
    EXPECT_EQ(check_stability(scene, wrench(0, -1, 0), r), "");
  }
  EXPECT_EQ(strong_stability<double>(scene, exact::to_double(wrench(0, -1, 0))).verdict,
            StabilityVerdict::kStronglyStable);
}

TEST(StrongStability, PushIntoTheSideFixelIsStronglyStable) {
  // Same energy argument with g = (1,0,0): a_2n = -xdd >= 0 at the fixel at (1,0).
  const auto scene = section7("1.2");
  const auto r = strong_stability<Q>(scene, wrench(1, 0, 0));
  EXPECT_EQ(r.verdict, StabilityVerdict::kStronglyStable);
  EXPECT_EQ(check_stability(scene, wrench(1, 0, 0), r), "");
}

TEST(StrongStability, DownLeftPushIsOnlyWeaklyStableAndUnstableWithLowFriction) {
  // Down-left through the centre: with mu = 1.2 the bottom fixel alone can hold it (|c_t|/c_n = 1 <= 1.2),
  // but the disk may also roll on the bottom fixel away from the side fixel.
  const auto scene = section7("1.2");
  const auto r = strong_stability<Q>(scene, wrench(-1, -1, 0));
  EXPECT_EQ(r.verdict, StabilityVerdict::kWeaklyStable);
  ASSERT_TRUE(r.has_moving);
  EXPECT_EQ(check_stability(scene, wrench(-1, -1, 0), r), "");
  // With mu = 0.3 nothing holds it: the side fixel can only push left, the bottom one needs mu >= 1.
  const auto low = section7("0.3");
  const auto u = strong_stability<Q>(low, wrench(-1, -1, 0));
  EXPECT_EQ(u.verdict, StabilityVerdict::kUnstable);
  EXPECT_FALSE(u.has_resting);
  EXPECT_EQ(check_stability(low, wrench(-1, -1, 0), u), "");
}

TEST(StrongStability, PullingAwayIsWeaklyStableOnlyUnderForceClosure) {
  // g = (0,1,0) lifts the disk. With mu = 1.2 each fixel lies in the other's friction cone (force
  // closure, section 7): the disk can wedge, c = (5, 6, -6, 6) balances g, yet it may also just lift off.
  const auto scene = section7("1.2");
  const auto r = strong_stability<Q>(scene, wrench(0, 1, 0));
  EXPECT_EQ(r.verdict, StabilityVerdict::kWeaklyStable);
  EXPECT_EQ(check_stability(scene, wrench(0, 1, 0), r), "");
  // With mu = 0.3: x balance gives c_2n = -c_1t <= 0.3 c_1n, y balance c_2t = c_1n + 1 <= 0.3 c_2n
  // <= 0.09 c_1n: impossible, so nothing holds it.
  const auto low = section7("0.3");
  const auto u = strong_stability<Q>(low, wrench(0, 1, 0));
  EXPECT_EQ(u.verdict, StabilityVerdict::kUnstable);
  EXPECT_EQ(check_stability(low, wrench(0, 1, 0), u), "");
}

TEST(StrongStability, CorruptedEvidenceIsRejected) {
  const auto scene = section7("1.2");
  auto r = strong_stability<Q>(scene, wrench(0, -1, 0));
  ASSERT_EQ(r.verdict, StabilityVerdict::kStronglyStable);
  auto wrong_verdict = r;
  wrong_verdict.verdict = StabilityVerdict::kWeaklyStable;
  EXPECT_NE(check_stability(scene, wrench(0, -1, 0), wrong_verdict), "");
  // Change one number in a dynamic proof (one that is not all zeros).
  bool corrupted = false;
  for (auto& p : r.proofs) {
    if (p.kinematic) continue;
    for (Eigen::Index i = 0; i < p.motzkin.size() && !corrupted; ++i)
      if (sgn(p.motzkin(i)) != 0) {
        p.motzkin(i) = -p.motzkin(i) - 1;
        corrupted = true;
      }
    if (corrupted) break;
  }
  ASSERT_TRUE(corrupted);
  EXPECT_NE(check_stability(scene, wrench(0, -1, 0), r), "");
  // The same evidence does not prove stability under another wrench.
  auto w = strong_stability<Q>(scene, wrench(0, -1, 0));
  EXPECT_NE(check_stability(scene, wrench(-1, -1, 0), w), "");
}

TEST(StrongStability, MembershipLpsAgreeWithTheWrenchConeAlgorithm) {
  // Each moving mode's LP answer must equal membership in the cone of the wrench cone algorithm
  // (an independent route: K z = P g, conversion, strict limits). Random small integer wrenches.
  const auto scene = section7("1.2");
  const auto model = contact_model<Q>(scene);
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> d(-3, 3);
  std::vector<geometry::FaceCone<Q>> cones;
  const auto modes = moving_modes(2);
  for (const auto& m : modes) cones.push_back(wrench_cone_face<Q>(scene, model, m, Route::kPaper));
  for (int t = 0; t < 60; ++t) {
    const Vec<Q> g = wrench(d(rng), d(rng), d(rng));
    for (std::size_t i = 0; i < modes.size(); ++i) {
      const auto ms = motion_system<Q>(scene, modes[i]);
      const bool lp = exact::strict_feasibility(ms.with_wrench(g), exact::Arith::kExact).status ==
                      exact::StrictStatus::kFeasible;
      EXPECT_EQ(lp, geometry::contains_point<Q>(cones[i], g)) << "mode " << modes[i].text() << " g = " << g.transpose();
    }
  }
}

TEST(StableRegion, EveryCellLabelEqualsTheOneWrenchVerdict) {
  // The cells come from the cones' planes; each cell's label (from the cones) must equal the LP verdict
  // at its representative, exactly, for both friction values.
  for (const char* mu : {"1.2", "0.3"}) {
    const auto scene = section7(mu);
    const auto region = stable_region<Q>(scene);
    int strong = 0, weak = 0, unstable = 0;
    for (const auto& cell : region.cells) {
      const auto r = strong_stability<Q>(scene, cell.point, {exact::Arith::kExact});
      EXPECT_EQ(r.verdict, cell.label) << "mu " << mu << " cell at " << cell.point.transpose();
      (cell.label == StabilityVerdict::kStronglyStable ? strong
       : cell.label == StabilityVerdict::kWeaklyStable ? weak
                                                       : unstable)++;
    }
    EXPECT_GT(strong, 0);  // e.g. pushing straight down
    if (std::string(mu) == "0.3") {
      EXPECT_GT(unstable, 0);
    } else {
      EXPECT_GT(weak, 0) << "e.g. the down-left push";
      EXPECT_EQ(unstable, 0) << "force closure: every wrench can be resisted";
    }
  }
}

TEST(StableRegion, SixtyRandomWrenchesAgreeWithTheirCellLabel) {
  const auto scene = section7("0.5");
  const auto region = stable_region<Q>(scene);
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> d(-4, 4);
  for (int t = 0; t < 60; ++t) {
    const Vec<Q> g = wrench(d(rng), d(rng), d(rng));
    EXPECT_EQ(region.label(g), strong_stability<Q>(scene, g).verdict) << g.transpose();
  }
}

TEST(FingerPushes, SquareWithTwoFrictionlessFixelsByHand) {
  // Square [0,2]^2 (com (1,1)), frictionless fixels under the bottom midpoint and left of the left
  // midpoint. Their contact wrenches are (0,1,0) and (1,0,0), so a resting solution needs zero torque
  // and f_x, f_y <= 0. A push on the top edge at (x,2) gives g = (0,-1,1-x): only x = 1 rests, and there
  // a moving solution would have vdot^T M vdot <= vdot^T g = -ydd <= 0 (a_1n = ydd >= 0): strongly stable.
  // The right edge at (2,y) gives (-1,0,y-1): the same at y = 1. Bottom and left pushes pull the square
  // off a fixel: unstable.
  const auto scene = geometry::read_planar_scene(exact::JsonInput::parse(R"({"kind": "planar",
      "workpiece": {"shape": {"type": "polygon", "vertices": [[0,0],[2,0],[2,2],[0,2]]}},
      "fixels": [{"position": [1, 0]}, {"position": [0, 1]}], "mu_s": 0, "mu_k": 0})",
                                                                         "square.json"));
  const auto region = stable_region<Q>(scene);
  const auto pushes = finger_pushes<Q>(scene, region);
  std::vector<std::string> got;
  for (const auto& p : pushes.edges)
    got.push_back(std::to_string(p.edge) + (p.from_closed ? "[" : "(") + exact::to_string(p.from) + "," +
                  exact::to_string(p.to) + (p.to_closed ? "]" : ")") + verdict_name(p.label));
  const std::vector<std::string> expected{
      "0(0,1)unstable",         "1(0,1/2)unstable", "1[1/2,1/2]strongly_stable", "1(1/2,1)unstable",
      "2(0,1/2)unstable",       "2[1/2,1/2]strongly_stable", "2(1/2,1)unstable", "3(0,1)unstable"};
  EXPECT_EQ(got, expected);
}

TEST(Margin, SquaredDistanceToAQuarterPlaneByHand) {
  geometry::SpanCone<Q> c;
  c.dim = 3;
  c.rays = exact::Mat<Q>(2, 3);
  c.rays << 1, 0, 0, 0, 1, 0;
  c.lines = exact::Mat<Q>(0, 3);
  EXPECT_EQ(squared_distance<Q>(wrench(-1, -1, 5), c), 27);  // nearest point: the apex
  EXPECT_EQ(squared_distance<Q>(wrench(1, -1, 2), c), 5);    // nearest point: (1,0,0) on a ray
  EXPECT_EQ(squared_distance<Q>(wrench(1, 1, 1), c), 1);     // nearest point: (1,1,0) inside the sector
  EXPECT_EQ(squared_distance<Q>(wrench(2, 3, 0), c), 0);
}

TEST(Margin, BallOfTheMarginStaysStronglyStable) {
  // Section 8: every wrench within the margin of a strongly stable biasing wrench is strongly stable.
  const auto scene = section7("1.2");
  const auto region = stable_region<Q>(scene);
  const Vec<Q> g = wrench(1, -2, 0);
  ASSERT_EQ(region.label(g), StabilityVerdict::kStronglyStable);
  const auto m = stability_margin<Q>(region, g);
  ASSERT_GT(m.squared_radius, 0);
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int> d(-20, 20);
  for (int t = 0; t < 200; ++t) {
    Vec<Q> delta = wrench(d(rng), d(rng), d(rng));
    const Q n2 = delta.dot(delta);
    if (n2 == 0) continue;
    // Scale delta to squared length just below the margin: |delta|^2 = margin * 99/100 (a rational factor
    // on the squared length is enough to stay inside: scale by s with s^2 <= 99/100 * margin / n2).
    Q s2 = m.squared_radius * Q(99, 100) / n2, s = 1;
    while (s * s > s2) s /= 2;
    EXPECT_EQ(region.label(Vec<Q>(g + s * delta)), StabilityVerdict::kStronglyStable);
  }
}

}  // namespace
}  // namespace contactcert::solvers
