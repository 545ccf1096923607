// Assembly stability on seeded random small assemblies (N = 2-3 boxes, k <= 6 contacts, random loads and friction)
// against a 4^k brute force of the same model written here: one LP per mode in its own formulation (Table 2's
// letters as rows on (vdot, c_n, c_t), no energy row, no relaxation), and the uniqueness argument for n..n (with
// a resting solution, every all-rolling solution is at rest: M vdot - g in range(J) and J^T vdot = 0 fix vdot).
// Without a resting solution the verdict is unstable whatever the modes do, so only stable draws enumerate.
#include <gtest/gtest.h>

#include <random>

#include "checker/assembly_check.h"
#include "exact/strict_feasibility.h"
#include "tests/solvers/assembly/assembly_fixtures.h"

namespace contactcert::solvers::assembly {
namespace {

using geometry::Point2;
using testing::body;
using testing::box;
using testing::mu;
using testing::obstacle;
using testing::point;
using testing::SceneText;

/// The brute force's model: rows built as A x = b with x = (vdot, per contact c_n, c_t, sigma, rho+, rho-).
struct Brute {
  const geometry::Assembly& a;
  Eigen::Index N3, k, cols;
  Eigen::Index cn(Eigen::Index i) const { return N3 + 5 * i; }

  /// d . (velocity of the contact point on `to` - on `from`) as a row over vdot: the point moves on body b with
  /// (a_x, a_y) + alpha (-r_y, r_x).
  Vec<Q> relative(const geometry::AssemblyContact& c, const Point2& d) const {
    Vec<Q> row = Vec<Q>::Zero(cols);
    for (const auto& [p, s] : {std::pair{c.from, -1}, std::pair{c.to, 1}}) {
      if (!p.movable()) continue;
      const Point2 r = c.point - a.bodies[p.index].com;
      const auto b = static_cast<Eigen::Index>(3 * p.index);
      row(b) += s * d.x;
      row(b + 1) += s * d.y;
      row(b + 2) += s * (d.y * r.x - d.x * r.y);
    }
    return row;
  }

  /// Whether mode (s l r n per contact) has a solution; `rest` adds vdot = 0.
  bool feasible(const std::string& mode, bool rest) const {
    std::vector<Vec<Q>> rows;
    std::vector<Q> rhs;
    struct {
      std::vector<bool> is_free, strict;
    } S;
    S.is_free.assign(static_cast<std::size_t>(cols), false);
    S.strict.assign(static_cast<std::size_t>(cols), false);
    for (Eigen::Index j = 0; j < N3; ++j) S.is_free[static_cast<std::size_t>(j)] = true;
    const auto unit = [&](Eigen::Index j, const Q& v) {
      Vec<Q> r = Vec<Q>::Zero(cols);
      r(j) = v;
      return r;
    };
    for (Eigen::Index i = 0; i < k; ++i) {
      const geometry::AssemblyContact& c = a.contacts[static_cast<std::size_t>(i)];
      const Point2 t{-c.normal.y, c.normal.x};
      const Eigen::Index n_ = cn(i), t_ = n_ + 1, sg = n_ + 2, r1 = n_ + 3, r2 = n_ + 4;
      S.is_free[static_cast<std::size_t>(t_)] = true;
      const char L = mode[static_cast<std::size_t>(i)];
      const Vec<Q> an = relative(c, c.normal), at = relative(c, t);
      if (L == 's') {
        S.strict[static_cast<std::size_t>(sg)] = true;
        rows.push_back(an - unit(sg, 1));
        rows.push_back(unit(n_, 1));
        rows.push_back(unit(t_, 1));
      } else {
        rows.push_back(an);
        if (L == 'n') {
          rows.push_back(at);
          rows.push_back(unit(n_, c.mu_s) - unit(t_, 1) - unit(r1, 1));
          rows.push_back(unit(n_, c.mu_s) + unit(t_, 1) - unit(r2, 1));
        } else {
          S.strict[static_cast<std::size_t>(sg)] = true;
          const int dir = L == 'l' ? 1 : -1;  // l: a_t > 0, c_t = -mu_k c_n; r: a_t < 0, c_t = mu_k c_n
          rows.push_back(Q(dir) * at - unit(sg, 1));
          rows.push_back(unit(t_, 1) + unit(n_, dir * c.mu_k));
        }
      }
      rhs.resize(rows.size(), Q(0));
    }
    // Newton-Euler: m a = load + sum of contact forces (c_n n + c_t t on `to`, minus on `from`), torques about com.
    for (std::size_t b = 0; b < a.bodies.size(); ++b) {
      const geometry::Body& B = a.bodies[b];
      Vec<Q> fx = unit(static_cast<Eigen::Index>(3 * b), B.mass),
             fy = unit(static_cast<Eigen::Index>(3 * b + 1), B.mass),
             tz = unit(static_cast<Eigen::Index>(3 * b + 2), B.inertia);
      for (Eigen::Index i = 0; i < k; ++i) {
        const geometry::AssemblyContact& c = a.contacts[static_cast<std::size_t>(i)];
        const Point2 t{-c.normal.y, c.normal.x};
        for (const auto& [p, s] : {std::pair{c.from, -1}, std::pair{c.to, 1}}) {
          if (!p.movable() || p.index != b) continue;
          const Point2 r = c.point - B.com;
          fx(cn(i)) -= s * c.normal.x, fx(cn(i) + 1) -= s * t.x;
          fy(cn(i)) -= s * c.normal.y, fy(cn(i) + 1) -= s * t.y;
          tz(cn(i)) -= s * geometry::cross(r, c.normal), tz(cn(i) + 1) -= s * geometry::cross(r, t);
        }
      }
      rows.push_back(fx), rhs.push_back(B.load_fx);
      rows.push_back(fy), rhs.push_back(B.load_fy);
      rows.push_back(tz), rhs.push_back(B.load_torque);
    }
    if (rest)
      for (Eigen::Index j = 0; j < N3; ++j) rows.push_back(unit(j, 1)), rhs.push_back(Q(0));
    // The rows by their non-zero entries (the verified LP's fast route), b = rhs.
    exact::SparseStrictSystem<Q> sparse{static_cast<Eigen::Index>(rows.size()), cols, {}, S.is_free, S.strict};
    Vec<Q> b(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      for (Eigen::Index j = 0; j < cols; ++j)
        if (sgn(rows[r](j)) != 0) sparse.entries.push_back({static_cast<Eigen::Index>(r), j, rows[r](j)});
      b(static_cast<Eigen::Index>(r)) = rhs[r];
    }
    return exact::StrictSolver<Q>(sparse).solve(b).status == exact::StrictStatus::kFeasible;
  }

  AssemblyVerdict verdict() const {
    const bool resting = feasible(std::string(static_cast<std::size_t>(k), 'n'), true);
    if (!resting) return AssemblyVerdict::kUnstable;
    std::string mode(static_cast<std::size_t>(k), 's');
    const std::string letters = "slrn";
    for (long m = 0; m < (1L << (2 * k)); ++m) {
      for (Eigen::Index i = 0; i < k; ++i) mode[static_cast<std::size_t>(i)] = letters[(m >> (2 * i)) & 3];
      if (mode == std::string(static_cast<std::size_t>(k), 'n')) continue;  // at rest (uniqueness)
      if (feasible(mode, false)) return AssemblyVerdict::kWeaklyStable;
    }
    return AssemblyVerdict::kStronglyStable;
  }
};

AssemblyVerdict brute_force(const geometry::Assembly& a) {
  const auto N3 = static_cast<Eigen::Index>(3 * a.bodies.size());
  const auto k = static_cast<Eigen::Index>(a.contacts.size());
  return Brute{a, N3, k, N3 + 5 * k}.verdict();
}

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
    const AssemblyVerdict want = brute_force(*a);
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

}  // namespace
}  // namespace contactcert::solvers::assembly
