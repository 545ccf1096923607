#include "solvers/stability/mode_tree_cone.h"

#include <algorithm>
#include <set>

namespace contactcert::solvers {

using exact::Int128;
namespace ring = exact::ring;

Int128 dot(const Int3& f, const Int3& v) {
  return ring::add(ring::add(ring::mul(f[0], v[0]), ring::mul(f[1], v[1])), ring::mul(f[2], v[2]));
}

namespace {

// v over the gcd of its entries (0 stays 0).
Int3 primitive(Int3 v) {
  const Int128 g = ring::gcd(ring::gcd(v[0], v[1]), v[2]);
  if (g > 1)
    for (Int128& x : v) x /= g;
  return v;
}

// a b_coef - b a_coef: with a_coef = f . a, b_coef = f . b of opposite signs, the point of segment [a, b] on f . v = 0.
Int3 on_plane(const Int3& a, Int128 fa, const Int3& b, Int128 fb) {
  Int3 v;
  for (int d = 0; d < 3; ++d) v[d] = ring::sub(ring::mul(fa, b[d]), ring::mul(fb, a[d]));
  if (fa < 0)
    for (Int128& x : v) x = -x;
  return primitive(v);
}

Int3 cross(const Int3& a, const Int3& b) {
  return {ring::sub(ring::mul(a[1], b[2]), ring::mul(a[2], b[1])),
          ring::sub(ring::mul(a[2], b[0]), ring::mul(a[0], b[2])),
          ring::sub(ring::mul(a[0], b[1]), ring::mul(a[1], b[0]))};
}

Int128 det3(const Int3& a, const Int3& b, const Int3& c) { return dot(a, cross(b, c)); }

bool is_zero(const Int3& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

}  // namespace

PrefixCone::PrefixCone() : lineality_{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}} {}

void PrefixCone::cut(const ConeRow& row) {
  const Int3& f = row.f;
  const bool equality = row.sign == RowSign::kZero;
  // A lineality vector l with f . l != 0: the others and the rays move along l onto f . v = 0 (C is unchanged),
  // and l leaves the lineality: as a ray on the side f . l > 0, or not at all for an equality.
  for (std::size_t i = 0; i < lineality_.size(); ++i) {
    Int3 l = lineality_[i];
    Int128 fl = dot(f, l);
    if (fl == 0) continue;
    if (fl < 0) {
      for (Int128& x : l) x = -x;
      fl = -fl;
    }
    lineality_.erase(lineality_.begin() + static_cast<std::ptrdiff_t>(i));
    auto project = [&](Int3& v) {
      const Int128 fv = dot(f, v);
      if (fv == 0) return;
      for (int d = 0; d < 3; ++d) v[d] = ring::sub(ring::mul(fl, v[d]), ring::mul(fv, l[d]));
      v = primitive(v);
    };
    for (Int3& m : lineality_) project(m);
    for (Int3& r : rays_) project(r);
    if (!equality) rays_.push_back(primitive(l));
    return;
  }
  // f vanishes on the lineality: clip the rays. Three or more form a cycle (a convex polygon's corners), fewer
  // a path; a new ray lies between each neighbouring pair on strictly opposite sides.
  const std::size_t n = rays_.size();
  std::vector<Int128> fr(n);
  for (std::size_t i = 0; i < n; ++i) fr[i] = dot(f, rays_[i]);
  std::vector<Int3> out;
  const std::size_t pairs = n >= 3 ? n : n - (n > 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (fr[i] == 0 || (fr[i] > 0 && !equality)) out.push_back(rays_[i]);
    if (i < pairs) {
      const std::size_t j = (i + 1) % n;
      if ((fr[i] > 0 && fr[j] < 0) || (fr[i] < 0 && fr[j] > 0))
        out.push_back(on_plane(rays_[i], fr[i], rays_[j], fr[j]));
    }
  }
  rays_ = std::move(out);
}

Int3 PrefixCone::ray_sum() const {
  Int3 s{0, 0, 0};
  for (const Int3& r : rays_)
    for (int d = 0; d < 3; ++d) s[d] = ring::add(s[d], r[d]);
  return primitive(s);
}

std::optional<Int3> PrefixCone::point_meeting(const std::vector<ConeRow>& rows) const {
  for (const Int3& r : rays_)
    if (meets_rows(rows, r)) return r;
  const Int3 s = ray_sum();
  if (meets_rows(rows, s)) return s;
  return std::nullopt;
}

bool meets_rows(const std::vector<ConeRow>& rows, const Int3& v) {
  for (const ConeRow& r : rows) {
    const Int128 fv = dot(r.f, v);
    if (r.sign == RowSign::kZero ? fv != 0 : r.sign == RowSign::kPositive ? fv <= 0 : fv < 0) return false;
  }
  return true;
}

CertificateCandidates certificate_candidates(const std::vector<ConeRow>& rows, std::size_t first_new,
                                             const PrefixCone& parent) {
  CertificateCandidates out;
  std::set<Int3> directions;
  std::vector<Int3> zero_basis;  // independent equality rows: their span is all that a certificate uses of them
  auto add = [&](std::size_t i) {
    if (rows[i].sign == RowSign::kZero) {
      const Int3& f = rows[i].f;
      const bool independent = zero_basis.size() == 0   ? !is_zero(f)
                               : zero_basis.size() == 1 ? !is_zero(cross(zero_basis[0], f))
                               : zero_basis.size() == 2 ? det3(zero_basis[0], zero_basis[1], f) != 0
                                                        : false;
      if (!independent) return;
      zero_basis.push_back(f);
    } else if (!directions.insert(primitive(rows[i].f)).second) {
      return;
    }
    out.rows.push_back(i);
  };
  for (std::size_t i = first_new; i < rows.size(); ++i) add(i);
  out.new_rows = out.rows.size();
  for (std::size_t i = 0; i < first_new; ++i) {
    bool tight = parent.rays().size() <= 1 || rows[i].sign == RowSign::kZero;
    for (std::size_t j = 0; j < parent.rays().size() && !tight; ++j) tight = dot(rows[i].f, parent.rays()[j]) == 0;
    if (tight) add(i);
  }
  return out;
}

namespace {

// Integer weights w on vectors a_0 .. a_{s-1} (s = 2 to 4) with sum w_i a_i = 0, w_0 >= 0, found by the formula
// for a one-dimensional null space: parallel vectors (s = 2), the cross product of two coordinate rows (s = 3, rank
// 2), Cramer's rule (s = 4, rank 3). All zero where the formula gives nothing; the caller checks the sum.
std::array<Int128, 4> null_combination(const std::array<Int3, 4>& a, std::size_t s) {
  std::array<Int128, 4> w{0, 0, 0, 0};
  if (s == 2) {
    for (int d = 0; d < 3 && w[0] == 0; ++d)
      if (a[1][d] != 0) w = {a[1][d], -a[0][d], 0, 0};
  } else if (s == 3) {
    for (int d = 0; d < 3 && w[0] == 0 && w[1] == 0 && w[2] == 0; ++d) {
      const int e = (d + 1) % 3;
      const Int3 n = cross({a[0][d], a[1][d], a[2][d]}, {a[0][e], a[1][e], a[2][e]});
      w = {n[0], n[1], n[2], 0};
    }
  } else {
    w = {det3(a[1], a[2], a[3]), -det3(a[0], a[2], a[3]), det3(a[0], a[1], a[3]), -det3(a[0], a[1], a[2])};
  }
  if (w[0] < 0)
    for (Int128& x : w) x = -x;
  return w;
}

}  // namespace

std::optional<std::vector<Int128>> cone_motzkin(const std::vector<ConeRow>& rows, const PrefixCone& cone,
                                                const CertificateCandidates& candidates, long budget) {
  const Int3 v = cone.ray_sum();
  const std::vector<std::size_t>& c = candidates.rows;
  const std::size_t n = c.size();
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (rows[r].sign != RowSign::kPositive || dot(rows[r].f, v) > 0) continue;
    // f_r vanishes on the cone: w_r f_r + (a combination of 1 to 3 candidates) = 0 with w_r > 0. The parent's rows
    // alone are feasible, so a certificate weighs a new row: unless r is new, the first candidate is (new rows
    // come first).
    const bool r_new = std::find(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(candidates.new_rows), r) !=
                       c.begin() + static_cast<std::ptrdiff_t>(candidates.new_rows);
    const std::size_t first_end = r_new ? n : candidates.new_rows;
    std::array<std::size_t, 3> pick{};
    std::array<Int3, 4> a;
    a[0] = rows[r].f;
    auto attempt = [&](std::size_t s) -> std::optional<std::vector<Int128>> {
      for (std::size_t t = 0; t < s; ++t) {
        if (c[pick[t]] == r) return std::nullopt;
        a[t + 1] = rows[c[pick[t]]].f;
      }
      std::array<Int128, 4> w = null_combination(a, s + 1);
      const Int128 g = ring::gcd(ring::gcd(w[0], w[1]), ring::gcd(w[2], w[3]));
      if (g > 1)
        for (Int128& x : w) x /= g;
      if (w[0] <= 0) return std::nullopt;
      for (std::size_t t = 0; t < s; ++t)
        if (rows[c[pick[t]]].sign != RowSign::kZero && w[t + 1] < 0) return std::nullopt;
      Int3 sum{0, 0, 0};  // the check: sum w_i f_i = 0
      for (std::size_t t = 0; t <= s; ++t)
        for (int d = 0; d < 3; ++d) sum[d] = ring::add(sum[d], ring::mul(w[t], a[t][d]));
      if (!is_zero(sum)) return std::nullopt;
      std::vector<Int128> out(rows.size(), 0);
      out[r] = w[0];
      for (std::size_t t = 0; t < s; ++t) out[c[pick[t]]] = w[t + 1];
      return out;
    };
    for (std::size_t size = 1; size <= 3; ++size)  // smallest subsets first: the fewest rows in the certificate
      for (pick[0] = 0; pick[0] < first_end; ++pick[0]) {
        if (size == 1) {
          if (auto w = attempt(1)) return w;
          continue;
        }
        for (pick[1] = pick[0] + 1; pick[1] < n; ++pick[1]) {
          if (size == 2) {
            if (auto w = attempt(2)) return w;
            continue;
          }
          for (pick[2] = pick[1] + 1; pick[2] < n; ++pick[2]) {
            if (--budget < 0) return std::nullopt;
            if (auto w = attempt(3)) return w;
          }
        }
      }
  }
  return std::nullopt;
}

}  // namespace contactcert::solvers
