// The spatial mode tree's counts against Zaslavsky's formula, for contacts in general position (issue 34).
//
// Regions. A central arrangement of n hyperplanes in general position in R^e (n >= 1, e >= 1) has, by Zaslavsky's
// theorem (r = sum over the flats X of |mu(0, X)|; in general position the flats are the intersections of i < e
// hyperplanes, with mu = (-1)^i C(n - 1, i) summed), r(n, e) = 2 sum_{i=0}^{e-1} C(n - 1, i) regions; r(0, e) = 1.
// Faces. In general position the flats of dimension >= 1 are the intersections of j < e of the hyperplanes, each of
// dimension e - j and cut by the other n - j in general position, plus the origin when n >= e; every face is a region
// of the arrangement restricted to its flat, so the faces number
//   F(n, e) = sum_{j=0}^{min(n, e - 1)} C(n, j) r(n - j, e - j) + [n >= e].
// The correspondence. The tree lists the modes in the closed cone {a_n >= 0 at every contact} of vdot in R^6 (it has
// no letter for a_n < 0), so the normal hyperplanes a_n = 0 alone give faces of a cone, not of an arrangement. What
// is an arrangement: the modes with no `s`. There every a_n = 0, so vdot lies in L = {a_n,i = 0, i = 1..k}, and with
// a square pyramid (edges +-mu t1, +-mu t2) the sliding letters are the signs of U = (t1 + t2) . a_t and
// V = (t1 - t2) . a_t (letter 2j's rows (d_{j-1} - d_j) . a_t > 0 and (d_{j+1} - d_j) . a_t > 0 are two of -U, U,
// -V, V > 0; the face letters put one of them at 0; `f` both): the 9 letters of a touching contact are the 9 sign
// patterns of (U, V) in {-, 0, +}^2. So the modes without `s` are in bijection with the faces of the central
// arrangement of the 2k hyperplanes U_i = 0, V_i = 0 in L. Its rank is not 2k in general but e(k): the body is rigid,
// so from rest two points accelerate with (acc_2 - acc_1) . (p_2 - p_1) = 0, and the 3k functionals acc_i on R^6 have
// rank 3 (k = 1), 5 (k = 2) or 6 (k >= 3, points not on a line); less the k independent normals,
// e(k) = 2, 3, 3, 2, 1, 0 for k = 1..6. For random data the 2k hyperplanes are otherwise in general position in that
// rank (a lineality space changes no count), so there are F(2k, e(k)) modes without `s`, and r(2k, e(k)) with sector
// letters only (A, C, E, G), its regions. And as the k normals' functionals are independent (k <= 6), every one of
// the 2^k patterns of `s` and touching contacts is met by some mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "geometry/spatial_scene.h"
#include "solvers/spatial/spatial_modes.h"

namespace contactcert::solvers::spatial {
namespace {

using geometry::SpatialContact;
using geometry::SpatialScene;

long binomial(long n, long i) {
  if (i < 0 || n < 0 || i > n) return 0;
  long c = 1;
  for (long t = 1; t <= i; ++t) c = c * (n - i + t) / t;
  return c;
}

long regions(long n, long e) {
  if (n == 0) return 1;
  long sum = 0;
  for (long i = 0; i < e; ++i) sum += binomial(n - 1, i);
  return 2 * sum;
}

long faces(long n, long e) {
  long sum = n >= e ? 1 : 0;
  for (long j = 0; j <= std::min(n, e - 1); ++j) sum += binomial(n, j) * regions(n - j, e - j);
  return sum;
}

// k contacts at random rational points with random integer normals (entries -9..9), square pyramids (mu = 1/2) in
// the default frames: in general position with probability 1 (the seeds are fixed).
SpatialScene generic_scene(std::mt19937& rng, std::size_t k) {
  std::uniform_int_distribution<int> num(-60, 60), den(1, 7), normal(-9, 9);
  SpatialScene s;
  s.body.mass = 1;
  s.body.com = {Q(0), Q(0), Q(0)};
  for (std::size_t i = 0; i < k; ++i) {
    SpatialContact c;
    c.point = {Q(num(rng), den(rng)), Q(num(rng), den(rng)), Q(num(rng), den(rng))};
    do c.normal = {Q(normal(rng)), Q(normal(rng)), Q(normal(rng))};
    while (sgn(c.normal[0]) == 0 || sgn(c.normal[1]) == 0 || sgn(c.normal[2]) == 0);
    std::tie(c.t1, c.t2) = geometry::default_tangent_frame(c.normal);
    c.edges = {{Q(1, 2), 0}, {0, Q(1, 2)}, {Q(-1, 2), 0}, {0, Q(-1, 2)}};
    s.contacts.push_back(std::move(c));
  }
  return s;
}

TEST(SpatialArrangement, FormulaOnSmallCases) {
  EXPECT_EQ(regions(3, 2), 6);   // three lines through the origin of the plane
  EXPECT_EQ(regions(3, 3), 8);   // the octants
  EXPECT_EQ(regions(4, 3), 14);  // four generic planes through the origin of R^3
  EXPECT_EQ(faces(2, 2), 9);     // one contact: its 9 touching letters
  EXPECT_EQ(faces(3, 2), 13);    // 6 sectors, 6 rays, the origin
  EXPECT_EQ(faces(4, 3), 51);    // two contacts: 14 regions, 24 faces on one plane, 12 on two, the origin
}

// k = 1 to 6 contacts, 3 seeds each (1 in the ASan + UBSan build): the modes without `s` count F(2k, e(k)), the
// sector-only ones r(2k, e(k)), and the s/touching patterns all 2^k.
constexpr int kSeeds = CONTACTCERT_SANITIZED ? 1 : 3;
TEST(SpatialArrangement, ModesWithoutSeparationAreTheFacesOfTheSlidingArrangement) {
  std::mt19937 rng(3434);
  for (std::size_t k = 1; k <= 6; ++k)
    for (int seed = 0; seed < kSeeds; ++seed) {
      const SpatialScene scene = generic_scene(rng, k);
      const SpatialModeTree tree = spatial_modes(spatial_model(scene));
      long touching = 0, sectors = 0;
      std::set<std::string> patterns;
      for (const std::string& m : tree.modes) {
        std::string pattern;
        for (char L : m) pattern += L == 's' ? 's' : 't';
        patterns.insert(pattern);
        if (m.find('s') != std::string::npos) continue;
        ++touching;
        sectors += m.find_first_not_of("ACEG") == std::string::npos;
      }
      const long n = 2 * static_cast<long>(k), e = std::min(3 * n / 2 - (k >= 2), 6L) - n / 2;
      EXPECT_EQ(touching, faces(n, e)) << "k = " << k << ", seed " << seed;
      EXPECT_EQ(sectors, e == 0 ? 0 : regions(n, e)) << "k = " << k << ", seed " << seed;
      EXPECT_EQ(patterns.size(), std::size_t{1} << k) << "k = " << k << ", seed " << seed;
    }
}

}  // namespace
}  // namespace contactcert::solvers::spatial
