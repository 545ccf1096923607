// The Shamos-Hoey sweep against the pairwise test it replaces, on seeded random vertex lists over a small
// integer grid (many touching, collinear and vertical edges) and on simple star-shaped polygons.
#include "geometry/simple_polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace contactcert::geometry {
namespace {

/// Closed segments ab and cd share a point (the reference test).
bool meet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

bool pairwise_crossing(const std::vector<Point2>& V) {
  const std::size_t n = V.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;
      if (meet(V[i], V[(i + 1) % n], V[j], V[(j + 1) % n])) return true;
    }
  return false;
}

/// The sweep's precondition: no repeated or collinear consecutive vertex.
bool admissible(const std::vector<Point2>& V) {
  const std::size_t n = V.size();
  for (std::size_t i = 0; i < n; ++i)
    if (V[i] == V[(i + 1) % n] || orient(V[(i + n - 1) % n], V[i], V[(i + 1) % n]) == 0) return false;
  return true;
}

TEST(SimplePolygon, AgreesWithPairwiseOnRandomGridPolygons) {
  std::mt19937_64 rng(17);
  int tested = 0, simple = 0;
  for (int trial = 0; tested < 4000; ++trial) {
    const int n = 3 + static_cast<int>(rng() % 8), grid = 2 + static_cast<int>(rng() % 5);
    std::vector<Point2> V;
    for (int i = 0; i < n; ++i) V.push_back({Q(static_cast<long>(rng() % grid)), Q(static_cast<long>(rng() % grid))});
    if (!admissible(V)) continue;
    ++tested;
    const bool expected = pairwise_crossing(V);
    simple += !expected;
    const std::optional<std::size_t> found = crossing_edge(V);
    ASSERT_EQ(found.has_value(), expected) << "trial " << trial;
  }
  EXPECT_GT(simple, 100);  // both outcomes are exercised
}

TEST(SimplePolygon, StarShapedPolygonsAreSimple) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    // Vertices on rays of increasing angle (integer directions sorted by angle), at random integer radii.
    std::vector<std::pair<long, long>> dirs;
    for (long x = -6; x <= 6; ++x)
      for (long y = -6; y <= 6; ++y)
        if ((x || y) && std::gcd(x, y) == 1) dirs.push_back({x, y});
    std::sort(dirs.begin(), dirs.end(),
              [](auto a, auto b) { return std::atan2(a.second, a.first) < std::atan2(b.second, b.first); });
    std::vector<Point2> V;
    for (auto [x, y] : dirs) {
      const long r = 1 + static_cast<long>(rng() % 4);
      V.push_back({Q(r * x), Q(r * y)});
    }
    if (!admissible(V)) continue;
    EXPECT_FALSE(crossing_edge(V).has_value());
    EXPECT_FALSE(pairwise_crossing(V));
  }
}

TEST(SimplePolygon, FindsABowtieAndAVertexOnAnEdge) {
  EXPECT_TRUE(crossing_edge({{0, 0}, {2, 2}, {2, 0}, {0, 2}}).has_value());
  EXPECT_TRUE(crossing_edge({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}).has_value());
  EXPECT_FALSE(crossing_edge({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}).has_value());
}

}  // namespace
}  // namespace contactcert::geometry
