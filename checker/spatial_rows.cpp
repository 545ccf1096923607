#include "checker/spatial_rows.h"

#include <algorithm>
#include <array>

namespace contactcert::checker::spatial_check {

using exact::Q;
using exact::Vec;
using geometry::Vec3;
using table2_check::Rows;

namespace {

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

}  // namespace

std::vector<Seen> seen(const geometry::SpatialScene& s) {
  std::vector<Seen> out;
  for (const auto& c : s.contacts) {
    Seen x{
        {c.point[0] - s.body.com[0], c.point[1] - s.body.com[1], c.point[2] - s.body.com[2]}, c.normal, c.t1, c.t2, {}};
    for (const auto& [u, v] : c.edges)
      x.d.push_back({u * c.t1[0] + v * c.t2[0], u * c.t1[1] + v * c.t2[1], u * c.t1[2] + v * c.t2[2]});
    out.push_back(std::move(x));
  }
  return out;
}

/// Contact i's frame as the checker relies on it, verified rather than taken from the reader: t1 and t2 non-zero,
/// orthogonal to the normal and to each other, t1 x t2 along +normal (a right-handed tangent frame, whichever way
/// the reader chose or derived it). Empty if so, else the reason.
std::string frame_fault(const std::vector<Seen>& cs) {
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const Seen& c = cs[i];
    const bool zero = sgn(geometry::dot(c.t1, c.t1)) == 0 || sgn(geometry::dot(c.t2, c.t2)) == 0;
    if (zero || sgn(geometry::dot(c.t1, c.n)) != 0 || sgn(geometry::dot(c.t2, c.n)) != 0 ||
        sgn(geometry::dot(c.t1, c.t2)) != 0 || sgn(geometry::dot(geometry::cross(c.t1, c.t2), c.n)) <= 0)
      return "contact " + std::to_string(i) + "'s tangent frame is not a right-handed frame orthogonal to its normal";
  }
  return {};
}

std::string alphabet(std::size_t m) {
  std::string s = "sf";
  for (std::size_t j = 0; j < 2 * m; ++j) s.push_back(static_cast<char>('A' + j));
  return s;
}

/// The row u . (a + alpha x r) = u . a + (r x u) . alpha on vdot's six columns, by its non-zero entries.
std::vector<Rows::Entry> along(const Seen& c, const Vec3& u) {
  const Vec3 m = geometry::cross(c.r, u);
  std::vector<Rows::Entry> e;
  for (std::size_t i = 0; i < 3; ++i) {
    if (sgn(u[i]) != 0) e.push_back({i, u[i]});
    if (sgn(m[i]) != 0) e.push_back({3 + i, m[i]});
  }
  std::sort(e.begin(), e.end(), [](const Rows::Entry& x, const Rows::Entry& y) { return x.col < y.col; });
  return e;
}

std::vector<LetterRow> letter_rows(const Seen& c, char L) {
  const std::size_t m = c.d.size(), l = static_cast<std::size_t>(L - 'A'), j = l / 2;
  if (L == 's') return {{c.n, true}};
  if (L == 'f') return {{c.n, false}, {c.t1, false}, {c.t2, false}};
  if (L < 'A' || l >= 2 * m) return {};
  const Vec3 prev = minus(c.d[(j + m - 1) % m], c.d[j]), next = minus(c.d[(j + 1) % m], c.d[j]);
  if (l % 2 == 0) return {{c.n, false}, {prev, true}, {next, true}};
  return {{c.n, false}, {next, false}, {prev, true}, {minus(c.d[(j + 2) % m], c.d[(j + 1) % m]), true}};
}

Rows prefix_rows(const std::vector<Seen>& cs, const std::string& prefix) {
  Rows R;
  R.columns.assign(6, Rows::Sign::kFree);
  for (std::size_t i = 0; i < prefix.size(); ++i)
    for (const LetterRow& r : letter_rows(cs[i], prefix[i])) {
      R.rows.push_back(along(cs[i], r.u));
      if (!r.strict) continue;
      R.rows.back().push_back({R.columns.size(), Q(-1)});
      R.columns.push_back(Rows::Sign::kPositive);
    }
  return R;
}

RowBlocks::RowBlocks(const std::vector<Seen>& cs) {
  for (const Seen& c : cs) {
    std::vector<Vec3> classes;
    std::vector<std::vector<Row>>& letters = rows_.emplace_back();
    for (const char L : alphabet(c.d.size())) {
      std::vector<Row>& rows = letters.emplace_back();
      for (const LetterRow& row : letter_rows(c, L)) {
        const Vec3 minus_u{-row.u[0], -row.u[1], -row.u[2]};
        std::size_t k = 0;
        while (k < classes.size() && classes[k] != row.u && classes[k] != minus_u) ++k;
        if (k == classes.size()) classes.push_back(row.u);
        rows.push_back({k, classes[k] == row.u ? 1 : -1, row.strict});
      }
    }
    std::vector<std::vector<Rows::Entry>>& functionals = functionals_.emplace_back();
    for (const Vec3& u : classes) functionals.push_back(along(c, u));
  }
}

const std::vector<RowBlocks::Row>* RowBlocks::rows(std::size_t i, char L) const {
  if (L != 's' && L != 'f' && L < 'A') return nullptr;
  const std::size_t at = L == 's' ? 0 : L == 'f' ? 1 : static_cast<std::size_t>(L - 'A') + 2;  // alphabet's order
  return at < rows_[i].size() ? &rows_[i][at] : nullptr;
}

/// Whether vdot = (a, alpha) realises the letters, read directly from the contact point's acceleration.
bool realises(const std::vector<Seen>& cs, const std::string& mode, const Vec<Q>& vdot) {
  const Vec3 a{vdot(0), vdot(1), vdot(2)}, alpha{vdot(3), vdot(4), vdot(5)};
  for (std::size_t i = 0; i < mode.size(); ++i) {
    const Seen& c = cs[i];
    const Vec3 w = geometry::cross(alpha, c.r);
    const Vec3 acc{a[0] + w[0], a[1] + w[1], a[2] + w[2]};
    const int an = sgn(geometry::dot(c.n, acc));
    const bool still = sgn(acc[0]) == 0 && sgn(acc[1]) == 0 && sgn(acc[2]) == 0;
    if (mode[i] == 's' || mode[i] == 'f') {
      if (mode[i] == 's' ? an <= 0 : !still) return false;
      continue;
    }
    if (an != 0 || still) return false;
    std::vector<Q> v;
    for (const Vec3& d : c.d) v.push_back(geometry::dot(d, acc));
    const Q low = *std::min_element(v.begin(), v.end());
    const std::size_t m = c.d.size(), L = static_cast<std::size_t>(mode[i] - 'A'), j = L / 2;
    for (std::size_t e = 0; e < m; ++e) {
      const bool active = e == j || (L % 2 == 1 && e == (j + 1) % m);
      if ((v[e] == low) != active) return false;
    }
  }
  return true;
}

std::string read_letters(const exact::JsonInput& j, const std::vector<Seen>& cs, bool whole, bool parent) {
  const std::string text = j.string();
  bool ok = whole    ? text.size() == cs.size()
            : parent ? text.size() < cs.size()
                     : !text.empty() && text.size() <= cs.size();
  for (std::size_t i = 0; ok && i < text.size(); ++i) ok = alphabet(cs[i].d.size()).find(text[i]) != std::string::npos;
  if (!ok)
    j.fail(std::string(whole    ? "a mode: one letter per contact ("
                       : parent ? "a prefix: 0 to "
                                : "a prefix: 1 to ") +
           std::to_string(whole || !parent ? cs.size() : cs.size() - 1) + (whole ? ")" : " letters") +
           ", each s, f or A.. (2m sliding letters for m pyramid edges)");
  return text;
}

std::vector<std::size_t> allowed(std::size_t m, char L) {
  std::vector<std::size_t> e;
  if (L == 'f')
    for (std::size_t j = 0; j < m; ++j) e.push_back(j);
  if (L == 'f' || L == 's') return e;
  const std::size_t j = static_cast<std::size_t>(L - 'A') / 2;
  e.push_back(j);
  if ((L - 'A') % 2 == 1) e.push_back((j + 1) % m);
  return e;
}

Vec3 edge_force(const Seen& c, std::size_t j) { return {c.n[0] + c.d[j][0], c.n[1] + c.d[j][1], c.n[2] + c.d[j][2]}; }

std::vector<Rows::Entry> mass_row(const geometry::SpatialBody& b, std::size_t d) {
  std::vector<Rows::Entry> e;
  if (d < 3) return {{d, b.mass}};
  for (std::size_t c = 0; c < 3; ++c)
    if (sgn(b.inertia[d - 3][c]) != 0) e.push_back({3 + c, b.inertia[d - 3][c]});
  return e;
}

Rows motion_rows(const geometry::SpatialBody& body, const std::vector<Seen>& cs, const std::string& mode,
                 const Vec<Q>& g, bool zero_acceleration) {
  Rows R;
  if (!zero_acceleration) R = prefix_rows(cs, mode);
  const std::size_t first = R.rows.size();
  for (std::size_t d = 0; d < 6; ++d)
    R.rows.push_back(zero_acceleration ? std::vector<Rows::Entry>{} : mass_row(body, d));
  for (std::size_t i = 0; i < cs.size(); ++i)
    for (const std::size_t j : allowed(cs[i].d.size(), mode[i])) {
      const std::size_t col = R.columns.size();
      R.columns.push_back(Rows::Sign::kNonNegative);
      for (const Rows::Entry& e : along(cs[i], edge_force(cs[i], j))) R.rows[first + e.col].push_back({col, -e.value});
    }
  R.b = Vec<Q>::Zero(static_cast<Eigen::Index>(R.rows.size()));
  R.b.tail(6) = g;
  return R;
}

}  // namespace contactcert::checker::spatial_check
