// The strongly stable set as a union of maximal sign cones (solvers/stability/strong_cones.h), on the section 7
// disk, the Figure 10 pentagon and the Figure 4 fixtures: a cell's representative lies in one of the cones iff
// the region labels it strongly stable (so the union is the strongly stable set exactly), and so do seeded
// random wrenches; every cone is maximal (relaxing any letter of its pattern admits a cell that is not strongly
// stable, so no facet is redundant); no two cones have a convex union (an exact witness a + b outside the
// strongly stable set, a and b cell representatives of the two cones); no cone is covered by the others.
#include "solvers/stability/strong_cones.h"

#include <gtest/gtest.h>

#include <random>

#include "../scene_fixtures.h"
#include "runtime/scenes.h"

namespace contactcert::solvers {
namespace {

bool in_cone(const geometry::FaceCone<Q>& c, const Vec<Q>& g) {
  for (Eigen::Index r = 0; r < c.strict.rows(); ++r)
    if (sgn(Q(c.strict.row(r).dot(g))) >= 0) return false;
  for (Eigen::Index r = 0; r < c.inequalities.rows(); ++r)
    if (sgn(Q(c.inequalities.row(r).dot(g))) > 0) return false;
  for (Eigen::Index r = 0; r < c.equalities.rows(); ++r)
    if (sgn(Q(c.equalities.row(r).dot(g))) != 0) return false;
  return true;
}

/// Whether the sign vector `signs` matches `pattern` (letters + - 0 P N *).
bool matches(const std::string& pattern, const std::string& signs) {
  for (std::size_t j = 0; j < pattern.size(); ++j) {
    const char p = pattern[j], s = signs[j];
    const bool ok = p == '*' || p == s || (p == 'P' && s != '-') || (p == 'N' && s != '+');
    if (!ok) return false;
  }
  return true;
}

/// The letters that allow strictly more signs than `p`.
std::string relaxations(char p) {
  if (p == '+') return "P*";
  if (p == '-') return "N*";
  if (p == '0') return "PN*";
  if (p == 'P' || p == 'N') return "*";
  return "";
}

TEST(StrongCones, MaximalConesWhoseUnionIsTheStronglyStableSet) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> w(-6, 6);
  for (const char* name : {"bt2002_section7_disk.json", "bt2002_fig10_pentagon_insert.json", "bt2002_fig4a_lla.json",
                           "bt2002_fig4c_peg_lra.json"}) {
    SCOPED_TRACE(name);
    const auto scene = geometry::load_planar_scene((contactcert::runtime::bundled_scenes_dir() + "/") + name);
    const auto region = stable_region<Q>(scene);
    const auto cones = strongly_stable_cones(region);
    std::vector<std::string> signs;
    long strong_cells = 0;
    for (const auto& c : region.cells) signs.push_back(sign_vector(region, c.point));
    auto check = [&](const Vec<Q>& g) {
      const bool strong = region.label(g) == StabilityVerdict::kStronglyStable;
      bool hit = false;
      for (const auto& c : cones) {
        EXPECT_EQ(in_cone(c.cone, g), matches(c.pattern, sign_vector(region, g))) << c.pattern;
        hit = hit || in_cone(c.cone, g);
      }
      EXPECT_EQ(hit, strong) << "g = " << g.transpose();
    };
    for (const auto& c : region.cells) {
      strong_cells += c.label == StabilityVerdict::kStronglyStable;
      check(c.point);
    }
    for (int i = 0; i < 200; ++i) {
      Vec<Q> g(3);
      g << w(rng), w(rng), w(rng);
      check(g);
    }
    auto admits_unstable = [&](const std::string& pattern) {
      for (std::size_t i = 0; i < signs.size(); ++i)
        if (matches(pattern, signs[i]) && region.cells[i].label != StabilityVerdict::kStronglyStable) return true;
      return false;
    };
    for (const auto& c : cones)
      for (std::size_t j = 0; j < c.pattern.size(); ++j)
        for (char r : relaxations(c.pattern[j])) {
          std::string q = c.pattern;
          q[j] = r;
          EXPECT_TRUE(admits_unstable(q)) << c.pattern << ": letter " << j << " relaxes to " << r;
        }
    for (std::size_t a = 0; a < cones.size(); ++a)
      for (std::size_t b = a + 1; b < cones.size(); ++b) {
        bool witness = false;
        for (std::size_t i = 0; i < signs.size() && !witness; ++i)
          for (std::size_t k = 0; k < signs.size() && !witness; ++k)
            if (matches(cones[a].pattern, signs[i]) && matches(cones[b].pattern, signs[k]))
              witness = region.label(Vec<Q>(region.cells[i].point + region.cells[k].point)) !=
                        StabilityVerdict::kStronglyStable;
        EXPECT_TRUE(witness) << cones[a].pattern << " and " << cones[b].pattern << ": no witness of a non-convex union";
      }
    EXPECT_LT(static_cast<long>(cones.size()), strong_cells);
  }
}

}  // namespace
}  // namespace contactcert::solvers
