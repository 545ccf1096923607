#include "solvers/design/symmetry.h"

#include <algorithm>
#include <map>
#include <optional>

namespace contactcert::solvers {
namespace {

using exact::Q;
using geometry::Point2;

/// x -> A x with A = [[a, b], [c, d]] (rows).
struct Linear {
  Q a, b, c, d;
  Point2 operator()(const Point2& x) const { return {a * x.x + b * x.y, c * x.x + d * x.y}; }
  bool orthogonal() const { return a * a + c * c == 1 && b * b + d * d == 1 && a * b + c * d == 0; }
  Q det() const { return a * d - b * c; }
};

/// The linear map taking u0 -> v0 and u1 -> v1 (u0, u1 independent).
std::optional<Linear> map_taking(const Point2& u0, const Point2& u1, const Point2& v0, const Point2& v1) {
  const Q det = geometry::cross(u0, u1);
  if (sgn(det) == 0) return std::nullopt;
  // A = [v0 v1] [u0 u1]^-1, [u0 u1]^-1 = [[u1y, -u1x], [-u0y, u0x]] / det.
  return Linear{(v0.x * u1.y - v1.x * u0.y) / det, (-v0.x * u1.x + v1.x * u0.x) / det,
                (v0.y * u1.y - v1.y * u0.y) / det, (-v0.y * u1.x + v1.y * u0.x) / det};
}

struct PointLess {
  bool operator()(const Point2& p, const Point2& q) const { return p.x < q.x || (p.x == q.x && p.y < q.y); }
};

bool maps_shape(const geometry::Shape& shape, const Point2& com, const Linear& A) {
  auto image = [&](const Point2& x) { return com + A(x - com); };
  if (const auto* d = std::get_if<geometry::DiskShape>(&shape)) return image(d->center) == d->center;
  const auto& V = std::get<geometry::PolygonShape>(shape).vertices;
  std::map<Point2, std::size_t, PointLess> index;
  for (std::size_t i = 0; i < V.size(); ++i) index[V[i]] = i;
  for (std::size_t i = 0; i < V.size(); ++i) {
    const auto p = index.find(image(V[i])), q = index.find(image(V[(i + 1) % V.size()]));
    if (p == index.end() || q == index.end()) return false;
    const std::size_t diff = (q->second + V.size() - p->second) % V.size();
    if (diff != 1 && diff != V.size() - 1) return false;  // an edge must map to an edge
  }
  return true;
}

/// Does x -> com + A (x - com) map the points onto themselves?
bool maps_points(const std::vector<Candidate>& points, const Point2& com, const Linear& A) {
  std::vector<Point2> from, to;
  for (const auto& c : points) {
    from.push_back(c.point);
    to.push_back(com + A(c.point - com));
  }
  std::sort(from.begin(), from.end(), PointLess());
  std::sort(to.begin(), to.end(), PointLess());
  return from == to;
}

bool maps_wrenches(const WrenchSet& w, const Linear& A) {
  auto key = [&](const exact::Vec<Q>& g) {
    Q s = 0;  // cones: compare rays up to a positive factor (normalise by the first non-zero entry's size)
    if (w.kind == WrenchSet::Kind::kCone)
      for (Eigen::Index i = 0; i < 3 && sgn(s) == 0; ++i) s = abs(g(i));
    const Q f = sgn(s) == 0 ? Q(1) : Q(1 / s);
    return std::array<Q, 3>{g(0) * f, g(1) * f, g(2) * f};
  };
  std::vector<std::array<Q, 3>> from, to;
  for (Eigen::Index r = 0; r < w.rows.rows(); ++r) {
    exact::Vec<Q> g = w.rows.row(r).transpose();
    from.push_back(key(g));
    const Point2 f = A({g(0), g(1)});
    exact::Vec<Q> h(3);
    h << f.x, f.y, A.det() * g(2);
    to.push_back(key(h));
  }
  std::sort(from.begin(), from.end());
  std::sort(to.begin(), to.end());
  return from == to;
}

}  // namespace

bool CandidateSymmetry::is_canonical(const Placement& placement) const {
  Placement image(placement.size());
  for (const auto& perm : permutations) {
    for (std::size_t i = 0; i < placement.size(); ++i) image[i] = perm[static_cast<std::size_t>(placement[i])];
    std::sort(image.begin(), image.end());
    if (image < placement) return false;
  }
  return true;
}

CandidateSymmetry candidate_symmetry(const DesignProblem& problem) {
  const Point2& com = problem.workpiece.com;
  std::vector<Linear> maps;
  for (int s : {1, -1})
    for (int t : {1, -1}) {
      maps.push_back({Q(s), 0, 0, Q(t)});
      maps.push_back({0, Q(s), Q(t), 0});
    }
  if (const auto* poly = std::get_if<geometry::PolygonShape>(&problem.workpiece.shape)) {
    const auto& V = poly->vertices;
    const std::size_t n = V.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j : {(i + 1) % n, (i + n - 1) % n})
        if (auto A = map_taking(V[0] - com, V[1] - com, V[i] - com, V[j] - com)) maps.push_back(*A);
  }
  std::map<Point2, int, PointLess> index;
  for (std::size_t i = 0; i < problem.candidates.size(); ++i) index[problem.candidates[i].point] = static_cast<int>(i);
  CandidateSymmetry out;
  std::vector<std::vector<int>> seen;
  for (const Linear& A : maps) {
    if (!A.orthogonal() || !maps_shape(problem.workpiece.shape, com, A) || !maps_wrenches(problem.wrenches, A))
      continue;
    std::vector<int> perm;
    for (const auto& c : problem.candidates) {
      const auto it = index.find(com + A(c.point - com));
      if (it == index.end()) break;
      perm.push_back(it->second);
    }
    if (perm.size() != problem.candidates.size() || !maps_points(problem.pushes, com, A)) continue;
    bool identity = true;
    for (std::size_t i = 0; i < perm.size(); ++i) identity = identity && perm[i] == static_cast<int>(i);
    if (identity || std::find(seen.begin(), seen.end(), perm) != seen.end()) continue;
    seen.push_back(perm);
    out.permutations.push_back(perm);
  }
  return out;
}

}  // namespace contactcert::solvers
