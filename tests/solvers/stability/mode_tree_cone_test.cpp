// The prefix cones of mode_tree_cone.h against the exact LP on random sign systems in R^3, and
// walk_modes_by_cones against the LP walk on random scenes: the same modes and dead prefixes, every certificate
// checked, every prefix decided without an LP.
#include "solvers/stability/mode_tree_cone.h"

#include <gtest/gtest.h>

#include <random>

#include "exact/json_input.h"
#include "exact/strict_feasibility.h"
#include "geometry/scene_json.h"
#include "solvers/stability/contact_modes.h"
#include "solvers/stability/mode_tree.h"
#include "tests/solvers/stability/random_scene.h"

namespace contactcert::solvers {
namespace {

using exact::Int128;
using exact::Q;

// The rows as the strict system f . v - sigma = 0 (sigma >= 0, > 0 on kPositive), f . v = 0 on kZero; v free.
exact::StrictSystem<Q> system_of(const std::vector<ConeRow>& rows) {
  const auto m = static_cast<Eigen::Index>(rows.size());
  exact::StrictSystem<Q> s{
      exact::Mat<Q>::Zero(m, 3 + m), exact::Vec<Q>::Zero(m), {true, true, true}, {false, false, false}};
  for (Eigen::Index i = 0; i < m; ++i) {
    const ConeRow& r = rows[static_cast<std::size_t>(i)];
    for (Eigen::Index d = 0; d < 3; ++d) s.A(i, d) = Q(static_cast<long>(r.f[static_cast<std::size_t>(d)]));
    s.A(i, 3 + i) = r.sign == RowSign::kZero ? 0 : -1;
    s.is_free.push_back(false);
    s.strict.push_back(r.sign == RowSign::kPositive);
  }
  return s;
}

TEST(PrefixCone, RandomSignSystemsAgreeWithTheExactLpAndEveryNoHasACheckedCertificate) {
  std::mt19937_64 rng(35);
  std::uniform_int_distribution<long> entry(-3, 3);
  int feasible = 0, infeasible = 0;
  for (int t = 0; t < 400; ++t) {
    std::vector<ConeRow> rows;
    PrefixCone cone;
    const int m = 1 + static_cast<int>(rng() % 7);
    for (int i = 0; i < m; ++i) {
      const int kind = static_cast<int>(rng() % 5);  // zero rows rarer than sign rows
      rows.push_back({{entry(rng), entry(rng), entry(rng)},
                      kind == 0  ? RowSign::kZero
                      : kind < 3 ? RowSign::kNonNegative
                                 : RowSign::kPositive});
      cone.cut(rows.back());
    }
    const auto lp = exact::strict_feasibility(system_of(rows), exact::Arith::kExact);
    const std::optional<Int3> v = cone.point_meeting(rows);
    ASSERT_EQ(v.has_value(), lp.status == exact::StrictStatus::kFeasible) << "system " << t;
    if (v) {
      EXPECT_TRUE(meets_rows(rows, *v));
      ++feasible;
      continue;
    }
    ++infeasible;
    CertificateCandidates all;
    for (std::size_t i = 0; i < rows.size(); ++i) all.rows.push_back(i);
    all.new_rows = rows.size();
    const auto w = cone_motzkin(rows, cone, all, 100000);
    ASSERT_TRUE(w.has_value()) << "system " << t;
    exact::Vec<Q> y(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i)  // slack coefficient -1: y = -w (sum y_i f_i = 0, y_i (-1) >= 0)
      exact::ring::to_rational(-(*w)[i], Int128(1), y(static_cast<Eigen::Index>(i)));
    EXPECT_TRUE(exact::verify_motzkin(system_of(rows), y)) << "system " << t;
  }
  EXPECT_GT(feasible, 50);
  EXPECT_GT(infeasible, 50);
}

// The block's floor rows a_n = vy + x omega at x = 0 and 9 (strict), 10 (equality), 11 (strict, new) and its
// a_t = vx > 0: no acceleration meets them. The first strict row that vanishes on the cone (x = 0) with the
// candidates gives 1 (x = 0) + 10 (x = 11) - 11 (x = 10); the circuit of the rows at x = 9, 10, 11 gives 1, -2, 1,
// fewer digits: the shorter is chosen, checks, and the first one is handed back for reuse.
TEST(PrefixCone, TheShorterOfTheFirstAndTheCircuitsCertificatesIsChosen) {
  const std::vector<ConeRow> rows{{{0, 1, 0}, RowSign::kPositive},
                                  {{0, 1, 9}, RowSign::kPositive},
                                  {{0, 1, 10}, RowSign::kZero},
                                  {{1, 0, 0}, RowSign::kPositive},
                                  {{0, 1, 11}, RowSign::kPositive}};
  PrefixCone parent;
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) parent.cut(rows[i]);
  ASSERT_TRUE(parent.point_meeting({rows.begin(), rows.end() - 1}).has_value());
  PrefixCone cone = parent;
  cone.cut(rows.back());
  ASSERT_FALSE(cone.point_meeting(rows).has_value());
  std::vector<Int128> first;
  const auto w = cone_motzkin(rows, cone, certificate_candidates(rows, 4, parent), 1000, nullptr, &first);
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(*w, (std::vector<Int128>{0, 1, -2, 0, 1}));
  EXPECT_EQ(first, (std::vector<Int128>{1, 0, -11, 0, 10}));
  exact::Vec<Q> y(5);
  for (Eigen::Index i = 0; i < 5; ++i) exact::ring::to_rational(-(*w)[static_cast<std::size_t>(i)], Int128(1), y(i));
  EXPECT_TRUE(exact::verify_motzkin(system_of(rows), y));
}

TEST(PrefixCone, ACutThroughALinealityVectorOrAnEqualityKeepsTheRightRays) {
  PrefixCone cone;                               // R^3
  cone.cut({{0, 0, 1}, RowSign::kNonNegative});  // z >= 0: lineality x, y; ray e3
  EXPECT_EQ(cone.rays().size(), 1u);
  cone.cut({{1, 0, 0}, RowSign::kNonNegative});  // x >= 0
  cone.cut({{0, 1, 0}, RowSign::kNonNegative});  // y >= 0: the positive octant
  ASSERT_EQ(cone.rays().size(), 3u);
  cone.cut({{1, -1, 0}, RowSign::kZero});  // x = y: the quarter plane spanned by (1, 1, 0) and (0, 0, 1)
  ASSERT_EQ(cone.rays().size(), 2u);
  EXPECT_EQ(cone.ray_sum(), (Int3{1, 1, 1}));
  cone.cut({{-1, 0, 1}, RowSign::kPositive});  // z >= x: still both rays' wedge, clipped at (1, 1, 1)
  EXPECT_TRUE(cone.point_meeting({{{-1, 0, 1}, RowSign::kPositive}, {{1, -1, 0}, RowSign::kZero}}).has_value());
  cone.cut({{0, 0, -1}, RowSign::kPositive});  // z < 0 on the cone: only 0 is left
  EXPECT_TRUE(cone.rays().empty());
}

geometry::PlanarScene parse(const std::string& text) {
  return geometry::read_planar_scene(exact::JsonInput::parse(text, "scene.json"));
}

TEST(ModeTreeCones, RandomScenesGiveTheLpWalksModesAndDeadPrefixesWithoutAnLp) {
  std::mt19937_64 rng(3535);
  long modes = 0, dead = 0;
  for (int t = 0; t < 120; ++t) {
    const std::string text = test::random_scene(rng, 1 + static_cast<std::size_t>(rng() % 6));
    const geometry::PlanarScene scene = parse(text);
    for (bool printed : {false, true}) {
      ContactModeOptions options;
      options.printed_separation = printed;
      options.unions = t % 5 == 0;
      const ContactModes m = contact_modes(scene, options);  // walk_modes_by_cones
      const ModeTree<Q> lp = walk_modes(m.model, m.alphabet, options.tree);
      ASSERT_EQ(m.tree.modes.size(), lp.modes.size()) << text;
      for (std::size_t i = 0; i < lp.modes.size(); ++i) {
        EXPECT_EQ(m.tree.modes[i].text(), lp.modes[i].text());
        EXPECT_TRUE(realises(m.model, m.alphabet.rules, m.tree.accelerations[i], m.tree.modes[i]));
      }
      ASSERT_EQ(m.tree.dead.size(), lp.dead.size()) << text;
      for (std::size_t i = 0; i < lp.dead.size(); ++i) {
        const ModeString& prefix = m.tree.dead[i].prefix;
        EXPECT_EQ(prefix.text(), lp.dead[i].prefix.text());
        EXPECT_TRUE(
            exact::verify_motzkin(kinematic_system(m.model, prefix, m.alphabet.rules).dense(), m.tree.dead[i].motzkin))
            << prefix.text() << "\n"
            << text;
      }
      EXPECT_EQ(m.tree.nodes, lp.nodes);
      EXPECT_EQ(m.tree.lps_by_cones, m.tree.lps) << "a prefix went to its LP\n" << text;
      modes += static_cast<long>(lp.modes.size());
      dead += static_cast<long>(lp.dead.size());
    }
  }
  EXPECT_GT(modes, 500);
  EXPECT_GT(dead, 500);
}

}  // namespace
}  // namespace contactcert::solvers
