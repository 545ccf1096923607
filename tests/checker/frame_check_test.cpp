// The checkers' own frames (issue 29): the verifier accepts the frames the geometry defines and refuses a frame
// forged on a collinear inner edge, a closest point that is not unique, a fixel inside, a wrong gap; and on seeded
// random star-shaped polygons the solvers' frames, the checker's frames and the modes of `modes` agree with a
// brute-force closest-point oracle written here.
#include "checker/frame_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <sstream>

#include "checker/modes_check.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "solvers/stability/contact_modes.h"
#include "solvers/ucp/problem.h"

namespace contactcert::solvers {
namespace {

using exact::Q;
using geometry::ContactFrame;
using geometry::FrameInput;
using geometry::FrameStatus;
using geometry::Point2;
using geometry::Shape;

Point2 P(int x, int y) { return {Q(x), Q(y)}; }
Point2 P(const char* x, const char* y) { return {Q(x), Q(y)}; }
FrameInput at(const Point2& f) { return {f, {}, {}, {}}; }
FrameInput contact(const Point2& p, const Point2& n, const Q& gap = 0) { return {std::nullopt, p, n, gap}; }
FrameStatus verdict(const Shape& s, const FrameInput& in, const ContactFrame& f) {
  return checker::frame_check::frame_violation(s, in, f).status;
}

// The L-shape of issue 29 (counter-clockwise) and a four-pointed star (tests/geometry/contact_frame_test.cpp).
const Shape kL = geometry::PolygonShape{{P(0, 0), P(4, 0), P(4, 1), P(2, 1), P(2, 3), P(0, 3)}};
const Shape kStar = geometry::PolygonShape{
    {P(2, 0), P("1/2", "1/2"), P(0, 2), P("-1/2", "1/2"), P(-2, 0), P("-1/2", "-1/2"), P(0, -2), P("1/2", "-1/2")}};
const Shape kDisk = geometry::DiskShape{P(0, 0), Q(5)};

TEST(FrameCheck, AcceptsTheFramesTheGeometryDefines) {
  // (0,1) on the L's outer edge x = 0: normal any positive multiple of (1,0), gap 0.
  EXPECT_EQ(verdict(kL, at(P(0, 1)), {P(0, 1), P(1, 0), 0}), FrameStatus::kOk);
  EXPECT_EQ(verdict(kL, at(P(0, 1)), {P(0, 1), P(3, 0), 0}), FrameStatus::kOk);
  EXPECT_EQ(verdict(kL, contact(P(0, 1), P(2, 0)), {P(0, 1), P(2, 0), 0}), FrameStatus::kOk);
  // (-1,1): point (0,1), normal p - f = (1,0), gap^2 1; (5,2): the vertex (4,1), normal (-1,-1) in its cone.
  EXPECT_EQ(verdict(kL, at(P(-1, 1)), {P(0, 1), P(1, 0), 1}), FrameStatus::kOk);
  EXPECT_EQ(verdict(kL, at(P(5, 2)), {P(4, 1), P(-1, -1), 2}), FrameStatus::kOk);
  // Explicit contacts at vertices: in the cone of the inward edge normals, convex (0,0) and reflex (2,1).
  EXPECT_EQ(verdict(kL, contact(P(0, 0), P(1, 1)), {P(0, 0), P(1, 1), 0}), FrameStatus::kOk);
  EXPECT_EQ(verdict(kL, contact(P(2, 1), P(-1, -2)), {P(2, 1), P(-1, -2), 0}), FrameStatus::kOk);
  EXPECT_EQ(verdict(kL, contact(P(3, 1), P(0, -1), 2), {P(3, 1), P(0, -1), 4}), FrameStatus::kOk);
  // Star: (2,1) has the unique closest point (17/10,1/10) at 9/10 (contact_frame_test.cpp derives it by hand).
  EXPECT_EQ(verdict(kStar, at(P(2, 1)), {P("17/10", "1/10"), P(-1, -3), Q("9/10")}), FrameStatus::kOk);
  // Disk: on the circle, and outside along a Pythagorean direction.
  EXPECT_EQ(verdict(kDisk, at(P(3, 4)), {P(3, 4), P(-3, -4), 0}), FrameStatus::kOk);
  EXPECT_EQ(verdict(kDisk, at(P(6, 8)), {P(3, 4), P(-6, -8), 25}), FrameStatus::kOk);
  EXPECT_EQ(verdict(kDisk, contact(P(-5, 0), P(1, 0), 3), {P(-5, 0), P(1, 0), 9}), FrameStatus::kOk);
}

TEST(FrameCheck, RefusesForgedFrames) {
  // The frame of the L's inner edge y = 1 at (0,1), which lies on the edge x = 0 only: issue 29's wrong frame.
  EXPECT_EQ(verdict(kL, at(P(0, 1)), {P(0, 1), P(0, -2), 0}), FrameStatus::kNormalNotUnique);
  EXPECT_EQ(verdict(kL, contact(P(0, 1), P(0, -1)), {P(0, 1), P(0, -1), 0}), FrameStatus::kNormalNotUnique);
  // A point on the inner edge's line but off every segment.
  EXPECT_EQ(verdict(kL, contact(P(1, 1), P(0, -1)), {P(1, 1), P(0, -1), 0}), FrameStatus::kClosestNotUnique);
  // Closest point not unique: (3,2) is 1 from (3,1) on edge 2 and from (2,2) on edge 3.
  EXPECT_EQ(verdict(kL, at(P(3, 2)), {P(3, 1), P(0, -1), 1}), FrameStatus::kClosestNotUnique);
  EXPECT_EQ(verdict(kStar, at(P(1, 1)), {P("4/5", "2/5"), P(-1, -3), Q("2/5")}), FrameStatus::kClosestNotUnique);
  // A closer point exists: (3,5/2) is 3/2 above (3,1) on edge 2, a frame right in every local respect, but 1 from
  // (2,5/2) on edge 3.
  EXPECT_EQ(verdict(kL, at(P("3", "5/2")), {P(3, 1), P(0, -1), Q("9/4")}), FrameStatus::kClosestNotUnique);
  // The fixel inside the foot, with the frame of the edge below it.
  EXPECT_EQ(verdict(kL, at(P("1", "1/2")), {P(1, 0), P(0, 4), Q("1/4")}), FrameStatus::kInsideWorkpiece);
  // Wrong gaps.
  EXPECT_EQ(verdict(kL, at(P(-1, 1)), {P(0, 1), P(1, 0), 2}), FrameStatus::kClosestNotUnique);
  EXPECT_EQ(verdict(kL, at(P(-1, 1)), {P(0, 1), P(1, 0), 0}), FrameStatus::kClosestNotUnique);
  EXPECT_EQ(verdict(kL, contact(P(3, 1), P(0, -1), 2), {P(3, 1), P(0, -1), 2}), FrameStatus::kClosestNotUnique);
  // Normals: off p - f, out of a vertex cone, zero.
  EXPECT_EQ(verdict(kL, at(P(5, 2)), {P(4, 1), P(-1, -2), 2}), FrameStatus::kNormalNotUnique);
  EXPECT_EQ(verdict(kL, contact(P(2, 1), P(1, -1)), {P(2, 1), P(1, -1), 0}), FrameStatus::kNormalNotUnique);
  EXPECT_EQ(verdict(kL, contact(P(0, 0), P(0, 0)), {P(0, 0), P(0, 0), 0}), FrameStatus::kNormalNotUnique);
  EXPECT_EQ(verdict(kStar, contact(P("1/2", "1/2"), P(0, -1)), {P("1/2", "1/2"), P(0, -1), 0}),
            FrameStatus::kNormalNotUnique);
  // Disk: a point off the circle, a normal off the radius, the wrong point of the circle, a fixel inside.
  EXPECT_EQ(verdict(kDisk, at(P(6, 8)), {P(6, 8), P(-6, -8), 0}), FrameStatus::kClosestNotUnique);
  EXPECT_EQ(verdict(kDisk, at(P(3, 4)), {P(3, 4), P(-4, 3), 0}), FrameStatus::kNormalNotUnique);
  EXPECT_EQ(verdict(kDisk, at(P(3, 4)), {P(4, 3), P(-4, -3), 2}), FrameStatus::kNormalNotUnique);
  EXPECT_EQ(verdict(kDisk, at(P(1, 1)), {P(3, 4), P(-3, -4), 13}), FrameStatus::kInsideWorkpiece);
}

TEST(FrameCheck, DerivesItsOwnFrames) {
  geometry::FrameResult r = checker::frame_check::checked_frame(kL, at(P(0, 1)));
  ASSERT_EQ(r.status, FrameStatus::kOk);
  EXPECT_TRUE(r.frame.normal == P(3, 0));
  EXPECT_EQ(checker::frame_check::checked_frame(kL, at(P(2, 1))).status, FrameStatus::kNormalNotUnique);
  EXPECT_EQ(checker::frame_check::checked_frame(kL, at(P(1, 1))).status, FrameStatus::kInsideWorkpiece);
  EXPECT_EQ(checker::frame_check::checked_frame(kStar, at(P(1, 1))).status, FrameStatus::kClosestNotUnique);
  EXPECT_EQ(checker::frame_check::checked_frame(kL, contact(P(0, 1), P(0, -1))).status, FrameStatus::kNormalNotUnique);
  EXPECT_EQ(checker::frame_check::checked_frame(kDisk, at(P(6, 1))).status, FrameStatus::kIrrationalDirection);
  r = checker::frame_check::checked_frame(kDisk, at(P(6, 8)));
  ASSERT_EQ(r.status, FrameStatus::kOk);
  EXPECT_TRUE(r.frame.point == P(3, 4) && r.frame.normal == P(-6, -8) && r.frame.gap_squared == 25);
}

TEST(FrameCheck, ReadsTheScenesFramesItself) {
  const std::string L = R"({"kind":"planar","workpiece":{"shape":{"type":"polygon",
    "vertices":[[0,0],[4,0],[4,1],[2,1],[2,3],[0,3]]}},"mu_s":"1/3","fixels":[)";
  checker::frame_check::CheckedSceneRead read = checker::frame_check::read_checked_scene(
      exact::JsonInput::parse(L + R"({"position":[0,1]},{"position":[0,2]}]})", "L"));
  ASSERT_EQ(read.violation, "");
  ASSERT_EQ(read.scene.fixels.size(), 2u);
  EXPECT_TRUE(read.scene.fixels[0].frame.normal == P(3, 0));
  read = checker::frame_check::read_checked_scene(
      exact::JsonInput::parse(L + R"({"position":[0,2]},{"point":[0,1],"normal":[0,-1]}]})", "L"));
  EXPECT_NE(read.violation.find("fixel 1"), std::string::npos) << read.violation;
  read = checker::frame_check::read_checked_scene(exact::JsonInput::parse(L + R"({"position":[1,1]}]})", "L"));
  EXPECT_NE(read.violation.find("fixel 0"), std::string::npos) << read.violation;
  EXPECT_NE(read.violation.find("inside"), std::string::npos) << read.violation;
}

TEST(FrameCheck, BuildsQuasistaticScenesWithItsOwnFrames) {
  const std::string qs = R"({"kind":"quasistatic_scene","workpiece":{"shape":{"type":"polygon",
    "vertices":[[0,0],[4,0],[4,1],[2,1],[2,3],[0,3]]}},"gravity":[-2,1],"contacts":[)";
  const exact::JsonInput right = exact::JsonInput::parse(qs + R"({"position":[0,1],"mu":"1/3"},
    {"point":[0,2],"normal":[1,0],"mu":"1/3"}]})",
                                                         "qs");
  const ucp::UcpProblem checked = ucp::read_ucp_problem(right, nullptr, checker::frame_check::checked_frame);
  EXPECT_EQ(ucp::to_json_text(checked), ucp::to_json_text(ucp::read_ucp_problem(right)));
  // W^T's first row is contact 0's (n, r x n) = (3, 0, (0,1) x (3,0)) = (3, 0, -3).
  EXPECT_EQ(checked.quasistatic->P(0, 0), Q(3));
  EXPECT_EQ(checked.quasistatic->P(0, 2), Q(-3));
  const exact::JsonInput inner =
      exact::JsonInput::parse(qs + R"({"point":[0,1],"normal":[0,-2],"mu":"1/3"}]})", "qs_inner");
  EXPECT_THROW(ucp::read_ucp_problem(inner, nullptr, checker::frame_check::checked_frame), exact::InputError);
}

// ---- seeded random star-shaped polygons against a brute-force oracle ----

// The oracle's frame of a fixel at f on a polygon that is star-shaped about the origin (the origin inside its
// kernel): f on the boundary when an edge's bounding box holds it and it is collinear with the edge (a vertex: no
// frame); strictly inside when the segment from the origin to f meets no edge (every ray from a kernel point leaves
// the polygon once); else the closest of all vertices and all perpendicular feet strictly inside their edges,
// unique when one point attains the minimum.
struct Oracle {
  enum Status { kOk, kInside, kVertex, kNotUnique } status = kOk;
  Point2 point, normal;
  Q gap2;
};

int orient(const Point2& a, const Point2& b, const Point2& c) { return sgn(Q(geometry::cross(b - a, c - a))); }

bool in_box(const Point2& a, const Point2& b, const Point2& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool segments_meet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && in_box(a, b, c)) || (o2 == 0 && in_box(a, b, d)) || (o3 == 0 && in_box(c, d, a)) ||
         (o4 == 0 && in_box(c, d, b));
}

Oracle oracle(const std::vector<Point2>& V, const Point2& f) {
  const std::size_t n = V.size();
  Oracle o;
  for (std::size_t i = 0; i < n; ++i) {
    if (V[i] == f) return {Oracle::kVertex, {}, {}, {}};
    const Point2 &a = V[i], &b = V[(i + 1) % n];
    if (orient(a, b, f) == 0 && in_box(a, b, f)) return {Oracle::kOk, f, geometry::perp(b - a), 0};
  }
  bool crosses = false;
  for (std::size_t i = 0; i < n; ++i) crosses = crosses || segments_meet(P(0, 0), f, V[i], V[(i + 1) % n]);
  if (!crosses) return {Oracle::kInside, {}, {}, {}};
  std::vector<Point2> candidates = V;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 &a = V[i], e = V[(i + 1) % n] - V[i];
    const Q t = geometry::dot(f - a, e) / geometry::norm2(e);
    if (sgn(t) > 0 && t < 1) candidates.push_back(a + t * e);
  }
  Q best = -1;
  for (const Point2& c : candidates)
    if (const Q d = geometry::norm2(f - c); sgn(best) < 0 || d < best) best = d;
  std::vector<Point2> at_best;
  for (const Point2& c : candidates)
    if (geometry::norm2(f - c) == best &&
        std::none_of(at_best.begin(), at_best.end(), [&](const Point2& x) { return x == c; }))
      at_best.push_back(c);
  if (at_best.size() != 1) return {Oracle::kNotUnique, {}, {}, {}};
  return {Oracle::kOk, at_best[0], at_best[0] - f, best};
}

bool positive_multiple(const Point2& x, const Point2& y) {
  return sgn(Q(geometry::cross(x, y))) == 0 && sgn(Q(geometry::dot(x, y))) > 0;
}

// Whether a frame result agrees with the oracle: both have no frame, or the same point and gap and normals that are
// positive multiples of each other.
bool agrees(const geometry::FrameResult& r, const Oracle& o) {
  if (o.status != Oracle::kOk) return r.status != FrameStatus::kOk;
  return r.status == FrameStatus::kOk && r.frame.point == o.point && r.frame.gap_squared == o.gap2 &&
         positive_multiple(r.frame.normal, o.normal);
}

// A random polygon star-shaped about the origin: 5 to 12 integer directions in strictly increasing angle, turning by
// less than pi each time, scaled by 1/2 to 2; retried until check_polygon accepts it (no collinear vertices).
std::vector<Point2> random_star(std::mt19937_64& rng) {
  std::uniform_int_distribution<long> coord(-6, 6), radius(1, 4), count(5, 12);
  for (;;) {
    std::vector<Point2> d;
    const long m = count(rng);
    while (static_cast<long>(d.size()) < m) {
      const Point2 v{Q(coord(rng)), Q(coord(rng))};
      if (sgn(geometry::norm2(v)) == 0) continue;
      if (std::none_of(d.begin(), d.end(), [&](const Point2& u) { return positive_multiple(u, v); })) d.push_back(v);
    }
    // Sort by angle: exact half-plane then cross product.
    auto half = [](const Point2& v) { return sgn(v.y) < 0 || (sgn(v.y) == 0 && sgn(v.x) < 0); };
    std::sort(d.begin(), d.end(), [&](const Point2& a, const Point2& b) {
      return half(a) != half(b) ? !half(a) : sgn(Q(geometry::cross(a, b))) > 0;
    });
    bool turns = true;
    for (std::size_t i = 0; i < d.size(); ++i)
      turns = turns && sgn(Q(geometry::cross(d[i], d[(i + 1) % d.size()]))) > 0;
    if (!turns) continue;
    std::vector<Point2> V;
    for (const Point2& v : d) V.push_back(Q(Q(radius(rng)) / 2) * v);
    if (geometry::check_polygon(V).defect == geometry::PolygonDefect::kNone) return V;
  }
}

constexpr int kRandomFixels = 12;

// Fixels to try on V: a point inside each edge, the points where an edge's line meets another edge's segment
// (issue 29's trap), and random points around the polygon.
std::vector<Point2> trial_fixels(const std::vector<Point2>& V, std::mt19937_64& rng) {
  const std::size_t n = V.size();
  std::vector<Point2> out;
  std::uniform_int_distribution<long> t(1, 4), coord(-30, 30);
  for (std::size_t i = 0; i < n; ++i) out.push_back(V[i] + Q(t(rng), 5) * (V[(i + 1) % n] - V[i]));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const Point2 &a = V[i], e = V[(i + 1) % n] - V[i], &c = V[j], g = V[(j + 1) % n] - V[j];
      const Q den = geometry::cross(e, g);
      if (j == i || sgn(den) == 0) continue;
      const Q s = geometry::cross(a - c, e) / -den;  // c + s g on the line of edge i: cross(c + s g - a, e) = 0
      if (sgn(s) > 0 && s < 1) out.push_back(c + s * g);
    }
  for (int k = 0; k < kRandomFixels; ++k) out.push_back(Q(1, 4) * Point2{Q(coord(rng)), Q(coord(rng))});
  return out;
}

std::string text(const Q& q) { return "\"" + exact::to_string(q) + "\""; }
std::string text(const Point2& p) { return "[" + text(p.x) + "," + text(p.y) + "]"; }

std::set<std::string> mode_set(const geometry::PlanarScene& scene) {
  std::set<std::string> out;
  for (const auto& m : contact_modes(scene).tree.modes) out.insert(m.text());
  return out;
}

TEST(FrameCheck, RandomStarsAgainstTheOracle) {
  std::mt19937_64 rng(29);
  int polygons = 0, fixels = 0, traps = 0, solver_wrong = 0, checker_wrong = 0, mode_lists_wrong = 0, scenes = 0;
  for (; polygons < 48; ++polygons) {
    const std::vector<Point2> V = random_star(rng);
    const Shape shape = geometry::PolygonShape{V};
    std::vector<Point2> touching;
    const std::vector<Point2> trials = trial_fixels(V, rng);
    traps += static_cast<int>(trials.size() - V.size()) - kRandomFixels;
    for (std::size_t k = 0; k < trials.size(); ++k) {
      const Point2& f = trials[k];
      const Oracle o = oracle(V, f);
      ++fixels;
      solver_wrong += !agrees(geometry::frame_from_position(shape, f), o);
      checker_wrong += !agrees(checker::frame_check::checked_frame(shape, at(f)), o);
      if (o.status == Oracle::kOk && sgn(o.gap2) == 0) touching.push_back(f);
    }
    // `modes` on three touching fixels, the last ones found (the traps come after the edge points), against the
    // modes of the oracle's frames.
    if (touching.size() < 3) continue;
    std::ostringstream s;
    s << R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[)";
    for (std::size_t i = 0; i < V.size(); ++i) s << (i ? "," : "") << text(V[i]);
    s << R"(]}},"mu_s":"1/3","fixels":[)";
    for (std::size_t i = touching.size() - 3; i < touching.size(); ++i)
      s << (i + 3 == touching.size() ? "" : ",") << R"({"position":)" << text(touching[i]) << "}";
    s << "]}";
    const std::string scene_text = s.str();
    const exact::JsonInput root = exact::JsonInput::parse(scene_text, "star");
    const geometry::PlanarScene solved = geometry::read_planar_scene(root);
    geometry::PlanarScene truth{geometry::read_planar_scene_input(root).workpiece, {}};
    for (std::size_t i = touching.size() - 3; i < touching.size(); ++i) {
      const Oracle o = oracle(V, touching[i]);
      truth.fixels.push_back({{o.point, o.normal, o.gap2}, Q(1, 3), Q(1, 3), touching[i]});
    }
    ++scenes;
    mode_lists_wrong += mode_set(solved) != mode_set(truth);
    // The checker accepts the modes certificate of the solved scene.
    const ContactModes m = contact_modes(solved);
    EXPECT_TRUE(
        checker::check_modes_certificate(exact::JsonInput::parse(modes_certificate(scene_text, m), "cert")).valid);
  }
  EXPECT_GE(scenes, 39);
  EXPECT_GE(traps, 100);
  EXPECT_EQ(solver_wrong, 0) << "of " << fixels << " fixels";
  EXPECT_EQ(checker_wrong, 0) << "of " << fixels << " fixels";
  EXPECT_EQ(mode_lists_wrong, 0) << "of " << scenes << " scenes";
}

}  // namespace
}  // namespace contactcert::solvers
