// A query's limit is a status (queries/limit.h): with_limits turns what the solvers throw into a Limit, and each
// family of queries returns its budget as one, with what was covered.
#include "queries/limit.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "queries/convert_query.h"
#include "queries/design_query.h"
#include "queries/modes_query.h"
#include "runtime/scenes.h"
#include "solvers/design/distribute.h"

namespace contactcert::queries {
namespace {

SceneInput scene(const std::string& name) { return load_scene(runtime::bundled_scenes_dir() + "/" + name); }

TEST(WithLimits, AnAnswerPassesThrough) {
  const Limited<int> r = with_limits(exact::Arith::kExact, [] { return 7; });
  ASSERT_TRUE(r);
  EXPECT_EQ(*r, 7);
}

TEST(WithLimits, ABudgetThrownInsideIsTheLimit) {
  const Limited<int> r = with_limits(exact::Arith::kVerified, []() -> int {
    throw exact::BudgetExceeded("mode enumeration: node budget of 1 prefixes exhausted", "1 prefixes visited");
  });
  ASSERT_FALSE(r);
  EXPECT_EQ(r.limit().kind, Limit::Kind::kBudget);
  EXPECT_EQ(r.limit().text(), "mode enumeration: node budget of 1 prefixes exhausted (covered: 1 prefixes visited)");
}

// The float path's rounded numbers contradicting the algorithm is "undecided"; on an exact path it is a bug.
TEST(WithLimits, ALogicErrorIsUndecidedOnlyInFloat) {
  const auto broken = []() -> int { throw std::logic_error("rank lacking"); };
  const Limited<int> r = with_limits(exact::Arith::kFloat, broken);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.limit().kind, Limit::Kind::kUndecided);
  EXPECT_EQ(r.limit().what, "the float computation is inconsistent after rounding (rank lacking)");
  EXPECT_THROW(with_limits(exact::Arith::kVerified, broken), std::logic_error);
  EXPECT_THROW(
      with_limits(exact::Arith::kFloat, []() -> int { throw exact::InputError("f.json", "$.mu", "a number"); }),
      exact::InputError);
}

// A work with a limit of its own is not wrapped twice.
TEST(WithLimits, AWorkReturningALimitKeepsIt) {
  const Limited<int> r = with_limits(exact::Arith::kExact, []() -> Limited<int> { return Limit{"w", "c"}; });
  ASSERT_FALSE(r);
  EXPECT_EQ(r.limit().text(), "w (covered: c)");
}

TEST(LimitOfModes, NodeAndOutputBudgets) {
  const SceneInput disk = scene("bt2002_section7_disk.json");
  ModesOptions o;
  o.max_nodes = 1;
  Limited<ModesAnswer> r = run_modes(disk, o);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.limit().kind, Limit::Kind::kBudget);
  EXPECT_EQ(r.limit().text(),
            "mode enumeration: node budget of 1 prefixes exhausted (covered: 1 prefixes visited, 0 feasible modes "
            "found)");
  o = {};
  o.unions = true;
  o.max_modes = 10;
  r = run_modes(disk, o);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.limit().what, "mode enumeration: output budget of 10 modes exhausted");
  o.max_modes = 100000;
  EXPECT_TRUE(run_modes(disk, o));
}

// The search's own stop names the command and the file (the CLI prints it without "budget exceeded: ").
TEST(LimitOfDesign, PlacementBudgetStopsTheSearch) {
  DesignOptions o;
  o.candidates = "200";
  o.stable_under = "0,-1,0";
  o.max_placements = 3;
  o.out = testing::TempDir() + "/limit_design";
  const SceneInput pawl = scene("design_ratchet_pawl.json");
  const Limited<DesignRun> r = run_design(pawl, o, *solvers::serial_distributor());
  ASSERT_FALSE(r);
  EXPECT_EQ(r.limit().kind, Limit::Kind::kStopped);
  EXPECT_EQ(r.limit().what, "design " + pawl.name + ": placement budget --max-placements reached");
  EXPECT_EQ(r.limit().covered.rfind("16 of 1313400 placements in 1 of 82088 chunks; ", 0), 0u) << r.limit().covered;
}

// A budget thrown while the candidates are made (before the search) is the Limit too.
TEST(LimitOfDesign, LatticeBudgetBeforeTheSearch) {
  DesignOptions o;
  o.lattice = "1/10000000";
  o.stable_under = "0,-1,0";
  o.out = testing::TempDir() + "/limit_design_lattice";
  const Limited<DesignRun> r = run_design(scene("design_ratchet_pawl.json"), o, *solvers::serial_distributor());
  ASSERT_FALSE(r);
  EXPECT_EQ(r.limit().kind, Limit::Kind::kBudget);
  EXPECT_NE(r.limit().what.find("lattice lines"), std::string::npos) << r.limit().what;
}

TEST(LimitOfConvert, TimeLimitStopsTheDoubleDescription) {
  ConvertOptions o;
  o.common.time_limit = 1e-9;
  const Limited<ConvertAnswer> r = run_convert(exact::JsonInput::load(CONVERT_SCENE), o);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.limit().kind, Limit::Kind::kBudget);
  EXPECT_EQ(r.limit().what.rfind("double description: time limit of 1e-09 s reached", 0), 0u) << r.limit().what;
}

}  // namespace
}  // namespace contactcert::queries
