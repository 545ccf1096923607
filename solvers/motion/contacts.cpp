#include "solvers/motion/contacts.h"

#include <algorithm>

#include "exact/enclose.h"
#include "exact/fraction_free.h"
#include "solvers/motion/first_root.h"
#include "solvers/motion/unreduced_point.h"

namespace contactcert::solvers::motion {
namespace {

using exact::sign;

template <class T>
Vec2<T> from_point(const Point2& p) {
  return {from_q<T>(p.x), from_q<T>(p.y)};
}

/// The sign of (b - a) x (p - a): unreduced on the exact paths, with the float sign tolerance on the float path.
template <class T>
int orientation(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& p) {
  const auto u = unreduced(a);
  return sign(cross2(unreduced(b) - u, unreduced(p) - u));
}

/// Whether x lies outside the closed interval between u and v (comparisons only).
bool outside(const Q& x, const Q& u, const Q& v) { return (x < u && x < v) || (x > u && x > v); }

/// The enclosures of v's points on the exact paths; none for double.
template <class T>
std::vector<Vec2<exact::Interval>> enclosures(const std::vector<Vec2<T>>& v) {
  std::vector<Vec2<exact::Interval>> out;
  if constexpr (std::is_same_v<T, Q>)
    for (const Vec2<Q>& x : v) out.push_back(enclose(x));
  return out;
}

/// A polygon's vertices and, on the exact paths, their interval enclosures (exact/interval_number.h), from which
/// most sign tests are taken without rationals.
template <class T>
struct Polygon {
  const std::vector<Vec2<T>>& v;
  const std::vector<Vec2<exact::Interval>>& in;
};

/// Intervals whose operations take the rounding mode as set upward (CGAL::Interval_nt<false>): a filter of several
/// operations runs under one CGAL::Protect_FPU_rounding (Upward below) instead of exact::Interval's setting and
/// restoring the mode at every operation; the enclosures are the same.
using Bare = CGAL::Interval_nt<false>;
using Upward = CGAL::Protect_FPU_rounding<true>;
Bare bare(const exact::Interval& x) { return Bare(x.inf(), x.sup()); }
Vec2<Bare> bare(const Vec2<exact::Interval>& p) { return {bare(p.x), bare(p.y)}; }

/// The sign of (b - a) x (p - a) when the enclosures prove it, else 0 (a filter: 0 decides nothing).
int proven_side(const Vec2<exact::Interval>& a, const Vec2<exact::Interval>& b, const Vec2<exact::Interval>& p) {
  const Upward upward;
  const Bare t = cross2(bare(b) - bare(a), bare(p) - bare(a));
  return t.inf() > 0 ? 1 : t.sup() < 0 ? -1 : 0;
}

/// True if the enclosures prove x outside the closed interval between u and v.
bool outside(const exact::Interval& x, const exact::Interval& u, const exact::Interval& v) {
  return x.sup() < std::min(u.inf(), v.inf()) || x.inf() > std::max(u.sup(), v.sup());
}

/// Where vertex k of P lies against the edge j of S (a -> b): 1 strictly inside it, 0 at an end, -1 off it (or off
/// its line). The exact paths first reject a point that the enclosures prove outside the segment's bounding box or
/// off its line, then one outside the box by comparisons, which take no gcd (most pairs of a pose are far apart),
/// and take the line and segment tests left in unreduced fractions; the float path keeps its sign tolerance.
template <class T>
int on_segment(const Polygon<T>& P, std::size_t k, const Polygon<T>& S, std::size_t j) {
  const std::size_t j1 = (j + 1) % S.v.size();
  const Vec2<T>&p = P.v[k], &a = S.v[j], &b = S.v[j1];
  if constexpr (std::is_same_v<T, Q>) {
    const Vec2<exact::Interval>&pi = P.in[k], &ai = S.in[j], &bi = S.in[j1];
    if (outside(pi.x, ai.x, bi.x) || outside(pi.y, ai.y, bi.y)) return -1;
    if (proven_side(ai, bi, pi) != 0) return -1;
    if (outside(p.x, a.x, b.x) || outside(p.y, a.y, b.y)) return -1;
  }
  const auto u = unreduced(a);
  const auto e = unreduced(b) - u, w = unreduced(p) - u;
  if (sign(cross2(e, w)) != 0) return -1;
  const auto s = dot2(w, e);
  const int lo = sign(s), hi = sign(dot2(e, e) - s);
  if (lo < 0 || hi < 0) return -1;
  return lo > 0 && hi > 0 ? 1 : 0;
}

/// The sign of e x (q - a) for x's edge i (a -> a + e) and vertex k of y: from the enclosures when they prove it (exact
/// paths), else from the numbers.
template <class T>
int side(const Polygon<T>& x, std::size_t i, const Polygon<T>& y, std::size_t k) {
  const std::size_t j = (i + 1) % x.v.size();
  if constexpr (std::is_same_v<T, Q>) {
    if (const int proven = proven_side(x.in[i], x.in[j], y.in[k]); proven != 0) return proven;
  }
  return orientation(x.v[i], x.v[j], y.v[k]);
}

/// True if no vertex of `other` is strictly on the inner (left) side of x's edge i.
template <class T>
bool separates(const Polygon<T>& x, std::size_t i, const Polygon<T>& other) {
  for (std::size_t k = 0; k < other.v.size(); ++k)
    if (side(x, i, other, k) > 0) return false;
  return true;
}

/// True if the interiors of the bounding boxes of x and y are disjoint (comparisons only): then so are the shapes';
/// with `touching` false, only if the closed boxes are (then the shapes cannot touch either).
bool boxes_apart(const std::vector<Vec2<Q>>& x, const std::vector<Vec2<Q>>& y, bool touching = true) {
  const auto range = [](const std::vector<Vec2<Q>>& v, Q Vec2<Q>::*c) {
    const auto [lo, hi] =
        std::minmax_element(v.begin(), v.end(), [c](const auto& a, const auto& b) { return a.*c < b.*c; });
    return std::pair<const Q&, const Q&>{(*lo).*c, (*hi).*c};
  };
  for (Q Vec2<Q>::*c : {&Vec2<Q>::x, &Vec2<Q>::y}) {
    const auto [xlo, xhi] = range(x, c);
    const auto [ylo, yhi] = range(y, c);
    if (xhi < ylo || yhi < xlo || (touching && (xhi == ylo || yhi == xlo))) return true;
  }
  return false;
}

template <class T>
bool convex_overlap(const Polygon<T>& x, const Polygon<T>& y) {
  if constexpr (std::is_same_v<T, Q>)
    if (boxes_apart(x.v, y.v)) return false;  // the exact paths' quick test; the float path keeps its tolerance
  for (std::size_t i = 0; i < x.v.size(); ++i)
    if (separates(x, i, y)) return false;
  for (std::size_t i = 0; i < y.v.size(); ++i)
    if (separates(y, i, x)) return false;
  return true;
}

std::string edge_name(const std::string& shape, std::size_t i) { return shape + " edge " + std::to_string(i); }
std::string vertex_name(const std::string& shape, std::size_t i) { return shape + " vertex " + std::to_string(i); }

}  // namespace

Vec2<exact::Interval> enclose(const Vec2<Q>& p) { return {exact::enclose(p.x), exact::enclose(p.y)}; }

template <class T>
SceneGeometry<T> scene_geometry(const MotionScene& scene) {
  SceneGeometry<T> g;
  for (const MovingBody& b : scene.bodies) {
    std::vector<Vec2<T>> v;
    for (const Point2& p : std::get<geometry::PolygonShape>(b.workpiece.shape).vertices) v.push_back(from_point<T>(p));
    g.bodies.push_back(v);
    g.coms.push_back(from_point<T>(b.workpiece.com));
    g.weights.push_back(from_point<T>(b.weight));
    g.body_mu.push_back(from_q<T>(b.mu));
    g.body_names.push_back(b.name);
  }
  for (std::size_t k = 0; k < scene.obstacles.size(); ++k) {
    const Obstacle& o = scene.obstacles[k];
    std::vector<Vec2<T>> v;
    for (const Point2& p : o.vertices) v.push_back(from_point<T>(p));
    g.obstacles.push_back(v);
    g.obstacles_enclosed.push_back(enclosures(v));
    g.obstacle_mu.push_back(from_q<T>(o.mu));
    g.obstacle_names.push_back(o.name.empty() ? "obstacle " + std::to_string(k) : o.name);
  }
  for (std::size_t k = 0; k < scene.fingers.size(); ++k) {
    g.finger_mu.push_back(from_q<T>(scene.fingers[k].mu));
    g.finger_names.push_back("finger " + (scene.fingers[k].name.empty() ? std::to_string(k) : scene.fingers[k].name));
  }
  return g;
}

namespace {

/// The contacts of body `which` (vertices `body`, world) with obstacle o, appended to out (docs/motion.md, step 1).
template <class T>
void obstacle_contacts(const SceneGeometry<T>& g, int which, const Polygon<T>& B, std::size_t o, ContactSet<T>& out) {
  const std::string& name = g.body_names[static_cast<std::size_t>(which)];
  const std::vector<Vec2<T>>&ob = g.obstacles[o], &body = B.v;
  const Polygon<T> O{ob, g.obstacles_enclosed[o]};
  const std::size_t nb = body.size();
  for (std::size_t i = 0; i < nb; ++i)
    for (std::size_t k = 0; k < ob.size(); ++k) {
      const int where = on_segment(B, i, O, k);
      if (where == 0 && out.unsupported.empty())
        out.unsupported =
            name + " vertex " + std::to_string(i) + " on " + g.obstacle_names[o] + " vertex (normal not determined)";
      if (where != 1) continue;
      const Vec2<T> e = ob[(k + 1) % ob.size()] - ob[k];
      // The obstacle edge's outward normal (e turned by -90 degrees) points into the body.
      out.contacts.push_back({ContactKind::kBodyVertex, int(i), int(o), int(k), which, body[i], Vec2<T>{e.y, -e.x},
                              g.obstacle_mu[o], vertex_name(name, i) + " on " + edge_name(g.obstacle_names[o], k)});
    }
  for (std::size_t k = 0; k < ob.size(); ++k)
    for (std::size_t i = 0; i < nb; ++i) {
      if (on_segment(O, k, B, i) != 1) continue;
      const Vec2<T> e = body[(i + 1) % nb] - body[i];
      out.contacts.push_back({ContactKind::kObstacleVertex, int(i), int(o), int(k), which, ob[k], perp2(e),
                              g.obstacle_mu[o], vertex_name(g.obstacle_names[o], k) + " on " + edge_name(name, i)});
    }
}

/// The vertices of body a on the edges of body b (the force acts on a; mu is b's edge friction), appended to out.
template <class T>
void body_contacts(const SceneGeometry<T>& g, int a, const Polygon<T>& PA, int b, const Polygon<T>& PB,
                   ContactSet<T>& out) {
  const std::string &na = g.body_names[static_cast<std::size_t>(a)], &nb = g.body_names[static_cast<std::size_t>(b)];
  const std::vector<Vec2<T>>&A = PA.v, &B = PB.v;
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t k = 0; k < B.size(); ++k) {
      const int where = on_segment(PA, i, PB, k);
      if (where == 0 && out.unsupported.empty())
        out.unsupported = na + " vertex " + std::to_string(i) + " on " + nb + " vertex (normal not determined)";
      if (where != 1) continue;
      const Vec2<T> e = B[(k + 1) % B.size()] - B[k];
      out.contacts.push_back({ContactKind::kBodyBody, int(i), b, int(k), a, A[i], Vec2<T>{e.y, -e.x},
                              g.body_mu[static_cast<std::size_t>(b)], vertex_name(na, i) + " on " + edge_name(nb, k)});
    }
}

}  // namespace

template <class T>
WorldBodies<T> world_bodies(const SceneGeometry<T>& g, const Poses<T>& poses) {
  WorldBodies<T> world;
  for (std::size_t b = 0; b < g.bodies.size(); ++b) {
    world.vertices.push_back(geometry::apply_all(poses[b], g.bodies[b]));
    world.enclosed.push_back(enclosures(world.vertices.back()));
  }
  return world;
}

/// Body b of `world` as a polygon.
template <class T>
Polygon<T> body_polygon(const WorldBodies<T>& world, std::size_t b) {
  return {world.vertices[b], world.enclosed[b]};
}

template <class T>
ContactSet<T> find_contacts(const SceneGeometry<T>& g, const WorldBodies<T>& world, const std::vector<Vec2<T>>& tips) {
  ContactSet<T> out;
  const std::size_t n = world.vertices.size();
  for (std::size_t b = 0; b < n; ++b) {
    const Polygon<T> B = body_polygon(world, b);
    for (std::size_t o = 0; o < g.obstacles.size(); ++o) obstacle_contacts(g, int(b), B, o, out);
    for (std::size_t b2 = b + 1; b2 < n; ++b2) {
      if constexpr (std::is_same_v<T, Q>)
        if (boxes_apart(world.vertices[b], world.vertices[b2], false)) continue;
      const Polygon<T> B2 = body_polygon(world, b2);
      body_contacts(g, int(b), B, int(b2), B2, out);
      body_contacts(g, int(b2), B2, int(b), B, out);
    }
  }
  const std::vector<Vec2<exact::Interval>> tips_in = enclosures(tips);
  const Polygon<T> fingers{tips, tips_in};
  for (std::size_t f = 0; f < tips.size(); ++f)
    for (std::size_t b = 0; b < n; ++b) {
      const Polygon<T> B = body_polygon(world, b);
      const std::vector<Vec2<T>>& body = B.v;
      const std::size_t nb = body.size();
      for (std::size_t i = 0; i < nb; ++i) {
        const int where = on_segment(fingers, f, B, i);
        if (where == 0 && out.unsupported.empty())
          out.unsupported = g.finger_names[f] + " on a " + g.body_names[b] + " vertex (normal not determined)";
        if (where != 1) continue;
        const Vec2<T> e = body[(i + 1) % nb] - body[i];
        out.contacts.push_back({ContactKind::kFinger, int(i), int(f), -1, int(b), tips[f], perp2(e), g.finger_mu[f],
                                g.finger_names[f] + " on " + edge_name(g.body_names[b], i)});
      }
    }
  return out;
}

template <class T>
std::string overlap(const SceneGeometry<T>& g, const Poses<T>& poses, const std::vector<Vec2<T>>& tips) {
  return overlap(g, world_bodies(g, poses), tips);
}

template <class T>
std::string overlap(const SceneGeometry<T>& g, const WorldBodies<T>& world, const std::vector<Vec2<T>>& tips) {
  const std::vector<Vec2<exact::Interval>> tips_in = enclosures(tips);
  const Polygon<T> fingers{tips, tips_in};
  const std::size_t n = world.vertices.size();
  for (std::size_t b = 0; b < n; ++b) {
    const Polygon<T> body = body_polygon(world, b);
    for (std::size_t o = 0; o < g.obstacles.size(); ++o)
      if (convex_overlap(body, Polygon<T>{g.obstacles[o], g.obstacles_enclosed[o]}))
        return "the " + g.body_names[b] + " overlaps " + g.obstacle_names[o];
    for (std::size_t b2 = b + 1; b2 < n; ++b2)
      if (convex_overlap(body, body_polygon(world, b2)))
        return "the " + g.body_names[b] + " overlaps the " + g.body_names[b2];
    for (std::size_t f = 0; f < tips.size(); ++f) {
      bool inside = true;
      for (std::size_t i = 0; i < body.v.size() && inside; ++i) inside = side(body, i, fingers, f) > 0;
      if (inside) return g.finger_names[f] + " is inside the " + g.body_names[b];
    }
  }
  return "";
}

namespace {

using exact::Interval;

/// The gap (times 1 + u^2) of a point p (w = p - c) against the segment a -> a + e (K = (c - a) x e) over a step
/// that turns a body by u = k tau about c, or translates it by v tau: p is the body's own vertex (body_point) or a
/// point moving with velocity pv in the world against the body's edge. In powers of tau, into g (its room reused from
/// pair to pair); over T or an enclosure.
template <class U>
void gap_polynomial(bool turning, bool body_point, const Vec2<U>& p, const Vec2<U>& w, const Vec2<U>& pv,
                    const Vec2<U>& v, const Vec2<U>& a, const Vec2<U>& e, const U& K, const U& k, std::vector<U>& g) {
  if (!turning) {
    const Vec2<U> rel = body_point ? v : pv - v;
    g = {cross2(p - a, e), cross2(rel, e)};
    return;
  }
  const U C = cross2(w, e), D = dot2(w, e);
  if (body_point) {
    g = {K + C, U(-2) * D * k, (K - C) * k * k};
    return;
  }
  // The point relative to the body: c + R(-u)(p + tau pv - c); eq. for a fixed point when pv = 0.
  const U Cv = cross2(pv, e), Dv = dot2(pv, e);
  g = {K + C, Cv + U(2) * D * k, (K - C) * k * k + U(2) * Dv * k, -Cv * k * k};
}

/// True if the enclosure g of a pair's gap polynomial proves the exact path's verdict that the pair closes no gap
/// in (0, H]: g_0 <= 0 (touching or beyond the edge's line at the start: skipped), or g_0 > 0 and positive_on's
/// bound g_0 + sum min(0, g_i) H^i > 0 (first_root.cpp); the exact bound lies in the enclosure computed here.
bool closes_no_gap(const std::vector<Bare>& g, const Bare& H) {
  if (g[0].sup() <= 0) return true;
  if (g[0].inf() <= 0) return false;
  Bare bound = g[0], power(1);
  for (std::size_t i = 1; i < g.size(); ++i) {
    power *= H;
    bound += Bare(std::min(g[i].inf(), 0.0), std::min(g[i].sup(), 0.0)) * power;
  }
  return bound.inf() > 0;
}

/// True if the enclosures prove the box [p - r, p + r] apart from the bounding box of the segment a -> b (rounding
/// upward, as Bare's operations take it).
bool proven_apart(const Vec2<Bare>& p, const Bare& r, const Vec2<Bare>& a, const Vec2<Bare>& b) {
  const Bare spread(-r.sup(), r.sup());
  const Bare x = p.x + spread, y = p.y + spread;
  return x.sup() < std::min(a.x.inf(), b.x.inf()) || x.inf() > std::max(a.x.sup(), b.x.sup()) ||
         y.sup() < std::min(a.y.inf(), b.y.inf()) || y.inf() > std::max(a.y.sup(), b.y.sup());
}

/// The first closing contact of body `which` (world vertices `body`, twist (v, omega)) with the obstacles and the
/// free fingers before `limit`: updates best and limit.
template <class T>
void closing_of_body(const SceneGeometry<T>& g, std::size_t which, const Polygon<T>& world_body,
                     const std::vector<Vec2<T>>& tips, const Vec2<T>& v, const T& omega,
                     const std::vector<std::optional<Vec2<T>>>& free_velocity, const T& H,
                     std::optional<ClosingContact<T>>& best, T& limit) {
  constexpr bool exact_path = std::is_same_v<T, Q>;
  const std::string& name = g.body_names[which];
  const std::vector<Vec2<T>>& body = world_body.v;
  const std::size_t nb = body.size();
  const bool turning = sign(omega) != 0;
  const T k = omega / T(2);  // u = k tau
  const Vec2<T> c = turning ? Vec2<T>{-v.y / omega, v.x / omega} : Vec2<T>{T(0), T(0)};
  // Each point p with w = p - c, each segment a -> a + e with K = (c - a) x e: computed once per step when a pair
  // needs them, shared by every pair that uses them. On the exact paths also boxes, [lo, hi]: the segment's
  // bounding box, and the box that a point not moving on its own stays in relative to the body (a body vertex in
  // the world, an obstacle vertex in the body's frame) over the step: each coordinate moves by at most |v|_inf H (a
  // translation) or |p - c|_2 |theta| <= 2 |p - c|_inf |omega| H (turning: the Cayley angle |theta| = 2 |atan(omega
  // tau / 2)| <= |omega| tau). A pair whose boxes are apart cannot meet in the step: it is skipped by comparisons.
  // Before all that, the exact paths take the same boxes and then each pair's gap polynomial over interval enclosures
  // of the data (exact/interval_number.h): most pairs are proved apart or to close no gap there (closes_no_gap),
  // without rationals; the enclosures of the boxes hold the exact boxes, so they skip no pair that these would not.
  const auto magnitude = [](const T& x) { return sign(x) < 0 ? T(-x) : x; };
  const auto larger = [](const T& x, const T& y) { return x < y ? y : x; };
  const T reach = turning ? T(2 * magnitude(omega) * H) : T(larger(magnitude(v.x), magnitude(v.y)) * H);
  struct Point {
    Vec2<T> p, w, lo, hi;
    bool boxed = false;
  };
  struct Segment {
    Vec2<T> a, e, lo, hi;
    T K;
  };
  const auto point = [&](const Vec2<T>& p, bool moves_on_its_own) {
    Point P{p, turning ? Vec2<T>(p - c) : p, p, p};
    if constexpr (exact_path) {
      if (moves_on_its_own) return P;
      const T r = turning ? T(reach * larger(magnitude(P.w.x), magnitude(P.w.y))) : reach;
      P = {p, P.w, {p.x - r, p.y - r}, {p.x + r, p.y + r}, true};
    }
    return P;
  };
  const auto segment = [&](const std::vector<Vec2<T>>& x, std::size_t j) {
    const Vec2<T>&a = x[j], &b = x[(j + 1) % x.size()];
    const Vec2<T> e = b - a;
    return Segment{a,
                   e,
                   {std::min(a.x, b.x), std::min(a.y, b.y)},
                   {std::max(a.x, b.x), std::max(a.y, b.y)},
                   turning ? T(cross2(c - a, e)) : T(0)};
  };
  // A shape's points and segments, each made on first use, and the velocity of its points in the world (a free
  // finger's; zero for a body or an obstacle); on the exact paths with the enclosures of its vertices and velocity.
  struct Shape {
    const std::vector<Vec2<T>>& x;
    Vec2<T> velocity;
    bool moves_on_its_own = false;
    std::vector<std::optional<Point>> points{};  // sized on first use
    std::vector<std::optional<Segment>> segments{};
    const std::vector<Vec2<Interval>>* enclosed = nullptr;
    Vec2<Interval> velocity_in{Interval(0), Interval(0)};
  };
  const Vec2<T> zero{T(0), T(0)};
  const auto enclosed = [&](Shape&& s, const std::vector<Vec2<Interval>>& points) {
    if constexpr (exact_path) {
      s.enclosed = &points;
      s.velocity_in = enclose(s.velocity);
    }
    return std::move(s);
  };
  [[maybe_unused]] Interval k_in, limit_in, reach_in;
  [[maybe_unused]] Vec2<Interval> c_in{Interval(0), Interval(0)}, v_in;
  if constexpr (exact_path) {
    const Interval omega_in = exact::enclose(omega);
    v_in = enclose(v);
    k_in = omega_in / 2;
    if (turning) c_in = {-v_in.y / omega_in, v_in.x / omega_in};
    limit_in = exact::enclose(limit);
    reach_in =
        (turning ? 2 * CGAL::abs(omega_in) : CGAL::max(CGAL::abs(v_in.x), CGAL::abs(v_in.y))) * exact::enclose(H);
  }
  std::vector<T> poly;
  [[maybe_unused]] std::vector<Bare> g_in;
  // The gap (times 1 + u^2) of point i of X, moving with velocity pv in the world (unless it is the body's own
  // vertex, body_point), against segment j of Y (a body edge when !body_point), in powers of tau.
  const auto consider = [&](Shape& X, std::size_t i, bool body_point, Shape& Y, std::size_t j, const auto& pair_name) {
    const Vec2<T>& pv = X.velocity;
    if constexpr (exact_path) {
      bool touching_or_beyond = false;  // the enclosure of g_0 does not prove it > 0
      {
        const Upward upward;
        const Vec2<Bare> p = bare((*X.enclosed)[i]), a = bare((*Y.enclosed)[j]);
        const Vec2<Bare> b = bare((*Y.enclosed)[(j + 1) % Y.enclosed->size()]), e = b - a, c = bare(c_in);
        const Vec2<Bare> w = turning ? p - c : p;
        if (!X.moves_on_its_own) {
          const Bare reach = bare(reach_in);
          const Bare r = turning ? reach * Bare(std::max(CGAL::abs(w.x).sup(), CGAL::abs(w.y).sup())) : reach;
          if (proven_apart(p, r, a, b)) return;
        }
        const Bare K = turning ? cross2(c - a, e) : Bare(0);
        gap_polynomial<Bare>(turning, body_point, p, w, bare(X.velocity_in), bare(v_in), a, e, K, bare(k_in), g_in);
        if (closes_no_gap(g_in, bare(limit_in))) return;
        touching_or_beyond = g_in[0].inf() <= 0;
      }
      // g_0 = (p - a) x e whatever the motion: a pair touching at the start, which the enclosure cannot prove, is
      // skipped by that sign alone.
      const Vec2<Q>& a0 = Y.x[j];
      if (touching_or_beyond && orientation(a0, Y.x[(j + 1) % Y.x.size()], X.x[i]) >= 0) return;
    }
    X.points.resize(X.x.size());
    Y.segments.resize(Y.x.size());
    if (!X.points[i]) X.points[i] = point(X.x[i], X.moves_on_its_own);
    if (!Y.segments[j]) Y.segments[j] = segment(Y.x, j);
    const Point& P = *X.points[i];
    const Segment& S = *Y.segments[j];
    if (P.boxed && (P.hi.x < S.lo.x || S.hi.x < P.lo.x || P.hi.y < S.lo.y || S.hi.y < P.lo.y)) return;
    const Vec2<T>&p = P.p, &a = S.a, &e = S.e;
    gap_polynomial<T>(turning, body_point, p, P.w, pv, v, a, e, S.K, k, poly);
    if (sign(poly[0]) <= 0) return;  // touching (or beyond the edge's line) at the start
    const auto accept = [&](const T& tau) {
      const Pose<T> m = geometry::twist_step(v, omega, tau);
      Vec2<T> q = body_point ? m.apply(p) : p + tau * pv, a2 = a, e2 = e;
      if (!body_point) {
        a2 = m.apply(a);
        e2 = m.rotate(e);
      }
      const T s = dot2(q - a2, e2);
      return sign(s) >= 0 && sign(T(dot2(e2, e2) - s)) >= 0;
    };
    const auto root = first_gap_root<T>(poly, limit, accept);
    if (!root) return;
    if (best && !(root->tau < best->tau)) return;
    best = ClosingContact<T>{root->tau, root->exact, pair_name()};
    limit = root->tau;
    if constexpr (exact_path) limit_in = exact::enclose(limit);
  };
  Shape B = enclosed({body, zero}, world_body.in);
  for (std::size_t o = 0; o < g.obstacles.size(); ++o) {
    const std::vector<Vec2<T>>& ob = g.obstacles[o];
    Shape O = enclosed({ob, zero}, g.obstacles_enclosed[o]);
    for (std::size_t i = 0; i < nb; ++i)
      for (std::size_t j = 0; j < ob.size(); ++j)
        consider(B, i, true, O, j, [&] { return vertex_name(name, i) + " on " + edge_name(g.obstacle_names[o], j); });
    for (std::size_t j = 0; j < ob.size(); ++j)
      for (std::size_t i = 0; i < nb; ++i)
        consider(O, j, false, B, i, [&] { return vertex_name(g.obstacle_names[o], j) + " on " + edge_name(name, i); });
  }
  for (std::size_t f = 0; f < tips.size(); ++f) {
    if (!free_velocity[f]) continue;
    const std::vector<Vec2<T>> at{tips[f]};
    const std::vector<Vec2<Interval>> at_in = enclosures(at);
    Shape tip = enclosed({at, *free_velocity[f], true}, at_in);
    for (std::size_t i = 0; i < nb; ++i)
      consider(tip, 0, false, B, i, [&] { return g.finger_names[f] + " on " + edge_name(name, i); });
  }
}

/// A body point's path over a step as N(tau) / D(tau): N with vector coefficients (low to high), D = 1 + k^2 tau^2
/// (turning, k = omega / 2) or 1. p -> c + R(u)(p - c) with R(u)'s numerator (1 - u^2) I + 2u J, u = k tau
/// (rigid_motion.h): N = p + 2k J(p - c) tau + k^2 (c - (p - c)) tau^2; a translation: N = p + v tau. An edge
/// vector e turns only: N = e + 2k J e tau - k^2 e tau^2.
template <class T>
struct Path {
  std::vector<Vec2<T>> N;
  std::vector<T> D;
};

template <class T>
Path<T> point_path(const Vec2<T>& p, const Twist<T>& tw, bool vector) {
  if (sign(tw.omega) == 0) return {vector ? std::vector<Vec2<T>>{p} : std::vector<Vec2<T>>{p, tw.v}, {T(1)}};
  const T k = tw.omega / T(2);
  const Vec2<T> c{-tw.v.y / tw.omega, tw.v.x / tw.omega};
  const Vec2<T> w = vector ? p : Vec2<T>(p - c);
  const Vec2<T> top = vector ? T(-1) * p : Vec2<T>(c - w);
  return {{p, T(T(2) * k) * perp2(w), T(k * k) * top}, {T(1), T(0), T(k * k)}};
}

/// a(tau) b(tau), a scalar and b a vector polynomial.
template <class T>
std::vector<Vec2<T>> times(const std::vector<T>& a, const std::vector<Vec2<T>>& b) {
  std::vector<Vec2<T>> out(a.size() + b.size() - 1, Vec2<T>{T(0), T(0)});
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) out[i + j] = out[i + j] + a[i] * b[j];
  return out;
}

/// The gap of vertex p of a body with twist ta against the edge a -> a + e of a body with twist tb, times the
/// positive D_p D_b^2: cross(N_p D_b - N_a D_p, N_e) (degree <= 6; at 0, cross(p - a, e) > 0 outside the edge).
template <class T>
std::vector<T> pair_gap(const Vec2<T>& p, const Twist<T>& ta, const Vec2<T>& a, const Vec2<T>& e, const Twist<T>& tb) {
  const Path<T> P = point_path(p, ta, false), A = point_path(a, tb, false), E = point_path(e, tb, true);
  std::vector<Vec2<T>> rel = times(A.D, P.N);
  const std::vector<Vec2<T>> sub = times(P.D, A.N);
  if (rel.size() < sub.size()) rel.resize(sub.size(), Vec2<T>{T(0), T(0)});
  for (std::size_t i = 0; i < sub.size(); ++i) rel[i] = rel[i] - sub[i];
  std::vector<T> out(rel.size() + E.N.size() - 1, T(0));
  for (std::size_t i = 0; i < rel.size(); ++i)
    for (std::size_t j = 0; j < E.N.size(); ++j) out[i + j] += cross2(rel[i], E.N[j]);
  return out;
}

/// The world box of a body's vertices over the step (exact paths): each coordinate moves by at most |v|_inf H (a
/// translation) or |p - c|_2 |theta| <= 2 |p - c|_inf |omega| H (turning), as in closing_of_body.
std::pair<Vec2<Q>, Vec2<Q>> swept_box(const std::vector<Vec2<Q>>& body, const Twist<Q>& tw, const Q& H) {
  Vec2<Q> lo = body[0], hi = body[0];
  Q reach(0);
  const bool turning = sgn(tw.omega) != 0;
  const Vec2<Q> c = turning ? Vec2<Q>{-tw.v.y / tw.omega, tw.v.x / tw.omega} : Vec2<Q>{Q(0), Q(0)};
  for (const Vec2<Q>& p : body) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    const Q r = turning ? Q(2 * abs(tw.omega) * H * std::max(abs(p.x - c.x), abs(p.y - c.y)))
                        : Q(std::max(abs(tw.v.x), abs(tw.v.y)) * H);
    reach = std::max(reach, r);
  }
  return {{lo.x - reach, lo.y - reach}, {hi.x + reach, hi.y + reach}};
}

/// The first closing contact of a vertex of body a on an edge of body b before `limit`: updates best and limit.
template <class T>
void closing_of_pair(const SceneGeometry<T>& g, std::size_t a, const std::vector<Vec2<T>>& A, std::size_t b,
                     const std::vector<Vec2<T>>& B, const std::vector<Twist<T>>& twists,
                     std::optional<ClosingContact<T>>& best, T& limit) {
  const Twist<T>&ta = twists[a], &tb = twists[b];
  for (std::size_t i = 0; i < A.size(); ++i)
    for (std::size_t k = 0; k < B.size(); ++k) {
      const Vec2<T>&p = A[i], &q = B[k];
      const Vec2<T> e = B[(k + 1) % B.size()] - q;
      const std::vector<T> poly = pair_gap(p, ta, q, e, tb);
      if (sign(poly[0]) <= 0) continue;  // touching (or beyond the edge's line) at the start
      const auto accept = [&](const T& tau) {
        const Pose<T> ma = geometry::twist_step(ta.v, ta.omega, tau), mb = geometry::twist_step(tb.v, tb.omega, tau);
        const Vec2<T> x = ma.apply(p), a2 = mb.apply(q), e2 = mb.rotate(e);
        const T s = dot2(x - a2, e2);
        return sign(s) >= 0 && sign(T(dot2(e2, e2) - s)) >= 0;
      };
      const auto root = first_gap_root<T>(poly, limit, accept);
      if (!root || (best && !(root->tau < best->tau))) continue;
      best = ClosingContact<T>{root->tau, root->exact,
                               vertex_name(g.body_names[a], i) + " on " + edge_name(g.body_names[b], k)};
      limit = root->tau;
    }
}

}  // namespace

template <class T>
std::optional<ClosingContact<T>> first_closing(const SceneGeometry<T>& g, const WorldBodies<T>& world,
                                               const std::vector<Vec2<T>>& tips, const std::vector<Twist<T>>& twists,
                                               const std::vector<std::optional<Vec2<T>>>& free_velocity, const T& H) {
  std::optional<ClosingContact<T>> best;
  T limit = H;
  const std::vector<std::vector<Vec2<T>>>& v = world.vertices;
  for (std::size_t b = 0; b < v.size(); ++b)
    closing_of_body(g, b, body_polygon(world, b), tips, twists[b].v, twists[b].omega, free_velocity, H, best, limit);
  for (std::size_t a = 0; a < v.size(); ++a)
    for (std::size_t b = a + 1; b < v.size(); ++b) {
      if constexpr (std::is_same_v<T, Q>) {
        const auto [alo, ahi] = swept_box(v[a], twists[a], H);
        const auto [blo, bhi] = swept_box(v[b], twists[b], H);
        if (ahi.x < blo.x || bhi.x < alo.x || ahi.y < blo.y || bhi.y < alo.y) continue;
      }
      closing_of_pair(g, a, v[a], b, v[b], twists, best, limit);
      closing_of_pair(g, b, v[b], a, v[a], twists, best, limit);
    }
  return best;
}

#define CONTACTCERT_MOTION_CONTACTS_INST(T)                                                                      \
  template SceneGeometry<T> scene_geometry<T>(const MotionScene&);                                               \
  template WorldBodies<T> world_bodies<T>(const SceneGeometry<T>&, const Poses<T>&);                             \
  template ContactSet<T> find_contacts<T>(const SceneGeometry<T>&, const WorldBodies<T>&,                        \
                                          const std::vector<Vec2<T>>&);                                          \
  template std::string overlap<T>(const SceneGeometry<T>&, const WorldBodies<T>&, const std::vector<Vec2<T>>&);  \
  template std::string overlap<T>(const SceneGeometry<T>&, const Poses<T>&, const std::vector<Vec2<T>>&);        \
  template std::optional<ClosingContact<T>> first_closing<T>(                                                    \
      const SceneGeometry<T>&, const WorldBodies<T>&, const std::vector<Vec2<T>>&, const std::vector<Twist<T>>&, \
      const std::vector<std::optional<Vec2<T>>>&, const T&);
CONTACTCERT_MOTION_CONTACTS_INST(Q)
CONTACTCERT_MOTION_CONTACTS_INST(double)
#undef CONTACTCERT_MOTION_CONTACTS_INST

}  // namespace contactcert::solvers::motion
