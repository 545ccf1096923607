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

// The length of the certificate entries [row, "weight"] that weights w on the rows at `support` become when
// written (sparse_motzkin_json): the entries factor_i w_i made primitive, in decimal, with their row numbers.
long written_length(const std::array<std::size_t, 4>& support, const std::array<Int128, 4>& w, std::size_t s,
                    const std::vector<std::int64_t>* factors) {
  auto digits = [](Int128 x) {
    int d = 1;
    for (x = x < 0 ? -x : x; !ring::fits_int64(x); x /= 10) ++d;
    for (auto u = static_cast<std::uint64_t>(x); u >= 10; u /= 10) ++d;
    return d;
  };
  std::array<Int128, 4> y{};
  Int128 g = 0;
  for (std::size_t i = 0; i < s; ++i) {
    y[i] = factors ? ring::mul(w[i], Int128((*factors)[support[i]])) : w[i];
    g = ring::gcd(g, y[i] < 0 ? -y[i] : y[i]);
  }
  long length = 0;
  for (std::size_t i = 0; i < s; ++i)
    length += 6 + digits(Int128(support[i])) + digits(g > 1 ? y[i] / g : y[i]) + (y[i] < 0);
  return length;
}

// The certificate to write: `first` (first_vanishing_row's), or a circuit of the candidates with fewer rows, or
// with as many and shorter as written. A circuit is a minimal dependent set of 2 to 4 candidates, a new one among
// them, with sum w_i f_i = 0, every weight non-zero, the sign rows' weights of one sign (made positive) and a
// kPositive row among them. Circuits of two and of three rows are compared (up to kCompared of each size), of four
// rows where there are at most kFourRows subsets with a new row. Where there are more and `first` has four rows,
// `first` is kept without a search (the many candidates of a long prefix whose cone is a point or a ray); with no
// `first`, the first circuit found (within `budget`).
constexpr long kCompared = 1024;
constexpr long kFourRows = 16;

std::optional<std::vector<Int128>> shortest_circuit(const std::vector<ConeRow>& rows,
                                                    const CertificateCandidates& candidates, long& budget,
                                                    const std::vector<std::int64_t>* factors,
                                                    const std::optional<std::vector<Int128>>& first) {
  const std::vector<std::size_t>& c = candidates.rows;
  std::array<std::size_t, 4> t{}, support{}, best_support{};
  std::array<Int128, 4> best_w{};
  std::array<Int3, 4> a;
  std::size_t best_s = 0;
  long best_length = 0;
  if (first) {
    for (std::size_t i = 0; i < first->size(); ++i)
      if ((*first)[i] != 0) best_support[best_s] = i, best_w[best_s++] = (*first)[i];
    best_length = written_length(best_support, best_w, best_s, factors);
  }
  auto circuit = [&](std::size_t s) {
    for (std::size_t i = 0; i < s; ++i) a[i] = rows[c[t[i]]].f;
    std::array<Int128, 4> w = null_combination(a, s);
    int sign = 0;
    bool strict = false;
    for (std::size_t i = 0; i < s; ++i) {
      if (w[i] == 0) return false;  // a smaller subset is dependent: its circuit is found there
      const RowSign row_sign = rows[c[t[i]]].sign;
      if (row_sign == RowSign::kZero) continue;
      if (sign != 0 && (w[i] > 0 ? 1 : -1) != sign) return false;
      sign = w[i] > 0 ? 1 : -1;
      strict = strict || row_sign == RowSign::kPositive;
    }
    if (!strict) return false;
    Int3 sum{0, 0, 0};  // the check: sum w_i f_i = 0
    for (std::size_t i = 0; i < s; ++i)
      for (int d = 0; d < 3; ++d) sum[d] = ring::add(sum[d], ring::mul(w[i], a[i][d]));
    if (!is_zero(sum)) return false;
    const Int128 g = ring::gcd(ring::gcd(w[0], w[1]), ring::gcd(w[2], w[3]));
    for (std::size_t i = 0; i < s; ++i) {
      w[i] = g > 1 ? sign * w[i] / g : sign * w[i];
      support[i] = c[t[i]];
    }
    const long length = written_length(support, w, s, factors);
    if (best_s == 0 || s < best_s || (s == best_s && length < best_length))
      best_s = s, best_length = length, best_support = support, best_w = w;
    return true;
  };
  auto answer = [&]() -> std::optional<std::vector<Int128>> {
    if (best_s == 0) return std::nullopt;
    std::vector<Int128> out(rows.size(), 0);
    for (std::size_t i = 0; i < best_s; ++i) out[best_support[i]] = best_w[i];
    return out;
  };
  const std::size_t m = c.size();
  long quads = static_cast<long>(candidates.new_rows);  // four-row subsets with a new row (kFourRows + 1 if more)
  for (long i = 1; i <= 3; ++i) quads = std::min(quads * std::max(0L, static_cast<long>(m) - i) / i, kFourRows + 1);
  if (best_s == 4 && quads > kFourRows) return answer();
  long tried = 0;  // circuits of the current size tried: past kCompared, the shortest found so far is taken
  auto enough = [&] { return ++tried > kCompared && best_s != 0; };
  for (t[0] = 0; t[0] < candidates.new_rows; ++t[0])  // two rows: parallel ones
    for (t[1] = t[0] + 1; t[1] < m; ++t[1])
      if (circuit(2); enough()) return answer();
  if (best_s != 0 && best_s <= 2) return answer();
  // Three rows: a new row g and f_j, f_k on one plane, i.e. g x f_j parallel to g x f_k. The rows are sorted by
  // that direction and only rows of one direction paired.
  tried = 0;
  std::vector<std::pair<Int3, std::size_t>> planes;
  for (t[0] = 0; t[0] < candidates.new_rows; ++t[0]) {
    planes.clear();
    for (std::size_t j = t[0] + 1; j < m; ++j) {
      Int3 d = primitive(cross(rows[c[t[0]]].f, rows[c[j]].f));
      if (d < Int3{0, 0, 0})
        for (Int128& x : d) x = -x;
      if (!is_zero(d)) planes.emplace_back(d, j);
    }
    std::sort(planes.begin(), planes.end());
    for (std::size_t lo = 0, hi = 0; lo < planes.size(); lo = hi) {
      for (hi = lo + 1; hi < planes.size() && planes[hi].first == planes[lo].first;) ++hi;
      for (std::size_t p = lo; p < hi; ++p)
        for (std::size_t q = p + 1; q < hi; ++q) {
          t[1] = planes[p].second, t[2] = planes[q].second;
          if (circuit(3); enough()) return answer();
        }
    }
  }
  if (best_s != 0 && best_s <= 3) return answer();
  for (t[0] = 0; t[0] < candidates.new_rows; ++t[0])  // four rows
    for (t[1] = t[0] + 1; t[1] < m; ++t[1])
      for (t[2] = t[1] + 1; t[2] < m; ++t[2])
        for (t[3] = t[2] + 1; t[3] < m; ++t[3]) {
          if (--budget < 0) return answer();
          if (circuit(4) && quads > kFourRows) return answer();
        }
  return answer();
}

std::optional<std::vector<Int128>> first_vanishing_row(const std::vector<ConeRow>& rows, const PrefixCone& cone,
                                                       const CertificateCandidates& candidates, long& budget) {
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

}  // namespace

std::optional<std::vector<Int128>> cone_motzkin(const std::vector<ConeRow>& rows, const PrefixCone& cone,
                                                const CertificateCandidates& candidates, long budget,
                                                const std::vector<std::int64_t>* factors,
                                                std::vector<Int128>* first_found) {
  std::optional<std::vector<Int128>> first = first_vanishing_row(rows, cone, candidates, budget);
  std::optional<std::vector<Int128>> w;
  try {
    w = shortest_circuit(rows, candidates, budget, factors, first);
  } catch (const exact::RingOverflow&) {  // a subset's determinants or a written weight beyond 128 bits
    if (!first) throw;
    w = first;
  }
  if (first_found) {
    first_found->clear();
    if (first && w != first) *first_found = std::move(*first);
  }
  return w;
}

}  // namespace contactcert::solvers
