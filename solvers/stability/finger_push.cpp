#include "solvers/stability/finger_push.h"

#include <algorithm>

#include "exact/input_error.h"

namespace contactcert::solvers {

using exact::is_zero;
using exact::sign;
using Index = Eigen::Index;

template <class T>
Vec<T> push_wrench(const geometry::Point2& com, const Vec<T>& p, const Vec<T>& n) {
  const T rx = T(p(0) - from_exact<T>(com.x)), ry = T(p(1) - from_exact<T>(com.y));
  Vec<T> g(3);
  g << n(0), n(1), T(rx * n(1) - ry * n(0));
  return g;
}

template <class T>
std::vector<Vec<T>> cone_rows(const std::vector<const geometry::FaceCone<T>*>& cones) {
  std::vector<Vec<T>> rows;
  for (const auto* c : cones)
    for (const Mat<T>* M : {&c->inequalities, &c->equalities, &c->strict})
      for (Index r = 0; r < M->rows(); ++r) rows.push_back(M->row(r).transpose());
  return rows;
}

namespace {

template <class T>
Vec<T> v2(const T& x, const T& y) {
  Vec<T> v(2);
  v << x, y;
  return v;
}

// Polygon edge e: g(s) = g0 + s g1, breakpoints where a row's sign changes.
template <class T, class Label>
void edge_pieces(const geometry::PlanarScene& scene, const std::function<Label(const Vec<T>&)>& label,
                 const std::vector<Vec<T>>& rows, std::size_t e, std::vector<EdgeInterval<T, Label>>& out) {
  const auto& V = std::get<geometry::PolygonShape>(scene.workpiece.shape).vertices;
  const auto& a = V[e];
  const auto& b = V[(e + 1) % V.size()];
  const Vec<T> pa = v2<T>(from_exact<T>(a.x), from_exact<T>(a.y));
  const Vec<T> d = v2<T>(T(from_exact<T>(b.x) - pa(0)), T(from_exact<T>(b.y) - pa(1)));
  const Vec<T> n = v2<T>(T(-d(1)), d(0));  // left normal of a counter-clockwise edge points inside
  const Vec<T> g0 = push_wrench<T>(scene.workpiece.com, pa, n);
  const Vec<T> g1 = push_wrench<T>(scene.workpiece.com, Vec<T>(pa + d), n) - g0;
  std::vector<T> cuts{T(0), T(1)};
  for (const Vec<T>& f : rows) {
    const T f0 = f.dot(g0), f1 = f.dot(g1);
    if (is_zero(f1)) continue;
    const T s = T(-f0 / f1);
    if (sign(s) > 0 && sign(T(s - 1)) < 0) cuts.push_back(s);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end(), [](const T& x, const T& y) { return is_zero(T(x - y)); }),
             cuts.end());
  auto label_at = [&](const T& s) { return label(Vec<T>(g0 + s * g1)); };
  // Pieces: open gaps (cuts[i], cuts[i+1]) and interior breakpoints; merge equal neighbours.
  std::vector<EdgeInterval<T, Label>> pieces;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (i > 0) pieces.push_back({e, cuts[i], cuts[i], true, true, label_at(cuts[i])});
    pieces.push_back({e, cuts[i], cuts[i + 1], false, false, label_at(T((cuts[i] + cuts[i + 1]) / T(2)))});
  }
  for (const auto& p : pieces) {
    if (!out.empty() && out.back().edge == e && out.back().label == p.label) {
      out.back().to = p.to;
      out.back().to_closed = p.to_closed;
    } else {
      out.push_back(p);
    }
  }
}

// Disk: g(u) = G u for the outward direction u of the push point; a row f changes sign where u is
// orthogonal to w = G^T f.
template <class T, class Label>
void disk_pieces(const geometry::PlanarScene& scene, const std::function<Label(const Vec<T>&)>& label,
                 const std::vector<Vec<T>>& rows, std::vector<ArcInterval<T, Label>>& out) {
  const auto& disk = std::get<geometry::DiskShape>(scene.workpiece.shape);
  const T ax = T(from_exact<T>(disk.center.x) - from_exact<T>(scene.workpiece.com.x));
  const T ay = T(from_exact<T>(disk.center.y) - from_exact<T>(scene.workpiece.com.y));
  Mat<T> G(3, 2);  // push along n = -u at p = c + r u: g = (-u, -(c - com) x u)
  G << T(-1), T(0), T(0), T(-1), ay, T(-ax);
  auto half = [](const Vec<T>& u) { return (sign(u(1)) > 0 || (sign(u(1)) == 0 && sign(u(0)) > 0)) ? 0 : 1; };
  auto before = [&](const Vec<T>& u, const Vec<T>& v) {
    if (half(u) != half(v)) return half(u) < half(v);
    return sign(T(u(0) * v(1) - u(1) * v(0))) > 0;
  };
  std::vector<Vec<T>> cuts;
  for (const Vec<T>& f : rows) {
    const Vec<T> w = G.transpose() * f;
    if (is_zero(w(0)) && is_zero(w(1))) continue;
    cuts.push_back(v2<T>(T(-w(1)), w(0)));
    cuts.push_back(v2<T>(w(1), T(-w(0))));
  }
  std::sort(cuts.begin(), cuts.end(), before);
  cuts.erase(std::unique(cuts.begin(), cuts.end(),
                         [&](const Vec<T>& u, const Vec<T>& v) { return !before(u, v) && !before(v, u); }),
             cuts.end());
  auto label_at = [&](const Vec<T>& u) { return label(Vec<T>(G * u)); };
  if (cuts.empty()) {
    const Vec<T> u = v2<T>(T(1), T(0));
    out.push_back({u, u, false, false, label_at(u)});
    return;
  }
  std::vector<ArcInterval<T, Label>> pieces;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const Vec<T>& u = cuts[i];
    const Vec<T>& v = cuts[(i + 1) % cuts.size()];
    // A direction strictly between u and v (counter-clockwise): u + v when less than pi apart, else u rotated.
    const bool short_gap = sign(T(u(0) * v(1) - u(1) * v(0))) > 0;
    const Vec<T> mid = short_gap ? Vec<T>(u + v) : v2<T>(T(-u(1)), u(0));
    pieces.push_back({u, u, true, true, label_at(u)});
    pieces.push_back({u, v, false, false, label_at(mid)});
  }
  for (const auto& p : pieces) {
    if (!out.empty() && out.back().label == p.label) {
      out.back().to = p.to;
      out.back().to_closed = p.to_closed;
    } else {
      out.push_back(p);
    }
  }
  // One label all round: the whole circle, written as from == to with both ends open.
  if (out.size() == 1) {
    out.front() = {out.front().from, out.front().from, false, false, out.front().label};
    return;
  }
  // The circle closes: merge the last piece into the first when they carry the same label.
  if (out.back().label == out.front().label) {
    out.front().from = out.back().from;
    out.front().from_closed = out.back().from_closed;
    out.pop_back();
  }
}

}  // namespace

template <class T, class Label>
BoundaryPieces<T, Label> boundary_pieces(const geometry::PlanarScene& scene, const std::vector<Vec<T>>& rows,
                                         const std::function<Label(const Vec<T>&)>& label) {
  BoundaryPieces<T, Label> out;
  if (const auto* poly = std::get_if<geometry::PolygonShape>(&scene.workpiece.shape)) {
    for (std::size_t e = 0; e < poly->vertices.size(); ++e) edge_pieces(scene, label, rows, e, out.edges);
  } else {
    disk_pieces(scene, label, rows, out.arcs);
  }
  return out;
}

template <class T>
FingerPushes<T> finger_pushes(const geometry::PlanarScene& scene, const StableRegion<T>& region,
                              const exact::Deadline& deadline) {
  std::vector<const geometry::FaceCone<T>*> cones{&region.weak};
  for (const auto& c : region.cones) cones.push_back(&c);
  std::size_t labelled = 0;
  return boundary_pieces<T, StabilityVerdict>(scene, cone_rows<T>(cones), [&](const Vec<T>& g) {
    if (deadline.expired())
      throw exact::BudgetExceeded("finger pushes: " + deadline.reached_text(),
                                  "the region, then " + std::to_string(labelled) + " boundary pieces labelled");
    ++labelled;
    return region.label(g);
  });
}

#define CONTACTCERT_FINGER_INSTANTIATE(T)                                                                             \
  template std::vector<Vec<T>> cone_rows<T>(const std::vector<const geometry::FaceCone<T>*>&);                        \
  template BoundaryPieces<T, StabilityVerdict> boundary_pieces<T, StabilityVerdict>(                                  \
      const geometry::PlanarScene&, const std::vector<Vec<T>>&,                                                       \
      const std::function<StabilityVerdict(const Vec<T>&)>&);                                                         \
  template BoundaryPieces<T, bool> boundary_pieces<T, bool>(const geometry::PlanarScene&, const std::vector<Vec<T>>&, \
                                                            const std::function<bool(const Vec<T>&)>&);               \
  template FingerPushes<T> finger_pushes<T>(const geometry::PlanarScene&, const StableRegion<T>&,                     \
                                            const exact::Deadline&);                                                  \
  template Vec<T> push_wrench<T>(const geometry::Point2&, const Vec<T>&, const Vec<T>&);
CONTACTCERT_FINGER_INSTANTIATE(double)
CONTACTCERT_FINGER_INSTANTIATE(Q)

}  // namespace contactcert::solvers
