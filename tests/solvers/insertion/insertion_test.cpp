#include "solvers/insertion/insertion.h"

#include <gtest/gtest.h>

#include <random>

#include "exact/input_error.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "tests/solvers/scene_fixtures.h"

namespace contactcert::solvers {
namespace {

using exact::Q;
using exact::Vec;

using testing::random_wrench;
using testing::wrench;

geometry::PlanarScene load(const char* name, const char* mu) { return testing::scene_with_mu(name, mu); }

TEST(Insertion, DiskIntoTwoFixelsEq21) {
  // The disk of Figure 6 (fixels at (0,-1) and (1,0)), mu = 0.2. A push through the centre toward the
  // corner between the fixels seats it from any state; a push away from them never does.
  const auto scene = load("bt2002_section7_disk.json", "0.2");
  const auto ins = insertion<Q>(scene);
  ASSERT_EQ(ins.sets.size(), 4u);
  EXPECT_TRUE(ins.in_goal(wrench(1, -1, 0)));
  EXPECT_FALSE(ins.in_goal(wrench(-1, 1, 0)));
  EXPECT_FALSE(ins.in_goal(wrench(0, -1, 0)));  // straight down never reaches the side fixel: G_ms
  // The frictionless pushes in G_goal: one open arc of push points, between the directions (-1,5) and
  // (-5,1) from the centre, symmetric about the diagonal.
  const auto pushes = insertion_pushes<Q>(scene, ins);
  std::vector<const ArcInterval<Q, bool>*> in;
  for (const auto& a : pushes.arcs)
    if (a.label) in.push_back(&a);
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0]->from(0) * 5, -in[0]->from(1));
  EXPECT_EQ(in[0]->to(1) * 5, -in[0]->to(0));
  EXPECT_FALSE(in[0]->from_closed);
  EXPECT_FALSE(in[0]->to_closed);
}

TEST(Insertion, BothRoutesGiveTheSameGoalSet) {
  const auto scene = load("bt2002_fig10_pentagon_insert.json", "0.2");
  const auto a = insertion<Q>(scene, Route::kPaper);
  const auto b = insertion<Q>(scene, Route::kProject);
  ASSERT_EQ(a.cones.size(), b.cones.size());
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> d(-5, 5);
  for (int t = 0; t < 200; ++t) {
    const Vec<Q> g = random_wrench(d, rng);
    EXPECT_EQ(a.in_goal(g), b.in_goal(g)) << g.transpose();
  }
  EXPECT_EQ(a.redundant, b.redundant);
}

TEST(Insertion, GoalShrinksWithFriction) {
  // Figure 11's trend: the pushes that seat the pentagon get fewer as mu grows, none at mu = 0.4.
  auto goal_length = [](const char* mu) {
    const auto s = load("bt2002_fig10_pentagon_insert.json", mu);
    const auto p = insertion_pushes<Q>(s, insertion<Q>(s));
    Q total = 0;
    for (const auto& e : p.edges)
      if (e.label) total += e.to - e.from;
    return total;
  };
  const Q a = goal_length("0.01"), b = goal_length("0.2"), c = goal_length("0.4");
  EXPECT_GT(a, b);
  EXPECT_GT(b, 0);
  EXPECT_EQ(c, 0);
}

TEST(Insertion, NeedsTheGoalConfigurationWithTwoOrThreeFixels) {
  auto scene = load("bt2002_section7_disk.json", "0.2");
  scene.fixels[1].frame.gap_squared = 1;
  EXPECT_THROW(insertion<Q>(scene), exact::InputError);
  auto one = load("bt2002_section7_disk.json", "0.2");
  one.fixels.pop_back();
  EXPECT_THROW(insertion<Q>(one), exact::InputError);
}

}  // namespace
}  // namespace contactcert::solvers
