// Assembly stability on seeded random small assemblies (N = 2-3 boxes, k <= 6 contacts, random loads and friction)
// against the 4^k brute force of assembly_brute_force.h.
#include <gtest/gtest.h>

#include <random>

#include "checker/assembly_check.h"
#include "tests/solvers/assembly/assembly_brute_force.h"
#include "tests/solvers/assembly/assembly_fixtures.h"

namespace contactcert::solvers::assembly {
namespace {

using testing::body;
using testing::box;
using testing::mu;
using testing::obstacle;
using testing::point;
using testing::SceneText;

/// A random friction pair: mu_s from {0, 1/8, 1/4, 1/2, 1}, mu_k = mu_s times 1, 1/2 or 1/4.
std::string random_friction(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> d(0, 4), three(0, 2);
  const int i = d(rng);
  const Q mu_s = i == 0 ? Q(0) : Q(1, 1 << (4 - i));
  return "\"mu_s\": " + testing::num(mu_s) + ", \"mu_k\": " + testing::num(mu_s / (1 << three(rng)));
}

/// Contacts between `first` and `second` at one or two points of [lo, hi] on the line y = level (or x = level when
/// `side`), the normal from the first into the second written either way round; friction mostly `friction`.
void random_contacts(SceneText& s, std::mt19937_64& rng, const std::string& first, const std::string& second,
                     const Q& lo, const Q& hi, const Q& level, bool side, const std::string& friction) {
  std::uniform_int_distribution<int> four(0, 3), at(0, 4), coin(0, 1);
  const int n = four(rng) == 0 ? 1 : 2;
  const bool ends = n == 2 && coin(rng);  // the interface's two ends, else random quarters
  int used = -1;
  for (int j = 0; j < n; ++j) {
    int u = ends ? 4 * j : at(rng);
    if (u == used) u = (u + 2) % 5;
    used = u;
    const Q v = lo + (hi - lo) * Q(u, 4);
    const std::string p = side ? point(level, v) : point(v, level);
    const std::string nrm = side ? "[1, 0]" : "[0, 1]", neg = side ? "[-1, 0]" : "[0, -1]";
    const std::string f = four(rng) == 0 ? random_friction(rng) : friction;  // mostly the scene's
    if (coin(rng))
      s.contact(first, second, p, nrm, f);
    else
      s.contact(second, first, p, neg, f);
  }
}

/// A random assembly of 2 or 3 boxes with at most 6 contacts, or nothing if this draw is not a valid scene.
std::optional<geometry::Assembly> random_assembly(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> size(1, 3), coin(0, 1), three(0, 2), lateral(-2, 2);
  SceneText s;
  const std::string g = obstacle(testing::ground(s));
  struct Box {
    Q x0, y0, x1, y1;
  };
  std::vector<Box> boxes;
  const auto add = [&](const Box& b) {
    std::string more;
    if (three(rng) != 0) {  // its weight m = area and a lateral push of m j / 8 at the com, j in -2..2
      const Q m = (b.x1 - b.x0) * (b.y1 - b.y0);
      more = "\"load\": [" + testing::num(m * lateral(rng) / 8) + ", " + testing::num(-m) + ", 0]";
    }
    boxes.push_back(b);
    return s.body(box(b.x0, b.y0, b.x1, b.y1), more);
  };
  const int N = 2 + coin(rng);
  const std::string friction = random_friction(rng);
  {
    const Box b{0, 0, size(rng), size(rng)};
    add(b);
    random_contacts(s, rng, g, body(0), b.x0, b.x1, 0, false, friction);
  }
  for (int i = 1; i < N; ++i) {
    const std::size_t below = static_cast<std::size_t>(std::uniform_int_distribution<int>(0, i - 1)(rng));
    const Box L = boxes[below];  // a copy: add() grows boxes
    const bool beside = three(rng) == 0;
    if (beside) {  // on the ground, touching `below`'s right face
      const Box b{L.x1, 0, L.x1 + size(rng), Q(size(rng))};
      add(b);
      random_contacts(s, rng, g, body(static_cast<std::size_t>(i)), b.x0, b.x1, 0, false, friction);
      const Q hi = b.y1 < L.y1 ? b.y1 : L.y1;
      if (L.y0 == 0)
        random_contacts(s, rng, body(below), body(static_cast<std::size_t>(i)), 0, hi, L.x1, true, friction);
    } else {  // on top, shifted by a random quarter
      const Q shift = Q(three(rng) - 1, 2 + coin(rng) * 2);
      const Box b{L.x0 + shift, L.y1, L.x0 + shift + size(rng), L.y1 + size(rng)};
      add(b);
      const Q lo = b.x0 < L.x0 ? L.x0 : b.x0, hi = b.x1 < L.x1 ? b.x1 : L.x1;
      random_contacts(s, rng, body(below), body(static_cast<std::size_t>(i)), lo, hi, L.y1, false, friction);
    }
  }
  if (s.contacts.size() > 6) return std::nullopt;
  try {
    return s.read();
  } catch (const exact::InputError&) {  // overlapping boxes, a point off a boundary
    return std::nullopt;
  }
}

// The ASan + UBSan build of CI (-O0, where this test alone took over five minutes) checks the first 20 of the
// normal build's 100 cases.
#ifdef CONTACTCERT_SANITIZED
constexpr int kCases = 20;
#else
constexpr int kCases = 100;
#endif

TEST(AssemblyRandom, AgreesWithBruteForceOn4PowerKModes) {
  std::mt19937_64 rng(31);
  int cases = 0, counts[3] = {0, 0, 0};
  for (int draw = 0; cases < kCases && draw < 2000; ++draw) {
    const std::optional<geometry::Assembly> a = random_assembly(rng);
    if (!a) continue;
    ++cases;
    const AssemblyStabilityResult r = assembly_stability(*a);
    ASSERT_EQ(r.status, AssemblyStatus::kDecided);
    const AssemblyVerdict want = testing::brute_force(*a);
    EXPECT_EQ(r.verdict, want) << "draw " << draw << ": " << verdict_name(r.verdict) << " vs " << verdict_name(want);
    EXPECT_EQ(checker::check_assembly_stability(*a, r), "") << "draw " << draw;
    ++counts[static_cast<int>(want)];
  }
  EXPECT_EQ(cases, kCases);
  // The draws reach every verdict (seed 31: 18 strongly stable, 4 weakly stable, 78 unstable in 100 cases).
  if (kCases == 100) {
    for (const int c : counts) EXPECT_GE(c, 3) << counts[0] << " " << counts[1] << " " << counts[2];
  }
}

/// Every member of the systems a and b equal (entries in the same order).
void expect_same_system(const AssemblySystem& a, const AssemblySystem& b, const std::string& what) {
  ASSERT_EQ(a.system.rows, b.system.rows) << what;
  ASSERT_EQ(a.system.cols, b.system.cols) << what;
  ASSERT_EQ(a.system.entries.size(), b.system.entries.size()) << what;
  for (std::size_t e = 0; e < a.system.entries.size(); ++e) {
    const exact::Entry<Q>&x = a.system.entries[e], &y = b.system.entries[e];
    EXPECT_TRUE(x.row == y.row && x.col == y.col && x.value == y.value) << what << ", entry " << e;
  }
  EXPECT_EQ(a.system.is_free, b.system.is_free) << what;
  EXPECT_EQ(a.system.strict, b.system.strict) << what;
  EXPECT_EQ(a.b, b.b) << what;
  EXPECT_EQ(a.resting, b.resting) << what;
  EXPECT_EQ(a.vdot_size, b.vdot_size) << what;
  EXPECT_EQ(a.c_n_column, b.c_n_column) << what;
  EXPECT_EQ(a.c_t_column, b.c_t_column) << what;
  EXPECT_EQ(a.c_t_per_c_n, b.c_t_per_c_n) << what;
  EXPECT_EQ(a.row_label, b.row_label) << what;
}

// The stability walk rebuilds every prefix's system in one AssemblySystem (assembly_system(model, letters, out)):
// whatever system it held before (another assembly's, a resting one, more or fewer entries), the result is the
// system built afresh.
TEST(AssemblyRandom, SystemRebuiltInPlaceIsTheFreshSystem) {
  std::mt19937_64 rng(32);
  std::uniform_int_distribution<int> letter(0, 4), one_in_six(0, 5);
  AssemblySystem reused;
  int cases = 0;
  for (int draw = 0; cases < 30 && draw < 1000; ++draw) {
    const std::optional<geometry::Assembly> a = random_assembly(rng);
    if (!a) continue;
    ++cases;
    const AssemblyModel model = assembly_model(*a);
    for (int t = 0; t < 8; ++t) {
      std::string letters;
      for (std::size_t i = 0; i < model.contacts.size(); ++i) letters += "slrn*"[letter(rng)];
      const bool resting = one_in_six(rng) == 0;
      assembly_system(model, letters, reused, resting);
      expect_same_system(reused, assembly_system(model, letters, resting),
                         "draw " + std::to_string(draw) + ", " + letters + (resting ? " resting" : ""));
    }
  }
  EXPECT_EQ(cases, 30);
}

}  // namespace
}  // namespace contactcert::solvers::assembly
