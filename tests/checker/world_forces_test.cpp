// The world forces that `check` shows (checker/world_forces.h), from the checker's own Jacobian: against forces
// derived by hand from eq. 4 (so a wrong Jacobian in the solver or in the checker fails here), and against the
// solver's resting solutions, which must balance g exactly in the checker's model too.
#include "checker/world_forces.h"

#include <gtest/gtest.h>

#include "checker/frame_check.h"
#include "exact/json_input.h"
#include "solvers/stability/strong_stability.h"

namespace contactcert::checker {
namespace {

using exact::Q;
using exact::Vec;

geometry::PlanarScene scene_of(const std::string& text) {
  const frame_check::CheckedSceneRead read = frame_check::read_checked_scene(exact::JsonInput::parse(text, "scene"));
  EXPECT_EQ(read.violation, "");
  return read.scene;
}

Vec<Q> vec(std::initializer_list<Q> v) {
  Vec<Q> out(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (const Q& x : v) out(i++) = x;
  return out;
}

TEST(CheckedWorldForces, HandDerivedFromEquationFour) {
  // The 4 x 2 block (com (2, 1)) on fixels at (1, 0) and (3, 0), the normal (0, 1) into it, t = (-1, 0), and a
  // fixel half a unit left of (0, 1), not touching. Fixel 0 with c_n = 2, c_t = 3: f = 2 (0, 1) + 3 (-1, 0) =
  // (-3, 2), torque (p - com) x f = (-1, -1) x (-3, 2) = -1 * 2 - (-1) * (-3) = -5. Fixel 1 with c_n = 1, c_t = -1:
  // f = (1, 1), torque (1, -1) x (1, 1) = 1 + 1 = 2.
  const geometry::PlanarScene scene = scene_of(R"({"kind": "planar",
    "workpiece": {"shape": {"type": "polygon", "vertices": [[0, 0], [4, 0], [4, 2], [0, 2]]}},
    "fixels": [{"position": [1, 0]}, {"position": [3, 0]}, {"position": ["-1/2", 1]}], "mu_s": "1/2"})");
  const auto forces = checked_world_forces(scene, {0, 1}, vec({2, 1, 3, -1}));
  ASSERT_EQ(forces.size(), 2u);
  EXPECT_EQ(forces[0].fixel, 0);
  EXPECT_EQ(forces[0].force, vec({-3, 2}));
  EXPECT_EQ(forces[0].torque, Q(-5));
  EXPECT_EQ(forces[0].normal, vec({0, 1}));
  EXPECT_EQ(forces[0].tangent, vec({-1, 0}));
  EXPECT_EQ(forces[0].c_n, Q(2));
  EXPECT_EQ(forces[0].c_t, Q(3));
  EXPECT_EQ(forces[1].force, vec({1, 1}));
  EXPECT_EQ(forces[1].torque, Q(2));
  EXPECT_EQ(forces[1].point, vec({3, 0}));
}

TEST(CheckedWorldForces, ScaledNormalStatesTheWrittenFrame) {
  // An explicit contact with normal (0, 2) at (1, 0): the model's pair (w_n, w_t) = ((0, 2, -2), (-2, 0, -2)) is
  // scaled to the primitive ((0, 1, -1), (-1, 0, -1)), so raw c = (2, 0) is f = (0, 2); the view states it against
  // the normal as written: c_n = f . n / |n|^2 = 4 / 4 = 1.
  const geometry::PlanarScene scene = scene_of(R"({"kind": "planar",
    "workpiece": {"shape": {"type": "polygon", "vertices": [[0, 0], [4, 0], [4, 2], [0, 2]]}},
    "fixels": [{"point": [1, 0], "normal": [0, 2]}], "mu_s": "1/2"})");
  const auto forces = checked_world_forces(scene, {0}, vec({2, 0}));
  ASSERT_EQ(forces.size(), 1u);
  EXPECT_EQ(forces[0].force, vec({0, 2}));
  EXPECT_EQ(forces[0].torque, Q(-2));
  EXPECT_EQ(forces[0].normal, vec({0, 2}));
  EXPECT_EQ(forces[0].c_n, Q(1));
  EXPECT_EQ(forces[0].c_t, Q(0));
}

TEST(CheckedWorldForces, SolverRestingSolutionsBalanceInTheCheckersModel) {
  const geometry::PlanarScene scene = scene_of(R"({"kind": "planar",
    "workpiece": {"shape": {"type": "polygon", "vertices": [[0, 0], [4, 0], [4, 2], [0, 2]]}},
    "fixels": [{"position": [1, 0]}, {"position": [3, 0]}, {"position": [0, 1]}], "mu_s": "1/2"})");
  int resting = 0;
  for (int fx = -2; fx <= 2; ++fx)
    for (int tz = -2; tz <= 2; ++tz) {
      const Vec<Q> g = vec({fx, -3, tz});
      const auto r = solvers::strong_stability<Q>(scene, g);
      if (!r.has_resting) continue;
      ++resting;
      Vec<Q> sum = g;
      for (const auto& f : checked_world_forces(scene, r.touching, r.resting_forces)) {
        sum(0) += f.force(0), sum(1) += f.force(1), sum(2) += f.torque;
      }
      EXPECT_EQ(sum, Vec<Q>(Vec<Q>::Zero(3))) << "g = (" << fx << ", -3, " << tz << ")";
    }
  EXPECT_GT(resting, 5);
}

}  // namespace
}  // namespace contactcert::checker
