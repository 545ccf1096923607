#include "geometry/simple_polygon.h"

#include <algorithm>
#include <set>

namespace contactcert::geometry {
namespace {

bool lex_less(const Point2& a, const Point2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

/// Closed segments ab and cd share a point.
bool meet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

/// Edge i with its endpoints in sweep order (lexicographic: x, then y).
struct Edge {
  Point2 left, right;
};

/// The height of edge e on the vertical line x (left.x <= x <= right.x); a vertical edge's is its lower end.
Q height(const Edge& e, const Q& x) {
  if (e.left.x == e.right.x) return e.left.y;
  return e.left.y + (e.right.y - e.left.y) * (x - e.left.x) / (e.right.x - e.left.x);
}

}  // namespace

int orient(const Point2& a, const Point2& b, const Point2& c) { return sgn(Q(cross(b - a, c - a))); }

bool on_segment(const Point2& a, const Point2& b, const Point2& p) {
  return orient(a, b, p) == 0 && sgn(Q(dot(p - a, p - b))) <= 0;
}

std::optional<std::size_t> crossing_edge(const std::vector<Point2>& V) {
  const std::size_t n = V.size();
  std::vector<Edge> E(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 &a = V[i], &b = V[(i + 1) % n];
    E[i] = lex_less(a, b) ? Edge{a, b} : Edge{b, a};
  }
  const auto neighbours = [n](std::size_t i, std::size_t j) { return (i + 1) % n == j || (j + 1) % n == i; };
  // Sweep order of two edges alive at once: by height on the line through the later left end; at equal
  // height (they meet there) by slope, a vertical edge steepest. The order of edges that do not cross is the
  // same on every common vertical line, so it is consistent until the first crossing, which is reported first.
  const auto below = [&E](std::size_t i, std::size_t j) {
    if (i == j) return false;
    const Edge &a = E[i], &b = E[j];
    const Q& x = std::max(a.left.x, b.left.x);
    const int s = sgn(Q(height(a, x) - height(b, x)));
    if (s != 0) return s < 0;
    return sgn(Q(cross(a.right - a.left, b.right - b.left))) > 0;  // b turns left of a: b is steeper
  };
  std::set<std::size_t, decltype(below)> alive(below);
  // Events: each edge enters at its left end and leaves at its right end; at one point, entries come first, so
  // edges that only touch there are compared.
  struct Event {
    Point2 p;
    bool enter;
    std::size_t edge;
  };
  std::vector<Event> events;
  events.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    events.push_back({E[i].left, true, i});
    events.push_back({E[i].right, false, i});
  }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
    if (lex_less(a.p, b.p)) return true;
    if (lex_less(b.p, a.p)) return false;
    return a.enter && !b.enter;
  });
  const auto crossing = [&](std::size_t i, std::size_t j) {
    return !neighbours(i, j) && meet(E[i].left, E[i].right, E[j].left, E[j].right);
  };
  std::vector<std::set<std::size_t, decltype(below)>::iterator> where(n, alive.end());
  for (const Event& e : events) {
    if (e.enter) {
      const auto [it, inserted] = alive.insert(e.edge);
      if (!inserted) return std::min(e.edge, *it);  // collinear and overlapping at the sweep line
      where[e.edge] = it;
      if (it != alive.begin() && crossing(*std::prev(it), e.edge)) return std::min(*std::prev(it), e.edge);
      if (std::next(it) != alive.end() && crossing(*std::next(it), e.edge)) return std::min(*std::next(it), e.edge);
    } else {
      const auto it = where[e.edge];
      if (it != alive.begin() && std::next(it) != alive.end() && crossing(*std::prev(it), *std::next(it)))
        return std::min(*std::prev(it), *std::next(it));
      alive.erase(it);
    }
  }
  return std::nullopt;
}

}  // namespace contactcert::geometry
