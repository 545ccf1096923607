#include "solvers/design/candidates.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "exact/input_error.h"
#include "geometry/snap.h"

namespace contactcert::solvers {
namespace {

using exact::Z;
using geometry::DiskShape;
using geometry::Point2;
using geometry::PolygonShape;
using geometry::Q;

bool is_vertex(const std::vector<Point2>& V, const Point2& p) {
  return std::any_of(V.begin(), V.end(), [&](const Point2& v) { return v == p; });
}

/// Points on the disk in counter-clockwise order from angle 0 (exact half-plane and cross-product test).
bool before_on_circle(const Point2& c, const Point2& p, const Point2& q) {
  const Point2 u = p - c, v = q - c;
  auto half = [](const Point2& w) { return sgn(w.y) < 0 || (sgn(w.y) == 0 && sgn(w.x) < 0); };
  if (half(u) != half(v)) return !half(u);
  return sgn(geometry::cross(u, v)) > 0;
}

}  // namespace

CandidateCheck candidate_at(const geometry::Shape& shape, const Point2& p) {
  if (const auto* d = std::get_if<DiskShape>(&shape)) {
    if (sgn(Q(geometry::norm2(p - d->center) - d->radius * d->radius)) != 0)
      return {{p, {}}, "a point on the disk boundary |p - c| = r"};
    return {{p, d->center - p}, {}};
  }
  const auto& V = std::get<PolygonShape>(shape).vertices;
  if (is_vertex(V, p))
    return {{p, {}}, "a boundary point that is not a polygon vertex (the normal is not unique there)"};
  for (std::size_t e = 0; e < V.size(); ++e) {
    const Point2& a = V[e];
    const Point2& b = V[(e + 1) % V.size()];
    const Point2 ab = b - a, ap = p - a;
    if (sgn(geometry::cross(ab, ap)) != 0) continue;
    const Q t = geometry::dot(ab, ap) / geometry::norm2(ab);
    if (sgn(t) > 0 && t < 1) return {{p, geometry::perp(ab)}, {}};
  }
  return {{p, {}}, "a point on the polygon boundary"};
}

std::vector<Candidate> arc_length_candidates(const geometry::Shape& shape, long n) {
  std::vector<Candidate> out;
  if (n <= 0) return out;
  if (const auto* d = std::get_if<DiskShape>(&shape)) {
    const Z scale = Z(1) << 24;
    for (long k = 0; k < n; ++k) {
      // phi in [0, pi/2) within quadrant q: the parameterisation stays well conditioned (t < tan(pi/4)).
      const double theta = 2 * M_PI * (k + 0.5) / static_cast<double>(n);
      const long quadrant = static_cast<long>(std::floor(theta / (M_PI / 2))) % 4;
      const double phi = theta - quadrant * (M_PI / 2);
      Q t(Z(static_cast<long>(std::llround(std::tan(phi / 2) * scale.get_d()))), scale);
      t.canonicalize();
      const Point2 p = geometry::circle_point(d->center, d->radius, t, quadrant);
      out.push_back({p, d->center - p});
    }
    return out;
  }
  const auto& V = std::get<PolygonShape>(shape).vertices;
  std::vector<Q> length(V.size());
  Q perimeter = 0;
  bool rational = true;
  for (std::size_t e = 0; e < V.size(); ++e) {
    length[e] = geometry::rational_length(geometry::norm2(V[(e + 1) % V.size()] - V[e]), &rational);
    perimeter += length[e];
  }
  auto add = [&](std::size_t e, const Q& t) {
    if (sgn(t) == 0 || t >= 1) return;  // on a vertex: no unique normal
    const Point2 ab = V[(e + 1) % V.size()] - V[e];
    out.push_back({V[e] + t * ab, geometry::perp(ab)});
  };
  if (rational) {
    // Exact arc length s_k = (k + 1/2) L / n.
    std::size_t e = 0;
    Q start = 0;  // arc length at vertex e
    for (long k = 0; k < n; ++k) {
      const Q s = (Q(k) + Q(1, 2)) * perimeter / Q(n);
      while (e + 1 < V.size() && s >= start + length[e]) start += length[e++];
      add(e, (s - start) / length[e]);
    }
    return out;
  }
  // Some length is irrational: n_e points per edge by largest remainder of n L_e / L (rational lengths), at
  // equal parameter steps t = (j + 1/2) / n_e on the edge.
  std::vector<long> count(V.size());
  std::vector<std::pair<Q, std::size_t>> remainder;
  long given = 0;
  for (std::size_t e = 0; e < V.size(); ++e) {
    const Q share = Q(n) * length[e] / perimeter;
    count[e] = Z(share.get_num() / share.get_den()).get_si();
    given += count[e];
    remainder.emplace_back(share - Q(count[e]), e);
  }
  std::stable_sort(remainder.begin(), remainder.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t i = 0; given < n; ++i, ++given) ++count[remainder[i].second];
  for (std::size_t e = 0; e < V.size(); ++e)
    for (long j = 0; j < count[e]; ++j) add(e, (Q(j) + Q(1, 2)) / Q(count[e]));
  return out;
}

namespace {

/// Calls emit(point, inward normal) for each lattice point (i pitch, j pitch) on the boundary that is not a polygon
/// vertex: along each polygon edge in order (a disk's in the order of the lattice lines). BudgetExceeded beyond
/// `max_lines` lattice lines.
void scan_lattice(const geometry::Shape& shape, const Q& pitch, long max_lines,
                  const std::function<void(const Point2&, const Point2&)>& emit) {
  long lines = 0, found = 0;
  auto count_lines = [&](const Z& from, const Z& to) {
    const Z span = to - from + 1;
    if (span > 0) {
      if (span > max_lines - lines)
        throw exact::BudgetExceeded(
            "lattice pitch " + pitch.get_str() + " scans more than " + std::to_string(max_lines) + " lattice lines",
            std::to_string(found) + " lattice candidates found");
      lines += span.get_si();
    }
  };
  auto ceil_q = [](const Q& q) {
    Z r;
    mpz_cdiv_q(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
    return r;
  };
  auto floor_q = [](const Q& q) {
    Z r;
    mpz_fdiv_q(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
    return r;
  };
  auto on_lattice = [&](const Q& v) { return Q(v / pitch).get_den() == 1; };
  auto put = [&](const Point2& p, const Point2& normal) {
    ++found;
    emit(p, normal);
  };
  if (const auto* d = std::get_if<DiskShape>(&shape)) {
    const Z lo = ceil_q((d->center.x - d->radius) / pitch), hi = floor_q((d->center.x + d->radius) / pitch);
    count_lines(lo, hi);
    for (Z i = lo; i <= hi; ++i) {
      const Q x = Q(i) * pitch, dx = x - d->center.x;
      const Q h2 = d->radius * d->radius - dx * dx;
      if (!mpz_perfect_square_p(h2.get_num_mpz_t()) || !mpz_perfect_square_p(h2.get_den_mpz_t())) continue;
      const Q h = geometry::rational_length(h2);
      std::vector<Q> ys{d->center.y - h};
      if (sgn(h) > 0) ys.push_back(d->center.y + h);
      for (const Q& y : ys)
        if (on_lattice(y)) put({x, y}, d->center - Point2{x, y});
    }
    return;
  }
  const auto& V = std::get<PolygonShape>(shape).vertices;
  for (std::size_t e = 0; e < V.size(); ++e) {
    const Point2& a = V[e];
    const Point2 ab = V[(e + 1) % V.size()] - a;
    // Scan the lattice lines across the edge's longer extent; t along the edge is exact and monotone in the line.
    const bool by_x = abs(ab.x) >= abs(ab.y);
    const Q a0 = by_x ? a.x : a.y, d0 = by_x ? ab.x : ab.y;
    const Q lo_v = std::min(a0, Q(a0 + d0)), hi_v = std::max(a0, Q(a0 + d0));
    const Z lo = ceil_q(lo_v / pitch), hi = floor_q(hi_v / pitch);
    count_lines(lo, hi);
    const bool ascending = sgn(d0) > 0;
    for (Z i = ascending ? lo : hi; ascending ? i <= hi : i >= lo; ascending ? ++i : --i) {
      const Q t = (Q(i) * pitch - a0) / d0;
      if (sgn(t) <= 0 || t >= 1) continue;
      const Point2 p = a + t * ab;
      if (on_lattice(by_x ? p.y : p.x)) put(p, geometry::perp(ab));
    }
  }
}

}  // namespace

long lattice_candidate_count(const geometry::Shape& shape, const Q& pitch, long max_lines) {
  long n = 0;
  scan_lattice(shape, pitch, max_lines, [&](const Point2&, const Point2&) { ++n; });
  return n;
}

std::vector<Candidate> lattice_candidates(const geometry::Shape& shape, const Q& pitch, long max_lines) {
  std::vector<Candidate> out;
  scan_lattice(shape, pitch, max_lines, [&](const Point2& p, const Point2& normal) { out.push_back({p, normal}); });
  if (const auto* d = std::get_if<DiskShape>(&shape))
    std::sort(out.begin(), out.end(),
              [&](const Candidate& a, const Candidate& b) { return before_on_circle(d->center, a.point, b.point); });
  return out;
}

}  // namespace contactcert::solvers
