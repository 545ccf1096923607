// The strongly stable set as a union of merged face cones (solvers/stability/strong_cones.h): on the section 7
// disk and the Figure 10 pentagon, g lies in one of the cones iff the region labels it strongly stable, for every
// cell's representative and for seeded random wrenches; and merging leaves fewer cones than cells.
#include "solvers/stability/strong_cones.h"

#include <gtest/gtest.h>

#include <random>

#include "../scene_fixtures.h"

namespace contactcert::solvers {
namespace {

bool in_cone(const geometry::FaceCone<Q>& c, const Vec<Q>& g) {
  for (Eigen::Index r = 0; r < c.strict.rows(); ++r)
    if (sgn(Q(c.strict.row(r).dot(g))) >= 0) return false;
  for (Eigen::Index r = 0; r < c.equalities.rows(); ++r)
    if (sgn(Q(c.equalities.row(r).dot(g))) != 0) return false;
  return true;
}

TEST(StrongCones, UnionOfTheConesIsTheStronglyStableSet) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> w(-6, 6);
  for (const char* name : {"bt2002_section7_disk.json", "bt2002_fig10_pentagon_insert.json"}) {
    SCOPED_TRACE(name);
    const auto scene = geometry::load_planar_scene(std::string(CONTACTCERT_SCENES_DIR "/") + name);
    const auto region = stable_region<Q>(scene);
    const auto cones = strongly_stable_cones(region);
    long strong_cells = 0;
    auto check = [&](const Vec<Q>& g) {
      const bool strong = region.label(g) == StabilityVerdict::kStronglyStable;
      int hits = 0;
      for (const auto& c : cones) hits += in_cone(c.cone, g);
      EXPECT_EQ(hits > 0, strong) << "g = " << g.transpose();
      EXPECT_LE(hits, 1) << "the merged cones are disjoint";
    };
    for (const auto& c : region.cells) {
      strong_cells += c.label == StabilityVerdict::kStronglyStable;
      check(c.point);
    }
    for (int i = 0; i < 300; ++i) {
      Vec<Q> g(3);
      g << w(rng), w(rng), w(rng);
      check(g);
    }
    EXPECT_LT(static_cast<long>(cones.size()), strong_cells);
  }
}

}  // namespace
}  // namespace contactcert::solvers
