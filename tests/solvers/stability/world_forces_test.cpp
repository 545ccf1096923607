// World contact forces (solvers/stability/world_forces.h): on seeded random polygons with fixels on edges of
// irrational unit normal, the forces of a resting solution and their torques balance g exactly (eq. 4 with
// zero acceleration), and those of a moving witness give M vdot.
#include "solvers/stability/world_forces.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/contact_frame.h"
#include "solvers/stability/strong_stability.h"

namespace contactcert::solvers {
namespace {

using geometry::Point2;

/// n / d in lowest terms (mpq_class(n, d) is not canonical by itself).
Q frac(long n, long d) {
  Q q(n, d);
  q.canonicalize();
  return q;
}

/// A random convex polygon (a triangle or a quadrilateral around the origin) with 2-4 touching fixels at
/// rational points of random edges, normal = the inward edge normal perp(b - a) (not unit, often irrational
/// length), and mu in [0, 1].
geometry::PlanarScene random_scene(std::mt19937& rng) {
  std::uniform_int_distribution<int> coord(1, 6), count(2, 4), mu(0, 10), num(1, 9);
  const int n = std::uniform_int_distribution<int>(3, 4)(rng);
  geometry::PolygonShape poly;
  for (int i = 0; i < n; ++i) {
    // One vertex per quadrant-like sector, counter-clockwise: convex for these ranges.
    const int sx = (i == 1 || i == 2) ? -1 : 1, sy = i >= 2 ? -1 : 1;
    if (n == 3 && i == 2) {
      poly.vertices.push_back({Q(0), Q(-coord(rng))});
      break;
    }
    poly.vertices.push_back({Q(sx * coord(rng)), Q(sy * coord(rng))});
  }
  geometry::PlanarScene scene;
  scene.workpiece.shape = poly;
  scene.workpiece.com = geometry::polygon_centroid(poly.vertices);
  scene.workpiece.inertia_per_mass = geometry::polygon_inertia_per_mass(poly.vertices, scene.workpiece.com);
  const int k = count(rng);
  for (int f = 0; f < k; ++f) {
    const std::size_t e = std::uniform_int_distribution<std::size_t>(0, poly.vertices.size() - 1)(rng);
    const Point2 a = poly.vertices[e], b = poly.vertices[(e + 1) % poly.vertices.size()];
    const Point2 p = a + frac(num(rng), 10) * (b - a);
    const auto r = geometry::frame_from_contact(poly, p, geometry::perp(b - a), Q(0));
    EXPECT_EQ(r.status, geometry::FrameStatus::kOk) << r.message;
    scene.fixels.push_back({r.frame, frac(mu(rng), 10), frac(mu(rng), 10), std::nullopt});
  }
  return scene;
}

/// (sum of f_i, sum of torque_i).
Vec<Q> total(const std::vector<WorldForce<Q>>& forces) {
  Vec<Q> s = Vec<Q>::Zero(3);
  for (const auto& w : forces) {
    s(0) += w.force(0);
    s(1) += w.force(1);
    s(2) += w.torque;
    // f = c_n n + c_t t with t = perp(n), torque = (p - com) x f: the frame printed is the frame used.
    EXPECT_EQ(w.tangent(0), -w.normal(1));
    EXPECT_EQ(w.tangent(1), w.normal(0));
  }
  return s;
}

TEST(WorldForces, RestingForcesBalanceTheWrenchExactlyOnRandomScenes) {
  std::mt19937 rng(20);
  std::uniform_int_distribution<int> w(-5, 5);
  int resting = 0, moving = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const auto scene = random_scene(rng);
    Vec<Q> g(3);
    g << w(rng), w(rng), w(rng);
    const auto r = strong_stability<Q>(scene, g);
    if (r.has_resting) {
      ++resting;
      const auto forces = world_forces<Q>(scene, r.touching, r.resting_forces);
      ASSERT_EQ(forces.size(), r.touching.size());
      EXPECT_EQ(Vec<Q>(total(forces) + g), Vec<Q>(Vec<Q>::Zero(3))) << "trial " << trial;
      for (const auto& f : forces) {
        const auto& fr = scene.fixels[static_cast<std::size_t>(f.fixel)].frame;
        const Point2 r_ = Point2{f.point(0), f.point(1)} - scene.workpiece.com;
        EXPECT_EQ(f.torque, geometry::cross(r_, Point2{f.force(0), f.force(1)}));
        EXPECT_EQ(geometry::cross(fr.normal, Point2{f.normal(0), f.normal(1)}), Q(0));  // same direction as n_i
        EXPECT_GT(geometry::dot(fr.normal, Point2{f.normal(0), f.normal(1)}), Q(0));
      }
    }
    if (r.has_moving) {
      ++moving;
      // eq. 4: M vdot = g + J c with M = diag(1, 1, I/m) per unit mass.
      const Vec<Q> s = total(world_forces<Q>(scene, r.touching, r.moving.forces)) + g;
      const Vec<Q>& a = r.moving.acceleration;
      EXPECT_EQ(s(0), a(0));
      EXPECT_EQ(s(1), a(1));
      EXPECT_EQ(s(2), scene.workpiece.inertia_per_mass * a(2)) << "trial " << trial;
    }
  }
  EXPECT_GT(resting, 10);
  EXPECT_GT(moving, 10);
}

TEST(WorldForces, IndependentOfHowTheSceneGivesANormal) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> w(-3, 3);
  int compared = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const auto scene = random_scene(rng);
    Vec<Q> g(3);
    g << w(rng), w(rng), w(rng);
    auto scaled = scene;
    for (auto& f : scaled.fixels) f.frame.normal = frac(7, 3) * f.frame.normal;
    const auto a = strong_stability<Q>(scene, g), b = strong_stability<Q>(scaled, g);
    ASSERT_EQ(a.verdict, b.verdict);
    if (!a.has_resting) continue;
    ++compared;
    const auto fa = world_forces<Q>(scene, a.touching, a.resting_forces);
    const auto fb = world_forces<Q>(scaled, b.touching, b.resting_forces);
    for (std::size_t i = 0; i < fa.size(); ++i) {
      // The frame the output states is the one the scene writes (the model's scaling stays internal): the same
      // world force, against a normal 7/3 as long, has components 3/7 as large.
      EXPECT_EQ(fb[i].normal, Vec<Q>(frac(7, 3) * fa[i].normal));
      EXPECT_EQ(fb[i].c_n, frac(3, 7) * fa[i].c_n);
      EXPECT_EQ(fb[i].c_t, frac(3, 7) * fa[i].c_t);
      EXPECT_EQ(fa[i].force, fb[i].force);
      EXPECT_EQ(fa[i].force, Vec<Q>(fa[i].c_n * fa[i].normal + fa[i].c_t * fa[i].tangent));
    }
  }
  EXPECT_GT(compared, 5);
}

}  // namespace
}  // namespace contactcert::solvers
