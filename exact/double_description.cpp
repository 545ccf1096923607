#include "exact/double_description.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <numeric>
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
// pairs by the combinatorial test (Fukuda-Prodon). Rays and lines are the rows of integer matrices
// (int_matrix.h: contiguous, the rays' matrix with spare rows for new rays), the rays' zero sets bitsets
// over processed rows in a flat array; the scratch lists are reused from row to row.
template <class R>
class DoubleDescription {
 public:
  DoubleDescription(Index k, std::size_t rows, const DdBudget& budget)
      : k_(k),
        rows_(rows),
        words_((rows + 63) / 64),
        budget_(budget),
        coord_(0, k),
        lines_(k, k),
        common_(words_),
        tmp_(static_cast<size_t>(k)),
        line_(static_cast<size_t>(k)) {
    for (Index i = 0; i < k; ++i) lines_(i, i) = R(1);
  }

  // The orthant { y >= 0 } of R^k as the state after its k rows -e_1, ..., -e_k (and before `rows` more):
  // no lines, the rays e_1, ..., e_k, ray e_j tight on every one of those rows but the j-th.
  struct Orthant {};
  DoubleDescription(Index k, std::size_t rows, const DdBudget& budget, Orthant)
      : k_(k),
        rows_(static_cast<std::size_t>(k) + rows),
        words_((rows_ + 63) / 64),
        budget_(budget),
        coord_(0, k),
        lines_(0, k),
        common_(words_),
        tmp_(static_cast<size_t>(k)),
        line_(static_cast<size_t>(k)) {
    for (std::size_t j = 0; j < static_cast<std::size_t>(k); ++j) {
      const std::size_t id = push_ray(j);
      R* y = ray(id);
      std::fill_n(y, k_, R(0));
      y[j] = R(1);
      for (std::size_t u = 0; u < static_cast<std::size_t>(k); ++u)
        if (u != j) set_bit(id, u);
    }
    processed_ = static_cast<std::size_t>(k);
  }

  // If some line l has a . l != 0: intersects the cone with { a . y <= 0 } (or = 0) by removing l, and
  // returns true; false (nothing done) if a is orthogonal to every line.
  bool reduce_lineality(const R* a, bool equality) {
    const Index nl = lines_.rows();
    line_values_.resize(static_cast<std::size_t>(nl));
    Index piv = nl;
    for (Index i = 0; i < nl; ++i) {
      R& value = line_values_[static_cast<std::size_t>(i)];
      rg::dot(a, lines_.row(i), k_, value);
      if (rg::sign(value) != 0 && (piv == nl || rg::better_pivot(value, line_values_[static_cast<std::size_t>(piv)])))
        piv = i;
    }
    if (piv == nl) return false;
    const std::size_t t = processed_++;
    std::vector<R>& l = line_;
    std::swap_ranges(lines_.row(piv), lines_.row(piv) + k_, l.begin());
    const R al = line_values_[static_cast<std::size_t>(piv)];
    lines_.erase_row(piv);
    line_values_.erase(line_values_.begin() + static_cast<std::ptrdiff_t>(piv));
    // y <- (a . l) y - (a . y) l: a . y = 0 afterwards (times -1 for a ray when a . l < 0).
    for (Index i = 0; i < lines_.rows(); ++i) {
      const R& value = line_values_[static_cast<std::size_t>(i)];
      if (rg::sign(value) == 0) continue;
      rg::combine(l.data(), al, lines_.row(i), value, tmp_.data(), k_);
      std::swap_ranges(tmp_.begin(), tmp_.end(), lines_.row(i));
      rg::normalize(lines_.row(i), k_);
    }
    R v;
    for (std::size_t r = 0; r < count_; ++r) {
      R* y = ray(r);
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
      R* y = ray(id);
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
        coord_(static_cast<Index>(o.count_), o.k_),
        bits_(o.bits_),
        lines_(o.lines_.rows(), o.k_),
        common_(words_),
        tmp_(static_cast<size_t>(k_)),
        line_(static_cast<size_t>(k_)) {
    for (Index i = 0; i < coord_.rows(); ++i)
      for (Index j = 0; j < k_; ++j) rg::from_integer(static_cast<long>(o.coord_(i, j)), coord_(i, j));
    for (Index i = 0; i < lines_.rows(); ++i)
      for (Index j = 0; j < k_; ++j) rg::from_integer(static_cast<long>(o.lines_(i, j)), lines_(i, j));
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
      rg::dot(a, ray(r), k_, v);
      if (rg::sign(v) > 0) ++cut;
    }
    return cut;
  }

  std::size_t count() const { return count_; }
  /// The rays (count() rows) and lines of the cone, taken out of the iteration (which is left without them).
  RingGenerators<R> take_generators() {
    coord_.resize_rows(static_cast<Index>(count_));
    count_ = 0;
    return {std::move(coord_), std::move(lines_)};
  }

 private:
  template <class>
  friend class DoubleDescription;

  void intersect(const R* a, bool equality, std::size_t t, std::size_t n) {
    if (values_.size() < n) values_.resize(n);
    plus_.clear();
    minus_.clear();
    keep_.clear();
    for (std::size_t r = 0; r < n; ++r) {
      rg::dot(a, ray(r), k_, values_[r]);
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
    const std::size_t free_dim = static_cast<std::size_t>(k_ - lines_.rows());
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
        rg::combine(ray(p), values_[p], ray(m), values_[m], ray(id), k_);
        rg::normalize(ray(id), k_);
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
      coord_.swap_rows(static_cast<Index>(i), static_cast<Index>(from));
      for (std::size_t w = 0; w < words_; ++w) bits_[i * words_ + w] = bits_[from * words_ + w];
    }
    count_ = keep_.size();
  }

  R* ray(std::size_t r) { return coord_.row(static_cast<Index>(r)); }
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
    if (static_cast<std::size_t>(coord_.rows()) < count_) coord_.resize_rows(static_cast<Index>(count_ * 2));
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
  IntMatrix<R> coord_;  // the rays in rows [0, count_); the rows below are storage for new rays
  std::vector<std::uint64_t> bits_;
  IntMatrix<R> lines_;
  std::vector<R> line_values_;
  std::vector<R> values_;
  std::vector<std::size_t> plus_, minus_, keep_;
  std::vector<std::uint64_t> common_;
  std::vector<std::vector<std::uint32_t>> tight_;
  std::vector<std::uint64_t> tight_bits_;
  std::vector<bool> has_tight_bits_;
  std::size_t ray_words_ = 0;
  std::vector<const std::uint64_t*> common_rows_;
  std::vector<R> tmp_, line_;
};

// Sorts the row numbers `which` of M by M's rows, lexicographically (the order of std::vector<R>'s <).
template <class R>
void lex_sort(const IntMatrix<R>& M, std::vector<Index>& which) {
  const Index k = M.cols();
  std::sort(which.begin(), which.end(), [&](Index a, Index b) {
    return std::lexicographical_compare(M.row(a), M.row(a) + k, M.row(b), M.row(b) + k);
  });
}

// R^3: an extreme ray of the pointed cone { y : a . y <= 0 } is tight on two independent rows, so it is
// +-(a_i x a_j) for a pair that keeps every row <= 0; no simplicial start, no DD. Normalized rays in
// lexicographic order, one per ray (rays equal by R's sign test: an exact ring's equality, a float
// ring's tolerance); nullopt if the rows have rank < 3.
template <class R>
std::optional<IntMatrix<R>> pointed_extreme_rays_3d(const IntMatrix<R>& rows, const DdBudget& budget) {
  const Index n = rows.rows();
  IntMatrix<R> out(0, 3);
  R c[3];
  R x;
  bool full_rank = false;
  WorkMeter meter(budget);
  for (Index i = 0; i < n; ++i)
    for (Index j = i + 1; j < n; ++j) {
      meter.charge(static_cast<std::uint64_t>(n),
                   [&] { return std::to_string(i) + " of " + std::to_string(n) + " rows paired"; });
      const R *a = rows.row(i), *b = rows.row(j);
      for (std::size_t t = 0; t < 3; ++t) {  // c_t = a_{t+1} b_{t+2} - a_{t+2} b_{t+1}
        const std::size_t u = (t + 1) % 3, v = (t + 2) % 3;
        rg::combine(&b[u], a[u], &b[v], a[v], &c[t], 1);
      }
      if (rg::sign(c[0]) == 0 && rg::sign(c[1]) == 0 && rg::sign(c[2]) == 0) continue;
      int side = 0;
      bool ray = true;
      for (Index l = 0; l < n && ray; ++l) {
        rg::dot(rows.row(l), c, 3, x);
        const int s = rg::sign(x);
        if (s == 0) continue;
        full_rank = true;
        if (side == 0) side = s;
        ray = side == s;
      }
      if (!ray || side == 0) continue;
      if (side > 0)
        for (R& e : c) e = negated(e);
      rg::normalize(c, 3);
      const auto same = [&](Index o) {
        for (Index t = 0; t < 3; ++t)
          if (rg::sign(rg::sub(out(o, t), c[t])) != 0) return false;
        return true;
      };
      bool is_new = true;
      for (Index o = 0; o < out.rows() && is_new; ++o) is_new = !same(o);
      if (is_new) out.append_row(c);
    }
  if (!full_rank) return std::nullopt;
  std::vector<Index> order(static_cast<std::size_t>(out.rows()));
  std::iota(order.begin(), order.end(), Index{0});
  lex_sort(out, order);
  out = out.select_rows(order);
  if (static_cast<std::size_t>(out.rows()) > budget.max_rays)
    throw BudgetExceeded("double description: more than " + std::to_string(budget.max_rays) + " rays",
                         std::to_string(out.rows()) + " rays");
  return out;
}

// Adds the rows A[i], i in `rest` (each orthogonal to every line of dd), in the given order, taking each
// out of `rest` once it is in. The cutoff orders look at every row left before each step (cddlib's
// MinCutoff / MaxCutoff). On RingOverflow, dd and `rest` are as they were before the row that overflowed.
template <class R>
void add_in_order(DoubleDescription<R>& dd, const IntMatrix<R>& A, std::vector<Index>& rest, RowOrder order) {
  const bool fewest = order == RowOrder::kMinCutoff;
  while (!rest.empty()) {
    std::size_t next = order == RowOrder::kLexMax ? rest.size() - 1 : 0;  // a position in rest
    if (fewest || order == RowOrder::kMaxCutoff) {
      std::size_t best = 0;
      for (std::size_t p = 0; p < rest.size(); ++p) {
        const std::size_t cut = dd.cutoff(A.row(rest[p]));
        if (p == 0 || (fewest ? cut < best : cut > best)) next = p, best = cut;
        if (fewest ? best == 0 : best == dd.count()) break;  // nothing better is left
      }
    }
    dd.add_row(A.row(rest[next]), false);
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(next));
  }
}

// A run in std::int64_t that overflowed with the rows A[i], i in `rest`, still to add (and was left as
// before the row that overflowed) goes on in Z from there: the rows before are not processed again.
RingGenerators<Z> finish_in_z(const DoubleDescription<std::int64_t>& fixed, const IntMatrix<std::int64_t>& A,
                              std::vector<Index> rest, RowOrder order) {
  DoubleDescription<Z> dd(fixed);
  IntMatrix<Z> wide(A.rows(), A.cols());
  for (Index i : rest)
    for (Index j = 0; j < A.cols(); ++j) rg::from_integer(static_cast<long>(A(i, j)), wide(i, j));
  add_in_order(dd, wide, rest, order);
  return dd.take_generators();
}

// Generators in Z as std::int64_t rows; RingOverflow if an entry does not fit (the caller then
// restarts in Z).
RingGenerators<std::int64_t> narrowed(const RingGenerators<Z>& g) {
  auto narrow = [](const IntMatrix<Z>& rows) {
    IntMatrix<std::int64_t> out(rows.rows(), rows.cols());
    for (Index i = 0; i < rows.rows(); ++i)
      for (Index j = 0; j < rows.cols(); ++j) rg::from_integer(rows(i, j), out(i, j));
    return out;
  };
  return {narrow(g.rays), narrow(g.lines)};
}

// Adds the rows A[i], i in `later`, to dd in the given order and returns its generators; a run in
// std::int64_t that overflows goes on in Z.
template <class R>
RingGenerators<R> finish(DoubleDescription<R>& dd, const IntMatrix<R>& A, std::vector<Index> later, RowOrder order) {
  if constexpr (std::is_same_v<R, std::int64_t>) {
    try {
      add_in_order(dd, A, later, order);
    } catch (const RingOverflow&) {
      return narrowed(finish_in_z(dd, A, std::move(later), order));
    }
  } else {
    add_in_order(dd, A, later, order);
  }
  return dd.take_generators();
}

// The double description of { y : A y <= 0, E y = 0 } for sorted rows: the equalities first, then the
// inequalities that lower the lineality (a basis of what is left, the greedy choice in order), then the
// others in budget.order.
template <class R>
RingGenerators<R> generators_of_sorted(const IntMatrix<R>& A, const IntMatrix<R>& E, const DdBudget& budget) {
  DoubleDescription<R> dd(A.cols(), static_cast<std::size_t>(A.rows() + E.rows()), budget);
  for (Index i = 0; i < E.rows(); ++i)
    if (!dd.reduce_lineality(E.row(i), true)) dd.add_row(E.row(i), true);
  std::vector<Index> later;
  for (Index i = 0; i < A.rows(); ++i)
    if (!dd.reduce_lineality(A.row(i), false)) later.push_back(i);
  return finish(dd, A, std::move(later), budget.order);
}

}  // namespace

template <class R>
void sort_rows(IntMatrix<R>& rows) {
  const Index k = rows.cols();
  std::vector<Index> order;
  for (Index i = 0; i < rows.rows(); ++i)
    if (std::any_of(rows.row(i), rows.row(i) + k, [](const R& x) { return rg::sign(x) != 0; })) order.push_back(i);
  lex_sort(rows, order);
  order.erase(std::unique(order.begin(), order.end(),
                          [&](Index a, Index b) { return std::equal(rows.row(a), rows.row(a) + k, rows.row(b)); }),
              order.end());
  rows = rows.select_rows(order);
}

template <class R>
RingGenerators<R> cone_generators(IntMatrix<R> A, IntMatrix<R> E, const DdBudget& budget) {
  sort_rows(A);
  sort_rows(E);
  if (A.cols() == 3 && E.rows() == 0)
    if (auto rays = pointed_extreme_rays_3d<R>(A, budget)) return {std::move(*rays), IntMatrix<R>(0, 3)};
  return generators_of_sorted<R>(A, E, budget);
}

template <class R>
IntMatrix<R> orthant_rays(const IntMatrix<R>& A, const DdBudget& budget) {
  DoubleDescription<R> dd(A.cols(), static_cast<std::size_t>(A.rows()), budget,
                          typename DoubleDescription<R>::Orthant{});
  std::vector<Index> rows(static_cast<std::size_t>(A.rows()));
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = static_cast<Index>(i);
  return finish(dd, A, std::move(rows), RowOrder::kLexMin).rays;  // rows[0] first: as given
}

template <class R>
std::optional<IntMatrix<R>> pointed_cone_rays(IntMatrix<R> rows, const DdBudget& budget) {
  const Index k = rows.cols();
  RingGenerators<R> g = cone_generators<R>(std::move(rows), IntMatrix<R>(0, k), budget);
  if (g.lines.rows() != 0) return std::nullopt;
  return std::move(g.rays);
}

#define CONTACTCERT_DD_RING_INSTANTIATE(R)                                                    \
  template RingGenerators<R> cone_generators<R>(IntMatrix<R>, IntMatrix<R>, const DdBudget&); \
  template std::optional<IntMatrix<R>> pointed_cone_rays<R>(IntMatrix<R>, const DdBudget&);   \
  template void sort_rows<R>(IntMatrix<R>&);                                                  \
  template IntMatrix<R> orthant_rays<R>(const IntMatrix<R>&, const DdBudget&);
CONTACTCERT_DD_RING_INSTANTIATE(double)
CONTACTCERT_DD_RING_INSTANTIATE(std::int64_t)
CONTACTCERT_DD_RING_INSTANTIATE(Z)
CONTACTCERT_DD_RING_INSTANTIATE(Mpfr)
CONTACTCERT_DD_RING_INSTANTIATE(Interval)
#undef CONTACTCERT_DD_RING_INSTANTIATE

}  // namespace contactcert::exact
