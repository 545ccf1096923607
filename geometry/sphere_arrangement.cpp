#include "geometry/sphere_arrangement.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>

namespace contactcert::geometry {
namespace {

using exact::is_zero;
using exact::sign;
using Index = Eigen::Index;

template <class T>
using V3 = Eigen::Matrix<T, 3, 1>;

template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return V3<T>(T(a(1) * b(2) - a(2) * b(1)), T(a(2) * b(0) - a(0) * b(2)), T(a(0) * b(1) - a(1) * b(0)));
}

template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return T(a(0) * b(0) + a(1) * b(1) + a(2) * b(2));
}

template <class T>
bool parallel(const V3<T>& a, const V3<T>& b) {
  const V3<T> c = cross(a, b);
  return is_zero(c(0)) && is_zero(c(1)) && is_zero(c(2));
}

template <class T>
bool nonzero(const V3<T>& a) {
  return !is_zero(a(0)) || !is_zero(a(1)) || !is_zero(a(2));
}

// Angular order of tangent directions around a vertex, in the coordinates (d . e1, d . e2).
template <class T>
struct Angular {
  T x, y;
  int half() const { return (sign(y) > 0 || (sign(y) == 0 && sign(x) > 0)) ? 0 : 1; }
  bool operator<(const Angular& o) const {
    if (half() != o.half()) return half() < o.half();
    return sign(T(x * o.y - y * o.x)) > 0;
  }
};

template <class T>
class Builder {
 public:
  explicit Builder(const std::vector<V3<T>>& n) : n_(n) {}

  void add(int dimension, const V3<T>& p) {
    std::vector<int> s(n_.size());
    for (std::size_t j = 0; j < n_.size(); ++j) s[j] = sign(dot(n_[j], p));
    record(dimension, p, std::move(s));
  }

  // Adds the cell of v + eps u, eps > 0 small enough that every plane not through v keeps its sign at v
  // (eps = half the least |n.v| / |n.u| over the planes whose sign would flip). `nv` caches n_j . v.
  void add_near(int dimension, const V3<T>& v, const std::vector<T>& nv, const V3<T>& u) {
    std::vector<T> nu(n_.size());
    T eps = T(1);
    for (std::size_t j = 0; j < n_.size(); ++j) {
      nu[j] = dot(n_[j], u);
      if (is_zero(nv[j]) || is_zero(nu[j]) || sign(nv[j]) == sign(nu[j])) continue;
      const T bound = T(-nv[j] / nu[j]) / T(2);  // positive
      if (bound < eps) eps = bound;
    }
    std::vector<int> s(n_.size());
    for (std::size_t j = 0; j < n_.size(); ++j) s[j] = is_zero(nv[j]) ? sign(nu[j]) : sign(nv[j]);
    if (seen_.count(s)) return;
    record(dimension, V3<T>(T(v(0) + eps * u(0)), T(v(1) + eps * u(1)), T(v(2) + eps * u(2))), std::move(s));
  }

  std::vector<ArrangementCell<T>> cells() && { return std::move(cells_); }

 private:
  void record(int dimension, const V3<T>& p, std::vector<int> s) {
    if (seen_.emplace(s, cells_.size()).second) cells_.push_back({dimension, Vec<T>(p), std::move(s)});
  }

  std::vector<V3<T>> n_;
  std::map<std::vector<int>, std::size_t> seen_;
  std::vector<ArrangementCell<T>> cells_;
};

}  // namespace

template <class T>
SphereArrangement<T> sphere_arrangement(const Mat<T>& normals) {
  std::vector<V3<T>> n;
  for (Index r = 0; r < normals.rows(); ++r) {
    const V3<T> v(normals(r, 0), normals(r, 1), normals(r, 2));
    if (!nonzero(v)) continue;
    if (std::none_of(n.begin(), n.end(), [&](const V3<T>& w) { return parallel(v, w); })) n.push_back(v);
  }
  SphereArrangement<T> out;
  out.planes = Mat<T>(static_cast<Index>(n.size()), 3);
  for (std::size_t j = 0; j < n.size(); ++j) out.planes.row(static_cast<Index>(j)) = n[j].transpose();

  Builder<T> b(n);
  b.add(0, V3<T>::Zero());
  if (n.empty()) {
    b.add(3, V3<T>(T(1), T(0), T(0)));
  } else if (n.size() == 1) {
    // One great circle: the two open hemispheres and the circle (a plane minus the origin).
    const V3<T>& a = n[0];
    V3<T> e = parallel(a, V3<T>(T(1), T(0), T(0))) ? V3<T>(T(0), T(1), T(0)) : V3<T>(T(1), T(0), T(0));
    b.add(2, cross(a, e));
    b.add(3, a);
    b.add(3, V3<T>(-a));
  } else {
    // Vertices: the lines n_i x n_j, both directions, each scaled so that its first non-zero
    // coordinate is +-1 (equal rays then compare equal; float near-duplicates only cost time, since
    // cells are merged by sign vector).
    std::set<std::array<T, 3>> vertices;
    for (std::size_t i = 0; i < n.size(); ++i)
      for (std::size_t j = i + 1; j < n.size(); ++j) {
        V3<T> d = cross(n[i], n[j]);
        const T lead = !is_zero(d(0)) ? d(0) : (!is_zero(d(1)) ? d(1) : d(2));
        const T scale = sign(lead) > 0 ? lead : T(-lead);
        d /= scale;
        vertices.insert({d(0), d(1), d(2)});
        vertices.insert({T(-d(0)), T(-d(1)), T(-d(2))});
      }
    for (const auto& key : vertices) {
      const V3<T> v(key[0], key[1], key[2]);
      b.add(1, v);
      std::vector<T> nv(n.size());
      for (std::size_t j = 0; j < n.size(); ++j) nv[j] = dot(n[j], v);
      // Tangent directions at v of the circles through v, sorted around v.
      std::vector<V3<T>> dirs;
      for (std::size_t j = 0; j < n.size(); ++j)
        if (is_zero(nv[j])) {
          const V3<T> d = cross(n[j], v);
          dirs.push_back(d);
          dirs.push_back(V3<T>(-d));
        }
      const V3<T> e1 = dirs.front(), e2 = cross(v, e1);
      std::vector<std::pair<Angular<T>, V3<T>>> order;
      for (const V3<T>& d : dirs) order.push_back({Angular<T>{dot(d, e1), dot(d, e2)}, d});
      std::sort(order.begin(), order.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
      for (std::size_t k = 0; k < order.size(); ++k) {
        const V3<T>& d = order[k].second;
        const V3<T>& next = order[(k + 1) % order.size()].second;
        b.add_near(2, v, nv, d);  // along an arc leaving v
        // Between two consecutive tangent directions (less than pi apart): a region at v.
        b.add_near(3, v, nv, V3<T>(T(d(0) + next(0)), T(d(1) + next(1)), T(d(2) + next(2))));
      }
    }
  }
  out.cells = std::move(b).cells();
  return out;
}

template SphereArrangement<double> sphere_arrangement<double>(const Mat<double>&);
template SphereArrangement<Q> sphere_arrangement<Q>(const Mat<Q>&);

}  // namespace contactcert::geometry
