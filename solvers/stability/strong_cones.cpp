#include "solvers/stability/strong_cones.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <numeric>

namespace contactcert::solvers {
namespace {

using Index = Eigen::Index;

/// A set of cells of the region, one bit per cell.
using Cells = std::vector<std::uint64_t>;

Cells& operator&=(Cells& a, const Cells& b) {
  for (std::size_t w = 0; w < a.size(); ++w) a[w] &= b[w];
  return a;
}
Cells& operator|=(Cells& a, const Cells& b) {
  for (std::size_t w = 0; w < a.size(); ++w) a[w] |= b[w];
  return a;
}
bool subset(const Cells& a, const Cells& b) {
  for (std::size_t w = 0; w < a.size(); ++w)
    if (a[w] & ~b[w]) return false;
  return true;
}
void set_bit(Cells& a, std::size_t i) { a[i / 64] |= std::uint64_t{1} << (i % 64); }
bool has_bit(const Cells& a, std::size_t i) { return (a[i / 64] >> (i % 64)) & 1U; }

/// A pattern letter as the set of signs it allows: bit 0 for -, bit 1 for 0, bit 2 for +. Convex sign sets
/// only: {-}, {0}, {+}, {-, 0}, {0, +} and all.
constexpr unsigned kMinus = 1, kZero = 2, kPlus = 4, kAll = 7;
constexpr unsigned kRelaxOrder[] = {kAll, kMinus | kZero, kZero | kPlus};

char letter(unsigned s) {
  switch (s) {
    case kMinus:
      return '-';
    case kZero:
      return '0';
    case kPlus:
      return '+';
    case kMinus | kZero:
      return 'N';
    case kZero | kPlus:
      return 'P';
    default:
      return '*';
  }
}

/// The cells of the region by the sign each plane gives them.
struct CellIndex {
  std::size_t words = 0;
  std::vector<std::array<Cells, 3>> by_sign;  ///< [plane][sign + 1]
  Cells strong;

  explicit CellIndex(const StableRegion<Q>& region) : words((region.cells.size() + 63) / 64) {
    by_sign.assign(static_cast<std::size_t>(region.planes.rows()), {Cells(words, 0), Cells(words, 0), Cells(words, 0)});
    strong.assign(words, 0);
    for (std::size_t i = 0; i < region.cells.size(); ++i) {
      const std::string s = sign_vector(region, region.cells[i].point);
      for (std::size_t j = 0; j < s.size(); ++j) set_bit(by_sign[j][s[j] == '-' ? 0 : s[j] == '0' ? 1 : 2], i);
      if (region.cells[i].label == StabilityVerdict::kStronglyStable) set_bit(strong, i);
    }
  }

  /// The cells a pattern (one sign set per plane) contains.
  Cells cells(const std::vector<unsigned>& pattern) const {
    Cells out(words, ~std::uint64_t{0});
    for (std::size_t j = 0; j < pattern.size(); ++j) {
      if (pattern[j] == kAll) continue;
      Cells allowed(words, 0);
      for (unsigned s = 0; s < 3; ++s)
        if (pattern[j] >> s & 1U) allowed |= by_sign[j][s];
      out &= allowed;
    }
    return out;
  }
};

/// The smallest pattern containing the cells `c`: at each plane the signs they take (with 0 between + and -).
std::vector<unsigned> hull(const CellIndex& index, const Cells& c) {
  std::vector<unsigned> p;
  for (const auto& signs : index.by_sign) {
    unsigned s = 0;
    for (unsigned k = 0; k < 3; ++k) {
      Cells both = signs[k];
      both &= c;
      if (std::any_of(both.begin(), both.end(), [](std::uint64_t w) { return w != 0; })) s |= 1U << k;
    }
    p.push_back(s == (kMinus | kPlus) ? kAll : s);
  }
  return p;
}

/// A pattern relaxed letter by letter, largest sign set first, while it holds only strongly stable cells;
/// repeated until no letter relaxes.
std::vector<unsigned> maximal_pattern(const CellIndex& index, std::vector<unsigned> p) {
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t j = 0; j < p.size(); ++j)
      for (unsigned relaxed : kRelaxOrder) {
        if (relaxed == p[j] || (relaxed & p[j]) != p[j]) continue;
        const unsigned was = p[j];
        p[j] = relaxed;
        if (subset(index.cells(p), index.strong)) {
          changed = true;
          break;
        }
        p[j] = was;
      }
  }
  return p;
}

Mat<Q> stack(const std::vector<Vec<Q>>& rows) {
  Mat<Q> M(static_cast<Index>(rows.size()), 3);
  for (std::size_t i = 0; i < rows.size(); ++i) M.row(static_cast<Index>(i)) = rows[i].transpose();
  return M;
}

/// The face form of a pattern: + and - strict, P and N inequalities, 0 equalities (F g <= 0, S g < 0, E g = 0).
SignCone sign_cone(const StableRegion<Q>& region, const std::vector<unsigned>& p) {
  std::vector<Vec<Q>> F, E, S;
  std::string text;
  for (std::size_t j = 0; j < p.size(); ++j) {
    const Vec<Q> row = region.planes.row(static_cast<Index>(j)).transpose();
    text += letter(p[j]);
    if (p[j] == kPlus) S.push_back(-row);
    if (p[j] == kMinus) S.push_back(row);
    if (p[j] == (kZero | kPlus)) F.push_back(-row);
    if (p[j] == (kMinus | kZero)) F.push_back(row);
    if (p[j] == kZero) E.push_back(row);
  }
  return {text, geometry::FaceCone<Q>::from_rows(3, stack(F), stack(E), stack(S))};
}

}  // namespace

std::string sign_vector(const StableRegion<Q>& region, const Vec<Q>& g) {
  std::string s;
  for (Index j = 0; j < region.planes.rows(); ++j) {
    const int v = sgn(Q(region.planes.row(j).dot(g)));
    s += v > 0 ? '+' : v < 0 ? '-' : '0';
  }
  return s;
}

std::vector<SignCone> strongly_stable_cones(const StableRegion<Q>& region) {
  const CellIndex index(region);
  std::vector<std::size_t> seeds(region.cells.size());
  std::iota(seeds.begin(), seeds.end(), std::size_t{0});
  std::stable_sort(seeds.begin(), seeds.end(),
                   [&](std::size_t a, std::size_t b) { return region.cells[a].dimension > region.cells[b].dimension; });
  std::vector<std::vector<unsigned>> patterns;
  std::vector<Cells> covers;
  Cells covered(index.words, 0);
  for (std::size_t i : seeds) {
    if (!has_bit(index.strong, i) || has_bit(covered, i)) continue;
    Cells seed(index.words, 0);
    set_bit(seed, i);
    patterns.push_back(maximal_pattern(index, hull(index, seed)));
    covers.push_back(index.cells(patterns.back()));
    covered |= covers.back();
  }
  // Two cones whose union lies in a strongly stable pattern (their hull) become that pattern, maximal; until no
  // pair merges. The hull is the smallest pattern holding both, so a union that is itself a pattern merges.
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t a = 0; a < patterns.size() && !merged; ++a)
      for (std::size_t b = a + 1; b < patterns.size() && !merged; ++b) {
        Cells both = covers[a];
        both |= covers[b];
        const std::vector<unsigned> h = hull(index, both);
        if (!subset(index.cells(h), index.strong)) continue;
        patterns[a] = maximal_pattern(index, h);
        covers[a] = index.cells(patterns[a]);
        patterns.erase(patterns.begin() + static_cast<std::ptrdiff_t>(b));
        covers.erase(covers.begin() + static_cast<std::ptrdiff_t>(b));
        merged = true;
      }
  }
  // Drop every cone the others cover, smallest first.
  std::vector<std::size_t> order(patterns.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto count = [](const Cells& c) {
    long n = 0;
    for (auto w : c) n += std::popcount(w);
    return n;
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return count(covers[a]) < count(covers[b]); });
  std::vector<bool> kept(patterns.size(), true);
  for (std::size_t i : order) {
    Cells others(index.words, 0);
    for (std::size_t j = 0; j < patterns.size(); ++j)
      if (j != i && kept[j]) others |= covers[j];
    if (subset(covers[i], others)) kept[i] = false;
  }
  std::vector<SignCone> out;
  for (std::size_t i = 0; i < patterns.size(); ++i)
    if (kept[i]) out.push_back(sign_cone(region, patterns[i]));
  return out;
}

}  // namespace contactcert::solvers
