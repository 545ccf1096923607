// The wrench cone of a spatial contact mode (solvers/spatial/spatial_cone.h) on the bundled box on a plane: the
// all-separating cone by hand, and every cone against the mode's LP (spatial_stability.h's system) at seeded wrenches.
#include "solvers/spatial/spatial_cone.h"

#include <gtest/gtest.h>

#include <random>

#include "runtime/scenes.h"
#include "solvers/spatial/spatial_stability.h"

namespace contactcert::solvers::spatial {
namespace {

geometry::SpatialScene box() {
  return geometry::read_spatial_scene(exact::JsonInput::parse(
      exact::JsonInput::read_text(runtime::bundled_scenes_dir() + "/spatial_box_on_plane.json"), "box"));
}

// ssss: no contact force, vdot = M^-1 g, and each corner lifts: a_z + y_i alpha_x - x_i alpha_y > 0 with a = f
// and alpha = I^-1 tau (I diagonal), at (x_i, y_i) = (+-1, +-1): four strict rows on (f_z, tau_x, tau_y), the
// facets of a square cone there, so the cone is open, 6-dimensional, and its lineality is (f_x, f_y, tau_z).
TEST(SpatialCone, AllSeparatingIsOpenWithFourStrictRows) {
  const geometry::NncForm<Q> cone = spatial_wrench_cone(box(), "ssss");
  EXPECT_EQ(cone.dimension(), 6);
  EXPECT_EQ(cone.face.strict.rows(), 4);
  EXPECT_EQ(cone.face.inequalities.rows(), 0);
  EXPECT_EQ(cone.closure.lines.rows(), 3);
  Vec<Q> up = Vec<Q>::Zero(6), down = Vec<Q>::Zero(6);
  up(2) = 1;
  down(2) = -1;
  EXPECT_TRUE(geometry::contains_point(cone.face, up));
  EXPECT_FALSE(geometry::contains_point(cone.face, down));
}

// Each cone holds exactly the wrenches for which its mode's system is feasible: seeded integer wrenches against one
// strict-feasibility LP each, on modes that stick, separate, tip and slide.
TEST(SpatialCone, ConesAgreeWithTheModesLps) {
  const geometry::SpatialScene s = box();
  const SpatialModel model = spatial_model(s);
  std::mt19937 rng(34);
  std::uniform_int_distribution<int> entry(-2, 2);
  for (const char* mode : {"ffff", "ssss", "ffss", "EEEE"}) {
    const geometry::NncForm<Q> cone = spatial_wrench_cone(s, mode);
    const exact::SparseStrictSystem<Q> sys = spatial_motion_system(s.body, model, mode);
    int inside = 0;
    for (int trial = 0; trial < 40; ++trial) {
      Vec<Q> g(6);
      for (Eigen::Index d = 0; d < 6; ++d) g(d) = entry(rng);
      if (trial == 0) g << 0, 0, -1, 0, 0, 0;        // gravity: in ffff's cone
      if (trial == 1) g << 0, 0, -1, 0, 2, 0;        // the weight at x = 2: in ffss's (the box tips)
      if (trial == 2) g << Q(3, 5), 0, -1, 0, 0, 0;  // past atan(mu): in EEEE's (it slides)
      Vec<Q> b = Vec<Q>::Zero(sys.rows);
      b.tail(6) = g;
      const bool feasible = exact::StrictSolver<Q>(sys).solve(b).status == exact::StrictStatus::kFeasible;
      EXPECT_EQ(geometry::contains_point(cone.face, g), feasible) << mode << " trial " << trial;
      inside += feasible;
    }
    EXPECT_GT(inside, 0) << mode;  // both sides of every cone are tested
    EXPECT_LT(inside, 40) << mode;
  }
}

}  // namespace
}  // namespace contactcert::solvers::spatial
