#include "exact/double_description.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/ladder_numbers.h"

namespace contactcert::exact {
namespace {

using Index = Eigen::Index;

namespace rg = ring;

// -x, without a negative zero in a float ring (0 - x).
template <class R>
R negated(const R& x) {
  return R(0) - x;
}

// The double description iteration on { y in R^k : a . y <= 0 (inequality rows), a . y = 0 (equality
// rows) } in the ring R (exact/fraction_free.h), started from R^k itself: k lines, no rays. A row that is
// not orthogonal to every line removes one line l (reduce_lineality): the other lines and the rays move
// along l onto the row's hyperplane (their values on earlier rows stay: l is orthogonal to those rows),
// and for an inequality -sign(a . l) l becomes a ray, tight on every earlier row. A row orthogonal to
// every line is a step of Motzkin's iteration on the rays (add_row), new rays from adjacent (plus, minus)
// pairs by the combinatorial test (Fukuda-Prodon). Rays and their zero sets (bitsets over processed rows)
// are kept in flat arrays; the scratch lists are reused from row to row.
template <class R>
class DoubleDescription {
 public:
  DoubleDescription(Index k, std::size_t rows, const DdBudget& budget)
      : k_(k), rows_(rows), words_((rows + 63) / 64), budget_(budget), common_(words_), tmp_(static_cast<size_t>(k)) {
    for (Index i = 0; i < k; ++i) {
      lines_.emplace_back(static_cast<size_t>(k), R(0));
      lines_.back()[static_cast<size_t>(i)] = R(1);
    }
  }

  // The orthant { y >= 0 } of R^k as the state after its k rows -e_1, ..., -e_k (and before `rows` more):
  // no lines, the rays e_1, ..., e_k, ray e_j tight on every one of those rows but the j-th.
  struct Orthant {};
  DoubleDescription(Index k, std::size_t rows, const DdBudget& budget, Orthant)
      : k_(k),
        rows_(static_cast<std::size_t>(k) + rows),
        words_((rows_ + 63) / 64),
        budget_(budget),
        common_(words_),
        tmp_(static_cast<size_t>(k)) {
    for (std::size_t j = 0; j < static_cast<std::size_t>(k); ++j) {
      const std::size_t id = push_ray(j);
      std::fill_n(&coord_[id * static_cast<size_t>(k_)], k_, R(0));
      coord_[id * static_cast<size_t>(k_) + j] = R(1);
      for (std::size_t u = 0; u < static_cast<std::size_t>(k); ++u)
        if (u != j) set_bit(id, u);
    }
    processed_ = static_cast<std::size_t>(k);
  }

  // If some line l has a . l != 0: intersects the cone with { a . y <= 0 } (or = 0) by removing l, and
  // returns true; false (nothing done) if a is orthogonal to every line.
  bool reduce_lineality(const R* a, bool equality) {
    line_values_.resize(lines_.size());
    std::size_t piv = lines_.size();
    for (std::size_t i = 0; i < lines_.size(); ++i) {
      rg::dot(a, lines_[i].data(), k_, line_values_[i]);
      if (rg::sign(line_values_[i]) != 0 &&
          (piv == lines_.size() || rg::better_pivot(line_values_[i], line_values_[piv])))
        piv = i;
    }
    if (piv == lines_.size()) return false;
    const std::size_t t = processed_++;
    std::vector<R> l = std::move(lines_[piv]);
    const R al = line_values_[piv];
    lines_.erase(lines_.begin() + static_cast<std::ptrdiff_t>(piv));
    line_values_.erase(line_values_.begin() + static_cast<std::ptrdiff_t>(piv));
    // y <- (a . l) y - (a . y) l: a . y = 0 afterwards (times -1 for a ray when a . l < 0).
    for (std::size_t i = 0; i < lines_.size(); ++i) {
      if (rg::sign(line_values_[i]) == 0) continue;
      rg::combine(l.data(), al, lines_[i].data(), line_values_[i], tmp_.data(), k_);
      lines_[i].swap(tmp_);
      rg::normalize(lines_[i].data(), k_);
    }
    R v;
    for (std::size_t r = 0; r < count_; ++r) {
      R* y = &coord_[r * static_cast<size_t>(k_)];
      rg::dot(a, y, k_, v);
      set_bit(r, t);
      if (rg::sign(v) == 0) continue;
      rg::combine(l.data(), al, y, v, tmp_.data(), k_);
      if (rg::sign(al) < 0)
        for (R& x : tmp_) x = negated(x);
      std::copy(tmp_.begin(), tmp_.end(), y);
      rg::normalize(y, k_);
    }
    if (!equality) {
      const std::size_t id = push_ray(t);
      R* y = &coord_[id * static_cast<size_t>(k_)];
      for (Index j = 0; j < k_; ++j)
        y[j] = rg::sign(al) > 0 ? negated(l[static_cast<size_t>(j)]) : l[static_cast<size_t>(j)];
      for (std::size_t u = 0; u < t; ++u) set_bit(id, u);  // l is orthogonal to every earlier row
    }
    return true;
  }

  // The state of a run in the ring S, in R (std::int64_t to Z after an overflow): the run goes on
  // from there exactly as a run in R from the start would.
  template <class S>
  explicit DoubleDescription(const DoubleDescription<S>& o)
      : k_(o.k_),
        rows_(o.rows_),
        words_(o.words_),
        budget_(o.budget_),
        meter_(o.meter_),
        processed_(o.processed_),
        count_(o.count_),
        coord_(o.count_ * static_cast<size_t>(o.k_)),
        bits_(o.bits_),
        common_(words_),
        tmp_(static_cast<size_t>(k_)) {
    for (std::size_t i = 0; i < coord_.size(); ++i) rg::from_integer(static_cast<long>(o.coord_[i]), coord_[i]);
    for (const auto& l : o.lines_) {
      lines_.emplace_back(l.size());
      for (std::size_t j = 0; j < l.size(); ++j) rg::from_integer(static_cast<long>(l[j]), lines_.back()[j]);
    }
  }

  // Intersects the current cone with { a . y <= 0 } (or = 0) for a row orthogonal to every line. On
  // RingOverflow the cone is left as it was before the row.
  void add_row(const R* a, bool equality) {
    const std::size_t t = processed_++;
    const std::size_t n = count_;
    try {
      intersect(a, equality, t, n);
    } catch (const RingOverflow&) {
      count_ = n;
      processed_ = t;
      for (std::size_t r = 0; r < n; ++r) bits_[r * words_ + t / 64] &= ~(std::uint64_t{1} << (t % 64));
      throw;
    }
  }

  // The number of current rays that { a . y <= 0 } cuts off (a . y > 0), charged as work.
  std::size_t cutoff(const R* a) {
    charge(count_, processed_);
    std::size_t cut = 0;
    R v;
    for (std::size_t r = 0; r < count_; ++r) {
      rg::dot(a, &coord_[r * static_cast<size_t>(k_)], k_, v);
      if (rg::sign(v) > 0) ++cut;
    }
    return cut;
  }

  std::size_t count() const { return count_; }
  const R* ray(std::size_t r) const { return &coord_[r * static_cast<size_t>(k_)]; }
  const std::vector<std::vector<R>>& lines() const { return lines_; }

 private:
  template <class>
  friend class DoubleDescription;

  void intersect(const R* a, bool equality, std::size_t t, std::size_t n) {
    if (values_.size() < n) values_.resize(n);
    plus_.clear();
    minus_.clear();
    keep_.clear();
    for (std::size_t r = 0; r < n; ++r) {
      rg::dot(a, &coord_[r * static_cast<size_t>(k_)], k_, values_[r]);
      const int s = rg::sign(values_[r]);
      if (s > 0) {
        plus_.push_back(r);
      } else if (s < 0) {
        minus_.push_back(r);
        if (!equality) keep_.push_back(r);
      } else {
        set_bit(r, t);
        keep_.push_back(r);
      }
    }
    if (plus_.empty() && (!equality || minus_.empty())) return;
    const std::size_t first_created = count_;
    if (has_popcnt())
      new_rays_popcnt(t, n);
    else
      new_rays(t, n);
    compact(first_created);
  }

  // The CPU's popcount instruction (x86-64 before SSE4.2 lacks it: the generic build calls a software
  // routine, 3/4 of the time on degenerate inputs), checked once.
  static bool has_popcnt() {
#if defined(__x86_64__) && defined(__GNUC__)
    static const bool yes = (__builtin_cpu_init(), __builtin_cpu_supports("popcnt"));
    return yes;
#else
    return false;
#endif
  }
#if defined(__x86_64__) && defined(__GNUC__)
  [[gnu::target("popcnt")]] void new_rays_popcnt(std::size_t t, std::size_t n) { new_rays(t, n); }
#else
  void new_rays_popcnt(std::size_t t, std::size_t n) { new_rays(t, n); }
#endif

  // New rays from adjacent (plus, minus) pairs of the n rays before row t: combinatorial test
  // (Fukuda-Prodon). The 2-face of an adjacent pair has dimension 2 + #lines, so its rows have rank
  // k - 2 - #lines at least. (Inlined into both CPU variants.)
  [[gnu::always_inline]] inline void new_rays(std::size_t t, std::size_t n) {
    const std::size_t free_dim = static_cast<std::size_t>(k_) - lines_.size();
    const std::size_t need = free_dim >= 2 ? free_dim - 2 : 0;
    // Zero sets hold rows before t only: the words from `used` on are 0 in every ray and in common_
    // (used grows with t).
    const std::size_t used = (t + 63) / 64;
    index_tight_rays(t, n);
    for (auto p : plus_) {
      charge(minus_.size(), t);
      for (auto m : minus_) {
        // (bits_ may grow below: index it afresh for every pair.)
        const std::uint64_t* bp = &bits_[p * words_];
        const std::uint64_t* bm = &bits_[m * words_];
        std::size_t pop = 0;
        for (std::size_t w = 0; w < used; ++w) pop += static_cast<std::size_t>(std::popcount(bp[w] & bm[w]));
        if (pop < need) continue;
        for (std::size_t w = 0; w < used; ++w) common_[w] = bp[w] & bm[w];
        if (!adjacent(p, m, pop, n, t)) continue;
        const std::size_t id = push_ray(t);
        rg::combine(&coord_[p * static_cast<size_t>(k_)], values_[p], &coord_[m * static_cast<size_t>(k_)], values_[m],
                    &coord_[id * static_cast<size_t>(k_)], k_);
        rg::normalize(&coord_[id * static_cast<size_t>(k_)], k_);
        for (std::size_t w = 0; w < words_; ++w) bits_[id * words_ + w] = common_[w];
        set_bit(id, t);
      }
    }
  }

  // For each row u < t, the rays r < n tight on it, as a list (tight_[u]); as a bit set over the rays
  // (tight_bits_, ray_words_ words per row) on first use (tight_bits(u)). Row t is tight on no plus or
  // minus ray.
  [[gnu::always_inline]] inline void index_tight_rays(std::size_t t, std::size_t n) {
    ray_words_ = (n + 63) / 64;
    tight_.resize(t);
    for (auto& list : tight_) list.clear();
    has_tight_bits_.assign(t, false);
    if (tight_bits_.size() < t * ray_words_) tight_bits_.resize(t * ray_words_);
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t w = 0; w < words_; ++w)
        for (std::uint64_t b = bits_[r * words_ + w]; b != 0; b &= b - 1) {
          const std::size_t u = w * 64 + static_cast<std::size_t>(std::countr_zero(b));
          if (u < t) tight_[u].push_back(static_cast<std::uint32_t>(r));
        }
  }
  const std::uint64_t* tight_bits(std::size_t u) {
    std::uint64_t* row = &tight_bits_[u * ray_words_];
    if (!has_tight_bits_[u]) {
      std::fill(row, row + ray_words_, 0);
      for (std::uint32_t r : tight_[u]) row[r / 64] |= std::uint64_t{1} << (r % 64);
      has_tight_bits_[u] = true;
    }
    return row;
  }

  // The combinatorial test: plus ray p and minus ray m (of the n rays before row t) are adjacent iff no
  // other ray is tight on every row of their common zero set common_ (pop rows; a face is determined by
  // its zero set). Such a ray is tight on each common row: either the rays tight on the common row with
  // the fewest of them are looked at one by one (mostly a word each: a miss shows in the first words),
  // or the bit sets of the common rows are intersected (a word per row and 64 rays), whichever reads
  // fewer words (every ray is a candidate if there is no common row).
  [[gnu::always_inline]] inline bool adjacent(std::size_t p, std::size_t m, std::size_t pop, std::size_t n,
                                              std::size_t t) {
    const std::vector<std::uint32_t>* scan = nullptr;
    for (std::size_t w = 0; w < words_; ++w)
      for (std::uint64_t b = common_[w]; b != 0; b &= b - 1) {
        const std::vector<std::uint32_t>& list = tight_[w * 64 + static_cast<std::size_t>(std::countr_zero(b))];
        if (scan == nullptr || list.size() < scan->size()) scan = &list;
      }
    if (scan != nullptr && pop * (ray_words_ + 1) < scan->size()) {
      common_rows_.clear();
      for (std::size_t w = 0; w < words_; ++w)
        for (std::uint64_t b = common_[w]; b != 0; b &= b - 1)
          common_rows_.push_back(tight_bits(w * 64 + static_cast<std::size_t>(std::countr_zero(b))));
      for (std::size_t w = 0; w < ray_words_; ++w) {
        std::uint64_t witnesses = ~std::uint64_t{0};
        for (const std::uint64_t* row : common_rows_) witnesses &= row[w];
        if (w == p / 64) witnesses &= ~(std::uint64_t{1} << (p % 64));
        if (w == m / 64) witnesses &= ~(std::uint64_t{1} << (m % 64));
        if (witnesses != 0) {
          charge(64 * (w + 1), t);  // (rays looked at, 64 per word)
          return false;
        }
      }
      charge(64 * ray_words_, t);
      return true;
    }
    const std::size_t candidates = scan != nullptr ? scan->size() : n;
    for (std::size_t looked = 0; looked < candidates; ++looked) {
      const std::size_t r = scan != nullptr ? (*scan)[looked] : looked;
      if (r == p || r == m) continue;
      const std::uint64_t* br = &bits_[r * words_];
      bool subset = true;
      for (std::size_t w = 0; w < words_ && subset; ++w) subset = (common_[w] & ~br[w]) == 0;
      if (subset) {
        charge(looked + 1, t);
        return false;
      }
    }
    charge(candidates, t);
    return true;
  }

  // Keeps the rays listed in keep_, then the rays created from first_created on.
  void compact(std::size_t first_created) {
    for (std::size_t id = first_created; id < count_; ++id) keep_.push_back(id);
    for (std::size_t i = 0; i < keep_.size(); ++i) {
      const std::size_t from = keep_[i];
      if (from == i) continue;
      for (Index j = 0; j < k_; ++j)
        std::swap(coord_[i * static_cast<size_t>(k_) + static_cast<size_t>(j)],
                  coord_[from * static_cast<size_t>(k_) + static_cast<size_t>(j)]);
      for (std::size_t w = 0; w < words_; ++w) bits_[i * words_ + w] = bits_[from * words_ + w];
    }
    count_ = keep_.size();
  }

  void set_bit(std::size_t r, std::size_t t) { bits_[r * words_ + t / 64] |= std::uint64_t{1} << (t % 64); }
  void charge(std::size_t units, std::size_t t) {
    meter_.charge(units, [&] { return covered(t); });
  }
  std::string covered(std::size_t t) const {
    return std::to_string(t) + " of " + std::to_string(rows_) + " rows processed, " + std::to_string(count_) + " rays";
  }

  std::size_t push_ray(std::size_t t) {
    if (count_ >= budget_.max_rays || count_ >= UINT32_MAX)  // (tight_ holds 32-bit ray indices)
      throw BudgetExceeded("double description: more than " + std::to_string(budget_.max_rays) + " rays", covered(t));
    const std::size_t id = count_++;
    if (coord_.size() < count_ * static_cast<size_t>(k_)) coord_.resize(count_ * static_cast<size_t>(k_) * 2);
    if (bits_.size() < count_ * words_) bits_.resize(count_ * words_ * 2);
    for (std::size_t w = 0; w < words_; ++w) bits_[id * words_ + w] = 0;
    return id;
  }

  Index k_;
  std::size_t rows_;
  std::size_t words_;
  const DdBudget& budget_;
  WorkMeter meter_{budget_};
  std::size_t processed_ = 0;
  std::size_t count_ = 0;
  std::vector<R> coord_;
  std::vector<std::uint64_t> bits_;
  std::vector<std::vector<R>> lines_;
  std::vector<R> line_values_;
  std::vector<R> values_;
  std::vector<std::size_t> plus_, minus_, keep_;
  std::vector<std::uint64_t> common_;
  std::vector<std::vector<std::uint32_t>> tight_;
  std::vector<std::uint64_t> tight_bits_;
  std::vector<bool> has_tight_bits_;
  std::size_t ray_words_ = 0;
  std::vector<const std::uint64_t*> common_rows_;
  std::vector<R> tmp_;
};

// R^3: an extreme ray of the pointed cone { y : a . y <= 0 } is tight on two independent rows, so it is
// +-(a_i x a_j) for a pair that keeps every row <= 0; no simplicial start, no DD. Normalized rays in
// lexicographic order, one per ray (rays equal by R's sign test: an exact ring's equality, a float
// ring's tolerance); nullopt if the rows have rank < 3.
template <class R>
std::optional<std::vector<std::vector<R>>> pointed_extreme_rays_3d(const std::vector<std::vector<R>>& rows,
                                                                   const DdBudget& budget) {
  std::vector<std::vector<R>> out;
  std::vector<R> c(3);
  R x;
  bool full_rank = false;
  WorkMeter meter(budget);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = i + 1; j < rows.size(); ++j) {
      meter.charge(rows.size(),
                   [&] { return std::to_string(i) + " of " + std::to_string(rows.size()) + " rows paired"; });
      const std::vector<R>&a = rows[i], &b = rows[j];
      for (std::size_t t = 0; t < 3; ++t) {  // c_t = a_{t+1} b_{t+2} - a_{t+2} b_{t+1}
        const std::size_t u = (t + 1) % 3, v = (t + 2) % 3;
        rg::combine(&b[u], a[u], &b[v], a[v], &c[t], 1);
      }
      if (rg::sign(c[0]) == 0 && rg::sign(c[1]) == 0 && rg::sign(c[2]) == 0) continue;
      int side = 0;
      bool ray = true;
      for (std::size_t l = 0; l < rows.size() && ray; ++l) {
        rg::dot(rows[l].data(), c.data(), 3, x);
        const int s = rg::sign(x);
        if (s == 0) continue;
        full_rank = true;
        if (side == 0) side = s;
        ray = side == s;
      }
      if (!ray || side == 0) continue;
      if (side > 0)
        for (R& e : c) e = negated(e);
      rg::normalize(c.data(), 3);
      const auto same = [&](const std::vector<R>& o) {
        for (std::size_t t = 0; t < 3; ++t)
          if (rg::sign(rg::sub(o[t], c[t])) != 0) return false;
        return true;
      };
      if (std::none_of(out.begin(), out.end(), same)) out.push_back(c);
    }
  if (!full_rank) return std::nullopt;
  std::sort(out.begin(), out.end());
  if (out.size() > budget.max_rays)
    throw BudgetExceeded("double description: more than " + std::to_string(budget.max_rays) + " rays",
                         std::to_string(out.size()) + " rays");
  return out;
}

template <class R>
RingGenerators<R> generators(const DoubleDescription<R>& dd, Index k) {
  RingGenerators<R> out;
  out.lines = dd.lines();
  for (std::size_t r = 0; r < dd.count(); ++r) out.rays.emplace_back(dd.ray(r), dd.ray(r) + k);
  return out;
}

// Adds the rows A[i], i in `rest` (each orthogonal to every line of dd), in the given order, taking each
// out of `rest` once it is in. The cutoff orders look at every row left before each step (cddlib's
// MinCutoff / MaxCutoff). On RingOverflow, dd and `rest` are as they were before the row that overflowed.
template <class R>
void add_in_order(DoubleDescription<R>& dd, const std::vector<std::vector<R>>& A, std::vector<std::size_t>& rest,
                  RowOrder order) {
  const bool fewest = order == RowOrder::kMinCutoff;
  while (!rest.empty()) {
    std::size_t next = order == RowOrder::kLexMax ? rest.size() - 1 : 0;  // a position in rest
    if (fewest || order == RowOrder::kMaxCutoff) {
      std::size_t best = 0;
      for (std::size_t p = 0; p < rest.size(); ++p) {
        const std::size_t cut = dd.cutoff(A[rest[p]].data());
        if (p == 0 || (fewest ? cut < best : cut > best)) next = p, best = cut;
        if (fewest ? best == 0 : best == dd.count()) break;  // nothing better is left
      }
    }
    dd.add_row(A[rest[next]].data(), false);
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(next));
  }
}

// A run in std::int64_t that overflowed with the rows A[i], i in `rest`, still to add (and was left as
// before the row that overflowed) goes on in Z from there: the rows before are not processed again.
RingGenerators<Z> finish_in_z(const DoubleDescription<std::int64_t>& fixed,
                              const std::vector<std::vector<std::int64_t>>& A, std::vector<std::size_t> rest, Index k,
                              RowOrder order) {
  DoubleDescription<Z> dd(fixed);
  std::vector<std::vector<Z>> wide(A.size());
  for (std::size_t i : rest) {
    wide[i].resize(static_cast<size_t>(k));
    for (Index j = 0; j < k; ++j)
      rg::from_integer(static_cast<long>(A[i][static_cast<size_t>(j)]), wide[i][static_cast<size_t>(j)]);
  }
  add_in_order(dd, wide, rest, order);
  return generators(dd, k);
}

// Generators in Z as std::int64_t rows; RingOverflow if an entry does not fit (the caller then
// restarts in Z).
RingGenerators<std::int64_t> narrowed(const RingGenerators<Z>& g) {
  auto narrow = [](const std::vector<std::vector<Z>>& rows) {
    std::vector<std::vector<std::int64_t>> out(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
      out[i].resize(rows[i].size());
      for (std::size_t j = 0; j < rows[i].size(); ++j) rg::from_integer(rows[i][j], out[i][j]);
    }
    return out;
  };
  return {narrow(g.rays), narrow(g.lines)};
}

// Adds the rows A[i], i in `later`, to dd in the given order and returns its generators; a run in
// std::int64_t that overflows goes on in Z.
template <class R>
RingGenerators<R> finish(DoubleDescription<R>& dd, const std::vector<std::vector<R>>& A, std::vector<std::size_t> later,
                         Index k, RowOrder order) {
  if constexpr (std::is_same_v<R, std::int64_t>) {
    try {
      add_in_order(dd, A, later, order);
    } catch (const RingOverflow&) {
      return narrowed(finish_in_z(dd, A, std::move(later), k, order));
    }
  } else {
    add_in_order(dd, A, later, order);
  }
  return generators(dd, k);
}

// The double description of { y : A y <= 0, E y = 0 } for sorted rows: the equalities first, then the
// inequalities that lower the lineality (a basis of what is left, the greedy choice in order), then the
// others in budget.order.
template <class R>
RingGenerators<R> generators_of_sorted(const std::vector<std::vector<R>>& A, const std::vector<std::vector<R>>& E,
                                       Index k, const DdBudget& budget) {
  DoubleDescription<R> dd(k, A.size() + E.size(), budget);
  for (const auto& e : E)
    if (!dd.reduce_lineality(e.data(), true)) dd.add_row(e.data(), true);
  std::vector<std::size_t> later;
  for (std::size_t i = 0; i < A.size(); ++i)
    if (!dd.reduce_lineality(A[i].data(), false)) later.push_back(i);
  return finish(dd, A, std::move(later), k, budget.order);
}

}  // namespace

template <class R>
void sort_rows(std::vector<std::vector<R>>& rows) {
  std::erase_if(rows, [](const std::vector<R>& r) {
    return std::all_of(r.begin(), r.end(), [](const R& x) { return rg::sign(x) == 0; });
  });
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
}

template <class R>
RingGenerators<R> cone_generators(std::vector<std::vector<R>> A, std::vector<std::vector<R>> E, Index k,
                                  const DdBudget& budget) {
  sort_rows(A);
  sort_rows(E);
  if (k == 3 && E.empty())
    if (auto rays = pointed_extreme_rays_3d<R>(A, budget)) return {std::move(*rays), {}};
  return generators_of_sorted<R>(A, E, k, budget);
}

template <class R>
std::vector<std::vector<R>> orthant_rays(const std::vector<std::vector<R>>& A, Index k, const DdBudget& budget) {
  DoubleDescription<R> dd(k, A.size(), budget, typename DoubleDescription<R>::Orthant{});
  std::vector<std::size_t> rows(A.size());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = i;
  return finish(dd, A, std::move(rows), k, RowOrder::kLexMin).rays;  // rows[0] first: as given
}

template <class R>
std::optional<std::vector<std::vector<R>>> pointed_cone_rays(std::vector<std::vector<R>> rows, Index k,
                                                             const DdBudget& budget) {
  RingGenerators<R> g = cone_generators<R>(std::move(rows), {}, k, budget);
  if (!g.lines.empty()) return std::nullopt;
  return std::move(g.rays);
}

#define CONTACTCERT_DD_RING_INSTANTIATE(R)                                                                       \
  template RingGenerators<R> cone_generators<R>(std::vector<std::vector<R>>, std::vector<std::vector<R>>, Index, \
                                                const DdBudget&);                                                \
  template std::optional<std::vector<std::vector<R>>> pointed_cone_rays<R>(std::vector<std::vector<R>>, Index,   \
                                                                           const DdBudget&);                     \
  template void sort_rows<R>(std::vector<std::vector<R>>&);                                                      \
  template std::vector<std::vector<R>> orthant_rays<R>(const std::vector<std::vector<R>>&, Index, const DdBudget&);
CONTACTCERT_DD_RING_INSTANTIATE(double)
CONTACTCERT_DD_RING_INSTANTIATE(std::int64_t)
CONTACTCERT_DD_RING_INSTANTIATE(Z)
CONTACTCERT_DD_RING_INSTANTIATE(Mpfr)
CONTACTCERT_DD_RING_INSTANTIATE(Interval)
#undef CONTACTCERT_DD_RING_INSTANTIATE

}  // namespace contactcert::exact
