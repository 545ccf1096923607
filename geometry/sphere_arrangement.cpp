#include "geometry/sphere_arrangement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <type_traits>
#include <unordered_set>

#include "exact/input_error.h"

namespace contactcert::geometry {
namespace {

using exact::Z;
using Index = Eigen::Index;

// The arrangement is computed over R: the exact one over the integers (each normal scaled to a primitive
// integer vector; a ray's direction is all that matters, so every point is kept integer too), the float one
// in doubles. Integer products need no gcd, unlike rational ones.
template <class T>
using Ring = std::conditional_t<std::is_same_v<T, Q>, Z, double>;

int sign_of(double x) { return exact::sign(x); }
int sign_of(const Z& x) { return sgn(x); }
template <class R>
bool is_zero(const R& x) {
  return sign_of(x) == 0;
}

template <class R>
using V3 = std::array<R, 3>;

template <class R>
V3<R> cross(const V3<R>& a, const V3<R>& b) {
  return {R(a[1] * b[2] - a[2] * b[1]), R(a[2] * b[0] - a[0] * b[2]), R(a[0] * b[1] - a[1] * b[0])};
}

template <class R>
R dot(const V3<R>& a, const V3<R>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// a . b without temporaries (the arrangement's inner loop).
Z dot(const V3<Z>& a, const V3<Z>& b) {
  Z r;
  mpz_mul(r.get_mpz_t(), a[0].get_mpz_t(), b[0].get_mpz_t());
  mpz_addmul(r.get_mpz_t(), a[1].get_mpz_t(), b[1].get_mpz_t());
  mpz_addmul(r.get_mpz_t(), a[2].get_mpz_t(), b[2].get_mpz_t());
  return r;
}

// s a + t b.
template <class R>
V3<R> combine(const R& s, const V3<R>& a, const R& t, const V3<R>& b) {
  return {R(s * a[0] + t * b[0]), R(s * a[1] + t * b[1]), R(s * a[2] + t * b[2])};
}

template <class R>
V3<R> negated(const V3<R>& a) {
  return {R(-a[0]), R(-a[1]), R(-a[2])};
}

template <class R>
bool nonzero(const V3<R>& a) {
  return !is_zero(a[0]) || !is_zero(a[1]) || !is_zero(a[2]);
}

template <class R>
bool parallel(const V3<R>& a, const V3<R>& b) {
  return !nonzero(cross(a, b));
}

// One representative of the ray through d: the primitive integer vector (exact), or d over the magnitude of
// its first non-zero coordinate (float), so that equal rays compare equal.
V3<Z> ray_key(V3<Z> d) {
  Z g;
  mpz_gcd(g.get_mpz_t(), d[0].get_mpz_t(), d[1].get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), d[2].get_mpz_t());
  for (Z& x : d) mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), g.get_mpz_t());
  return d;
}
V3<double> ray_key(V3<double> d) {
  const double lead = !is_zero(d[0]) ? d[0] : (!is_zero(d[1]) ? d[1] : d[2]);
  for (double& x : d) x /= std::abs(lead);
  return d;
}

// A normal row in R: the row times the lcm of its denominators, over the gcd of the numerators (exact).
V3<Z> to_ring(const Vec<Q>& row) {
  Z l = 1;
  for (Index j = 0; j < 3; ++j) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), row(j).get_den_mpz_t());
  V3<Z> v;
  for (Index j = 0; j < 3; ++j) v[static_cast<size_t>(j)] = row(j).get_num() * (l / row(j).get_den());
  return nonzero(v) ? ray_key(v) : v;
}
V3<double> to_ring(const Vec<double>& row) { return {row(0), row(1), row(2)}; }

V3<double> to_double(const V3<Z>& a) { return {a[0].get_d(), a[1].get_d(), a[2].get_d()}; }
const V3<double>& to_double(const V3<double>& a) { return a; }

// sign(n . u), with nd and ud the same vectors in doubles. Integers: decided in doubles when the float dot clears
// its error bound (operands rounded once, three products, two sums: under 6 u sum |n_i u_i|, u = 2^-53; taken as
// 2e-15 sum, which an overflow to infinity never clears), else exactly; doubles: the float dot.
int dot_sign(const V3<Z>& n, const V3<double>& nd, const V3<Z>& u, const V3<double>& ud) {
  const double s = nd[0] * ud[0] + nd[1] * ud[1] + nd[2] * ud[2];
  const double a = std::abs(nd[0] * ud[0]) + std::abs(nd[1] * ud[1]) + std::abs(nd[2] * ud[2]);
  if (std::abs(s) > 2e-15 * a) return s > 0 ? 1 : -1;
  return sign_of(dot(n, u));
}
int dot_sign(const V3<double>& n, const V3<double>&, const V3<double>& u, const V3<double>&) {
  return sign_of(dot(n, u));
}

// sign det(a, b, v) = sign a . (b x v): in doubles when the float value clears its error bound (inputs rounded
// once, three-term products, five sums: under 12 u sum of the terms' magnitudes; taken as 1e-14, which an overflow
// never clears), else exactly.
int triple_sign(const V3<Z>& a, const V3<double>& ad, const V3<Z>& b, const V3<double>& bd, const V3<Z>& v) {
  const V3<double> vd = to_double(v);
  const V3<double> c{bd[1] * vd[2], bd[2] * vd[0], bd[0] * vd[1]}, e{bd[2] * vd[1], bd[0] * vd[2], bd[1] * vd[0]};
  double s = 0, m = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    s += ad[i] * c[i] - ad[i] * e[i];
    m += std::abs(ad[i] * c[i]) + std::abs(ad[i] * e[i]);
  }
  if (std::abs(s) > 1e-14 * m) return s > 0 ? 1 : -1;
  return sign_of(dot(a, cross(b, v)));
}
int triple_sign(const V3<double>& a, const V3<double>&, const V3<double>& b, const V3<double>&, const V3<double>& v) {
  return sign_of(dot(a, cross(b, v)));
}

template <class T>
Vec<T> from_ring(const V3<Ring<T>>& p) {
  Vec<T> v(3);
  for (Index j = 0; j < 3; ++j) v(j) = T(p[static_cast<size_t>(j)]);
  return v;
}

// Angular order of tangent directions around a vertex, in the coordinates (d . e1, d . e2).
template <class R>
struct Angular {
  R x, y;
  int half() const { return (sign_of(y) > 0 || (sign_of(y) == 0 && sign_of(x) > 0)) ? 0 : 1; }
  bool operator<(const Angular& o) const {
    if (half() != o.half()) return half() < o.half();
    return sign_of(R(x * o.y - y * o.x)) > 0;
  }
};

// A hash of a sign vector (cells are found by their signs; their order is that of discovery).
struct SignsHash {
  std::size_t operator()(const std::vector<int>& s) const {
    std::size_t h = s.size();
    for (int x : s) h = h * 3 + static_cast<std::size_t>(x + 1);
    return h;
  }
};

template <class T>
class Builder {
  using R = Ring<T>;

 public:
  Builder(const std::vector<V3<R>>& n, const ArrangementBudget& budget, CellPoints points)
      : n_(n), budget_(budget), points_(points == CellPoints::kPoints) {
    for (const V3<R>& v : n_) nd_.push_back(to_double(v));
  }

  // Stops with BudgetExceeded past the deadline or once the cells' signs outgrow the budget; `where` says how far
  // the vertices went.
  void check_budget(const std::string& where) const {
    const bool signs = cells_.size() * std::max<std::size_t>(n_.size(), 1) > budget_.max_signs;
    if (!signs && !budget_.deadline.expired()) return;
    throw exact::BudgetExceeded("arrangement of " + std::to_string(n_.size()) + " planes: " +
                                    (signs ? "more than " + std::to_string(budget_.max_signs) + " cell signs"
                                           : budget_.deadline.reached_text()),
                                where + ", " + std::to_string(cells_.size()) + " cells found");
  }

  // sign(n_j . p) for every plane j.
  std::vector<int> signs_at(const V3<R>& p) const {
    const auto pd = to_double(p);
    std::vector<int> s(n_.size());
    for (std::size_t j = 0; j < n_.size(); ++j) s[j] = dot_sign(n_[j], nd_[j], p, pd);
    return s;
  }

  void add(int dimension, const V3<R>& p) { record(dimension, p, signs_at(p)); }

  // Adds the cell of v + eps u, eps > 0 small enough that every plane not through v keeps its sign at v:
  // eps = a / b = half the least |n.v| / |n.u| over the planes whose sign would flip (eps = 1 if none), and
  // the point is b v + a u, a positive multiple. `sv` holds the signs at v.
  void add_near(int dimension, const V3<R>& v, const std::vector<int>& sv, const V3<R>& u) {
    const auto ud = to_double(u);
    std::vector<int> s(sv);  // only the planes through v take the sign at u
    for (std::size_t j = 0; j < n_.size(); ++j)
      if (sv[j] == 0) s[j] = dot_sign(n_[j], nd_[j], u, ud);
    if (!seen_.insert(s).second) return;
    if (!points_) return keep(dimension, v, std::move(s));
    R a = 1, b = 1;
    for (std::size_t j = 0; j < n_.size(); ++j) {
      if (sv[j] == 0) continue;
      const R nu = dot(n_[j], u);
      if (is_zero(nu) || sv[j] == sign_of(nu)) continue;
      // |nv| / (2 |nu|) < a / b  <=>  |nv| b < 2 |nu| a
      const R nv = dot(n_[j], v);
      const R num = sv[j] > 0 ? nv : R(-nv), den = R(2 * (sign_of(nu) > 0 ? nu : R(-nu)));
      if (sign_of(R(num * b - den * a)) < 0) a = num, b = den;
    }
    keep(dimension, combine(b, v, a, u), std::move(s));
  }

  // Without points, the eight cells around a vertex v on exactly the two planes f < o, in the order the general
  // walk below finds them. With c_j = n_j x v and D = det(n_f, n_o, v), the tangent directions sorted around v are
  // c_f, t c_o, -c_f, -t c_o (t = sign D: the angle of c_o from c_f is that of n_f . c_o = D), and the signs
  // (n_f . u, n_o . u) along them and between them follow from n_f . c_o = D, n_o . c_f = -D.
  bool add_simple_vertex(const V3<R>& v, const std::vector<int>& sv) {
    if (points_ || !std::is_same_v<R, Z>) return false;  // floats take the general walk
    std::size_t f = n_.size(), o = n_.size(), through = 0;
    for (std::size_t j = 0; j < n_.size(); ++j)
      if (sv[j] == 0) (through++ == 0 ? f : o) = j;
    if (through != 2) return false;
    const int t = triple_sign(n_[f], nd_[f], n_[o], nd_[o], v);
    const std::array<std::array<int, 3>, 8> around{
        {{2, 0, -t}, {3, 1, -t}, {2, 1, 0}, {3, 1, t}, {2, 0, t}, {3, -1, t}, {2, -1, 0}, {3, -1, -t}}};
    for (const auto& [dimension, sf, so] : around) {
      std::vector<int> s(sv);
      s[f] = sf;
      s[o] = so;
      record(dimension, v, std::move(s));
    }
    return true;
  }

  // Keeps the cell of sign vector s (with the point p if points are kept) unless it is known.
  void record(int dimension, const V3<R>& p, std::vector<int> s) {
    if (seen_.insert(s).second) keep(dimension, p, std::move(s));
  }

  std::vector<ArrangementCell<T>> cells() && { return std::move(cells_); }

 private:
  std::vector<V3<R>> n_;
  std::vector<V3<double>> nd_;  // n_ in doubles (the sign filter)
  const ArrangementBudget& budget_;
  bool points_;
  std::unordered_set<std::vector<int>, SignsHash> seen_;
  std::vector<ArrangementCell<T>> cells_;

  void keep(int dimension, const V3<R>& p, std::vector<int> s) {
    cells_.push_back({dimension, points_ ? from_ring<T>(p) : Vec<T>(), std::move(s)});
  }
};

}  // namespace

template <class T>
SphereArrangement<T> sphere_arrangement(const Mat<T>& normals, const ArrangementBudget& budget, CellPoints points) {
  using R = Ring<T>;
  SphereArrangement<T> out;
  std::vector<V3<R>> n;
  std::vector<Index> kept;  // the input row of each plane
  out.row_plane.assign(static_cast<std::size_t>(normals.rows()), -1);
  out.row_orientation.assign(static_cast<std::size_t>(normals.rows()), 0);
  for (Index r = 0; r < normals.rows(); ++r) {
    if (budget.deadline.expired())
      throw exact::BudgetExceeded(
          "arrangement of " + std::to_string(normals.rows()) + " rows: " + budget.deadline.reached_text(),
          std::to_string(r) + " rows merged into " + std::to_string(n.size()) + " planes");
    const V3<R> v = to_ring(Vec<T>(normals.row(r).transpose()));
    if (!nonzero(v)) continue;
    const auto same = std::find_if(n.begin(), n.end(), [&](const V3<R>& w) { return parallel(v, w); });
    out.row_plane[static_cast<std::size_t>(r)] = same - n.begin();
    out.row_orientation[static_cast<std::size_t>(r)] = same == n.end() ? 1 : sign_of(dot(v, *same));
    if (same == n.end()) {
      n.push_back(v);
      kept.push_back(r);
    }
  }
  out.planes = Mat<T>(static_cast<Index>(n.size()), 3);
  for (std::size_t j = 0; j < n.size(); ++j) out.planes.row(static_cast<Index>(j)) = normals.row(kept[j]);

  Builder<T> b(n, budget, points);
  b.add(0, V3<R>{R(0), R(0), R(0)});
  if (n.empty()) {
    b.add(3, V3<R>{R(1), R(0), R(0)});
  } else if (n.size() == 1) {
    // One great circle: the two open hemispheres and the circle (a plane minus the origin).
    const V3<R>& a = n[0];
    const V3<R> x{R(1), R(0), R(0)}, y{R(0), R(1), R(0)};
    b.add(2, cross(a, parallel(a, x) ? y : x));
    b.add(3, a);
    b.add(3, negated(a));
  } else {
    // Vertices: the lines n_i x n_j, both directions, each as its ray_key (float near-duplicates only cost
    // time, since cells are merged by sign vector).
    std::set<V3<R>> vertices;
    for (std::size_t i = 0; i < n.size(); ++i) {
      b.check_budget("vertices of " + std::to_string(i) + " of " + std::to_string(n.size()) + " planes found");
      for (std::size_t j = i + 1; j < n.size(); ++j) {
        const V3<R> d = ray_key(cross(n[i], n[j]));
        vertices.insert(d);
        vertices.insert(negated(d));
      }
    }
    std::size_t visited = 0;
    for (const V3<R>& v : vertices) {
      b.check_budget(std::to_string(visited++) + " of " + std::to_string(vertices.size()) + " vertices visited");
      const std::vector<int> sv = b.signs_at(v);
      b.record(1, v, sv);
      if (b.add_simple_vertex(v, sv)) continue;
      // Tangent directions at v of the circles through v, sorted around v.
      std::vector<V3<R>> dirs;
      for (std::size_t j = 0; j < n.size(); ++j)
        if (sv[j] == 0) {
          const V3<R> d = cross(n[j], v);
          dirs.push_back(d);
          dirs.push_back(negated(d));
        }
      const V3<R> e1 = dirs.front(), e2 = cross(v, e1);
      std::vector<std::pair<Angular<R>, V3<R>>> order;
      for (const V3<R>& d : dirs) order.push_back({Angular<R>{dot(d, e1), dot(d, e2)}, d});
      std::sort(order.begin(), order.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
      for (std::size_t k = 0; k < order.size(); ++k) {
        const V3<R>& d = order[k].second;
        const V3<R>& next = order[(k + 1) % order.size()].second;
        b.add_near(2, v, sv, d);  // along an arc leaving v
        // Between two consecutive tangent directions (less than pi apart): a region at v.
        b.add_near(3, v, sv, combine(R(1), d, R(1), next));
      }
    }
  }
  out.cells = std::move(b).cells();
  return out;
}

template SphereArrangement<double> sphere_arrangement<double>(const Mat<double>&, const ArrangementBudget&, CellPoints);
template SphereArrangement<Q> sphere_arrangement<Q>(const Mat<Q>&, const ArrangementBudget&, CellPoints);

}  // namespace contactcert::geometry
