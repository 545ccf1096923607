#include "geometry/double_description.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/input_error.h"
#include "exact/ladder_numbers.h"
#include "exact/linalg.h"

namespace contactcert::geometry {
namespace {

using Index = Eigen::Index;
using exact::is_zero;

namespace rg = exact::ring;
using exact::Ring;

template <class T>
Mat<T> multiply(const Mat<T>& A, const Mat<T>& B) {
  Mat<T> C = Mat<T>::Zero(A.rows(), B.cols());
  for (Index i = 0; i < A.rows(); ++i)
    for (Index l = 0; l < A.cols(); ++l) {
      if (is_zero(A(i, l))) continue;
      for (Index j = 0; j < B.cols(); ++j) C(i, j) += A(i, l) * B(l, j);
    }
  return C;
}

// Scales the columns of M to primitive integers (Q) or unit max-norm (double); the cone described in
// the new coordinates is unchanged up to positive scaling of each coordinate.
template <class T>
void normalize_columns(Mat<T>& M) {
  using R = Ring<T>;
  std::vector<T> col(static_cast<size_t>(M.rows()));
  std::vector<R> r(static_cast<size_t>(M.rows()));
  for (Index j = 0; j < M.cols(); ++j) {
    for (Index i = 0; i < M.rows(); ++i) col[static_cast<size_t>(i)] = M(i, j);
    rg::to_ring(col.data(), M.rows(), r.data());
    for (Index i = 0; i < M.rows(); ++i) M(i, j) = rg::to_field<T>(r[static_cast<size_t>(i)]);
  }
}

// The adjacency work of a conversion against DdBudget::max_work and its deadline, checked every 2^20
// units; `covered()` says how far the run got when a limit is hit.
class WorkMeter {
 public:
  explicit WorkMeter(const DdBudget& budget) : budget_(budget) {}
  template <class Covered>
  void charge(std::uint64_t units, Covered covered) {
    work_ += units;
    if (work_ < next_check_) return;
    next_check_ = work_ + (std::uint64_t{1} << 20);
    if (work_ > budget_.max_work)
      throw exact::BudgetExceeded(
          "double description: more than " + std::to_string(budget_.max_work) + " units of adjacency work", covered());
    if (budget_.deadline.expired())
      throw exact::BudgetExceeded("double description: " + budget_.deadline.reached_text(), covered());
  }

 private:
  const DdBudget& budget_;
  std::uint64_t work_ = 0, next_check_ = 0;
};

// The double description iteration on a pointed cone { y in R^k : a_t . y <= 0 } whose rows have rank k,
// in the ring R (exact/fraction_free.h). Rays and their zero sets (bitsets over processed rows) are kept
// in flat arrays; the scratch lists are reused from row to row.
template <class R>
class DoubleDescription {
 public:
  DoubleDescription(Index k, std::size_t rows, const DdBudget& budget)
      : k_(k), rows_(rows), words_((rows + 63) / 64), budget_(budget), common_(words_) {}

  void add_initial_ray(const R* y, const std::vector<std::size_t>& zero_rows) {
    const std::size_t id = push_ray();
    std::copy(y, y + k_, &coord_[id * static_cast<size_t>(k_)]);
    for (auto t : zero_rows) bits_[id * words_ + t / 64] |= std::uint64_t{1} << (t % 64);
  }

  // Intersects the current cone with { a . y <= 0 }; `t` is the row's position (its bit).
  void add_row(const R* a, std::size_t t) {
    current_row_ = t;
    const std::size_t n = count_;
    if (values_.size() < n) values_.resize(n);
    plus_.clear();
    minus_.clear();
    keep_.clear();
    for (std::size_t r = 0; r < n; ++r) {
      rg::dot(a, &coord_[r * static_cast<size_t>(k_)], k_, values_[r]);
      const int s = rg::sign(values_[r]);
      if (s > 0) {
        plus_.push_back(r);
      } else {
        if (s < 0)
          minus_.push_back(r);
        else
          bits_[r * words_ + t / 64] |= std::uint64_t{1} << (t % 64);
        keep_.push_back(r);
      }
    }
    if (plus_.empty()) return;
    // New rays from adjacent (plus, minus) pairs: combinatorial test (Fukuda-Prodon).
    const std::size_t need = k_ >= 2 ? static_cast<std::size_t>(k_ - 2) : 0;
    const std::size_t first_created = count_;
    for (auto p : plus_) {
      charge(minus_.size(), t);
      for (auto m : minus_) {
        // (bits_ may grow below: index it afresh for every pair.)
        const std::uint64_t* bp = &bits_[p * words_];
        const std::uint64_t* bm = &bits_[m * words_];
        std::size_t pop = 0;
        for (std::size_t w = 0; w < words_; ++w) {
          common_[w] = bp[w] & bm[w];
          pop += static_cast<std::size_t>(std::popcount(common_[w]));
        }
        if (pop < need) continue;
        bool adjacent = true;
        std::size_t r = 0;
        for (; r < n && adjacent; ++r) {
          if (r == p || r == m) continue;
          const std::uint64_t* br = &bits_[r * words_];
          bool subset = true;
          for (std::size_t w = 0; w < words_ && subset; ++w) subset = (common_[w] & ~br[w]) == 0;
          if (subset) adjacent = false;
        }
        charge(r, t);
        if (!adjacent) continue;
        const std::size_t id = push_ray();
        rg::combine(&coord_[p * static_cast<size_t>(k_)], values_[p], &coord_[m * static_cast<size_t>(k_)], values_[m],
                    &coord_[id * static_cast<size_t>(k_)], k_);
        rg::normalize(&coord_[id * static_cast<size_t>(k_)], k_);
        for (std::size_t w = 0; w < words_; ++w) bits_[id * words_ + w] = common_[w];
        bits_[id * words_ + t / 64] |= std::uint64_t{1} << (t % 64);
      }
    }
    // Compact: kept rays, then created rays.
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

  std::size_t count() const { return count_; }
  const R* ray(std::size_t r) const { return &coord_[r * static_cast<size_t>(k_)]; }

 private:
  void charge(std::size_t units, std::size_t t) {
    meter_.charge(units, [&] { return covered(t); });
  }
  std::string covered(std::size_t t) const {
    return std::to_string(t) + " of " + std::to_string(rows_) + " rows processed, " + std::to_string(count_) + " rays";
  }

  std::size_t push_ray() {
    if (count_ >= budget_.max_rays)
      throw exact::BudgetExceeded("double description: more than " + std::to_string(budget_.max_rays) + " rays",
                                  covered(current_row_));
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
  std::size_t current_row_ = 0;
  std::size_t count_ = 0;
  std::vector<R> coord_;
  std::vector<std::uint64_t> bits_;
  std::vector<R> values_;
  std::vector<std::size_t> plus_, minus_, keep_;
  std::vector<std::uint64_t> common_;
};

// The extreme rays of the simplicial cone { y : B y <= 0 } for k independent rows B (ray j is tight on
// every row but j): y_j = -B^-1 e_j up to a positive factor, by fraction-free Gauss-Jordan elimination of
// [B^T | I] in the ring. Each row of the result reads u^T B^T = d e_j^T, i.e. B u = d e_j, so
// y_j = -sign(d) u. nullopt if a pivot vanishes (float path: B singular within the tolerance).
template <class R>
std::optional<std::vector<std::vector<R>>> simplicial_rays(const std::vector<const std::vector<R>*>& B, Index k) {
  const auto uk = static_cast<std::size_t>(k);
  std::vector<std::vector<R>> w(uk, std::vector<R>(2 * uk, R(0)));
  for (std::size_t i = 0; i < uk; ++i) {
    for (std::size_t j = 0; j < uk; ++j) w[i][j] = (*B[j])[i];
    w[i][uk + i] = R(1);
  }
  std::vector<std::size_t> pivot_row(uk);
  std::vector<bool> used(uk, false);
  std::vector<R> tmp(2 * uk);
  for (std::size_t c = 0; c < uk; ++c) {
    std::size_t p = uk;
    for (std::size_t i = 0; i < uk; ++i)
      if (!used[i] && rg::sign(w[i][c]) != 0 && (p == uk || rg::better_pivot(w[i][c], w[p][c]))) p = i;
    if (p == uk) return std::nullopt;
    used[p] = true;
    pivot_row[c] = p;
    for (std::size_t i = 0; i < uk; ++i) {
      if (i == p || rg::sign(w[i][c]) == 0) continue;
      // w_i <- piv * w_i - w_i[c] * w_p: zero in column c.
      const R piv = w[p][c], f = w[i][c];
      rg::combine(w[p].data(), piv, w[i].data(), f, tmp.data(), 2 * k);
      w[i].swap(tmp);
      w[i][c] = R(0);
      rg::normalize(w[i].data(), 2 * k);
    }
  }
  std::vector<std::vector<R>> rays(uk);
  for (std::size_t j = 0; j < uk; ++j) {
    const std::vector<R>& row = w[pivot_row[j]];
    rays[j].assign(row.begin() + k, row.end());
    if (rg::sign(row[j]) > 0)
      for (R& x : rays[j]) x = -x;
    rg::normalize(rays[j].data(), k);
  }
  return rays;
}

// R^3 (exact rings): an extreme ray of the pointed cone { y : a . y <= 0 } is tight on two independent
// rows, so it is +-(a_i x a_j) for a pair that keeps every row <= 0; no simplicial start, no DD.
// Primitive rays in lexicographic order; nullopt if the rows have rank < 3.
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
        for (R& e : c) e = -e;
      rg::normalize(c.data(), 3);
      out.push_back(c);
    }
  if (!full_rank) return std::nullopt;
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  if (out.size() > budget.max_rays)
    throw exact::BudgetExceeded("double description: more than " + std::to_string(budget.max_rays) + " rays",
                                std::to_string(out.size()) + " rays");
  return out;
}

// Extreme rays of { y in R^k : a . y <= 0 for every row a } if the rows have rank k (the cone is
// pointed), as ring vectors; nullopt if the rank is smaller.
template <class R>
std::optional<std::vector<std::vector<R>>> pointed_extreme_rays(const std::vector<std::vector<R>>& rows, Index k,
                                                                const DdBudget& budget) {
  if constexpr (std::is_integral_v<R> || std::is_same_v<R, Z>)  // exact rings; a float ring keeps the DD's tolerances
    if (k == 3) return pointed_extreme_rays_3d<R>(rows, budget);
  // Initial simplicial cone: k independent rows B (greedy, fraction-free elimination in the ring).
  std::vector<std::size_t> basis;
  {
    std::vector<std::vector<R>> reduced;
    std::vector<Index> pivot;
    std::vector<R> v(static_cast<size_t>(k)), tmp(static_cast<size_t>(k));
    for (std::size_t i = 0; i < rows.size() && static_cast<Index>(basis.size()) < k; ++i) {
      v = rows[i];
      for (std::size_t b = 0; b < reduced.size(); ++b) {
        const R& vp = v[static_cast<size_t>(pivot[b])];
        if (rg::sign(vp) == 0) continue;
        // v <- piv_b * v - v_p * row_b (zero in column p), kept small.
        const R pb = reduced[b][static_cast<size_t>(pivot[b])];
        const R vpc = vp;
        rg::combine(reduced[b].data(), pb, v.data(), vpc, tmp.data(), k);
        v.swap(tmp);
        rg::normalize(v.data(), k);
      }
      Index p = -1;
      for (Index j = 0; j < k; ++j)
        if (rg::sign(v[static_cast<size_t>(j)]) != 0 &&
            (p < 0 || rg::better_pivot(v[static_cast<size_t>(j)], v[static_cast<size_t>(p)])))
          p = j;
      if (p < 0) continue;
      reduced.push_back(v);
      pivot.push_back(p);
      basis.push_back(i);
    }
  }
  if (static_cast<Index>(basis.size()) < k) return std::nullopt;
  std::vector<std::size_t> order = basis;  // processing order: basis first
  {
    std::vector<bool> in_basis(rows.size(), false);
    for (auto b : basis) in_basis[b] = true;
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (!in_basis[i]) order.push_back(i);
  }
  std::vector<const std::vector<R>*> B;
  for (auto b : basis) B.push_back(&rows[b]);
  const auto initial = simplicial_rays<R>(B, k);
  if (!initial) return std::nullopt;  // float path only: independent for the ring test, singular for the elimination

  DoubleDescription<R> dd(k, rows.size(), budget);
  for (Index j = 0; j < k; ++j) {
    std::vector<std::size_t> zero_rows;
    for (Index i = 0; i < k; ++i)
      if (i != j) zero_rows.push_back(static_cast<std::size_t>(i));
    dd.add_initial_ray((*initial)[static_cast<size_t>(j)].data(), zero_rows);
  }
  for (std::size_t t = static_cast<std::size_t>(k); t < order.size(); ++t) dd.add_row(rows[order[t]].data(), t);
  std::vector<std::vector<R>> out;
  for (std::size_t r = 0; r < dd.count(); ++r) out.emplace_back(dd.ray(r), dd.ray(r) + k);
  return out;
}

}  // namespace

template <class R>
std::optional<std::vector<std::vector<R>>> pointed_cone_rays(std::vector<std::vector<R>> rows, Index k,
                                                             const DdBudget& budget) {
  // Zero rows and duplicates dropped, lexicographic order (a fixed processing order).
  std::erase_if(rows, [](const std::vector<R>& r) {
    return std::all_of(r.begin(), r.end(), [](const R& x) { return rg::sign(x) == 0; });
  });
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return pointed_extreme_rays<R>(rows, k, budget);
}

template std::optional<std::vector<std::vector<double>>> pointed_cone_rays<double>(std::vector<std::vector<double>>,
                                                                                   Index, const DdBudget&);
template std::optional<std::vector<std::vector<std::int64_t>>> pointed_cone_rays<std::int64_t>(
    std::vector<std::vector<std::int64_t>>, Index, const DdBudget&);
template std::optional<std::vector<std::vector<Z>>> pointed_cone_rays<Z>(std::vector<std::vector<Z>>, Index,
                                                                         const DdBudget&);
template std::optional<std::vector<std::vector<exact::Mpfr>>> pointed_cone_rays<exact::Mpfr>(
    std::vector<std::vector<exact::Mpfr>>, Index, const DdBudget&);
template std::optional<std::vector<std::vector<exact::Interval>>> pointed_cone_rays<exact::Interval>(
    std::vector<std::vector<exact::Interval>>, Index, const DdBudget&);

namespace {

template <class T>
struct Generators {
  Mat<T> rays;
  Mat<T> lines;
};

// Extreme rays and lineality of { x in R^n : A x <= 0, E x = 0 }. The iteration runs in the exact ring
// std::int64_t and restarts in Z if a number outgrows it (T = Q), in double for T = double.
template <class T>
Generators<T> extreme_rays(const Mat<T>& A, const Mat<T>& E, Index n, const DdBudget& budget) {
  Generators<T> out;
  // Fast path: no equalities and rank A = n (pointed): no change of coordinates.
  if (E.rows() == 0) {
    std::optional<Mat<T>> rays = exact::with_exact_ring<T>([&]<class R>() -> std::optional<Mat<T>> {
      const auto y = pointed_cone_rays<R>(rg::to_ring_rows<R>(A), n, budget);
      if (!y) return std::nullopt;
      return rg::to_field_rows<T>(*y, n);
    });
    if (rays) {
      out.lines = Mat<T>(0, n);
      out.rays = std::move(*rays);
      return out;
    }
  }
  // Restrict to the subspace E x = 0, then split off the lineality space {x : A x = 0, E x = 0}.
  const Mat<T> V = E.rows() > 0 ? exact::null_space<T>(E) : Mat<T>(Mat<T>::Identity(n, n));
  const Mat<T> A1 = multiply<T>(A, V);
  const Index n1 = V.cols();
  const Mat<T> L1 = A1.rows() > 0 ? exact::null_space<T>(A1) : Mat<T>(Mat<T>::Identity(n1, n1));
  Mat<T> lines_by_column = multiply<T>(V, L1);
  normalize_columns<T>(lines_by_column);
  out.lines = lines_by_column.transpose();
  const Index k = n1 - L1.cols();
  out.rays = Mat<T>(0, n);
  if (k == 0) return out;
  // Coordinates y of a complement of the lineality space: x = M y, and { y : (A M) y <= 0 } is pointed.
  const Mat<T> W = L1.cols() > 0 ? exact::null_space<T>(Mat<T>(L1.transpose())) : Mat<T>(Mat<T>::Identity(n1, n1));
  Mat<T> M = multiply<T>(V, W);
  normalize_columns<T>(M);
  const Mat<T> AM = multiply<T>(A, M);
  out.rays = exact::with_exact_ring<T>([&]<class R>() {
    const auto rays = pointed_cone_rays<R>(rg::to_ring_rows<R>(AM), k, budget);
    if (!rays) throw std::logic_error("double description: rank deficient after removing the lineality space");
    // Back to x = M y, as primitive (Q) / unit max-norm (double) rows.
    Mat<T> X(static_cast<Index>(rays->size()), n);
    std::vector<T> x(static_cast<size_t>(n));
    std::vector<Ring<T>> xr(static_cast<size_t>(n));
    for (std::size_t r = 0; r < rays->size(); ++r) {
      const std::vector<R>& y = (*rays)[r];
      for (Index i = 0; i < n; ++i) {
        T s = T(0);
        for (Index j = 0; j < k; ++j)
          if (rg::sign(y[static_cast<size_t>(j)]) != 0) s += M(i, j) * rg::to_field<T>(y[static_cast<size_t>(j)]);
        x[static_cast<size_t>(i)] = s;
      }
      rg::to_ring(x.data(), n, xr.data());
      for (Index i = 0; i < n; ++i) X(static_cast<Index>(r), i) = rg::to_field<T>(xr[static_cast<size_t>(i)]);
    }
    return X;
  });
  return out;
}

}  // namespace

template <class T>
FaceCone<T> to_face(const SpanCone<T>& cone, const DdBudget& budget) {
  // Facets of C are the extreme rays of its polar { f : R f <= 0, L f = 0 }; the polar's lineality
  // space is the orthogonal complement of C's linear hull (the equalities).
  const Mat<T> lines = cone.lines.rows() == 0 ? Mat<T>(0, cone.dim) : cone.lines;
  const Mat<T> rays = cone.rays.rows() == 0 ? Mat<T>(0, cone.dim) : cone.rays;
  Generators<T> g = extreme_rays<T>(rays, lines, cone.dim, budget);
  return FaceCone<T>::from_rows(cone.dim, g.rays, g.lines, Mat<T>(0, cone.dim));
}

template <class T>
SpanCone<T> to_span(const FaceCone<T>& cone, const DdBudget& budget) {
  Mat<T> A(cone.inequalities.rows() + cone.strict.rows(), cone.dim);
  for (Index i = 0; i < cone.inequalities.rows(); ++i) A.row(i) = cone.inequalities.row(i);
  for (Index i = 0; i < cone.strict.rows(); ++i) A.row(cone.inequalities.rows() + i) = cone.strict.row(i);
  const Mat<T> E = cone.equalities.rows() == 0 ? Mat<T>(0, cone.dim) : cone.equalities;
  Generators<T> g = extreme_rays<T>(A, E, cone.dim, budget);
  return SpanCone<T>::from_rows(cone.dim, g.rays, g.lines);
}

template FaceCone<double> to_face<double>(const SpanCone<double>&, const DdBudget&);
template FaceCone<Q> to_face<Q>(const SpanCone<Q>&, const DdBudget&);
template SpanCone<double> to_span<double>(const FaceCone<double>&, const DdBudget&);
template SpanCone<Q> to_span<Q>(const FaceCone<Q>&, const DdBudget&);
template FaceCone<exact::Mpfr> to_face<exact::Mpfr>(const SpanCone<exact::Mpfr>&, const DdBudget&);
template FaceCone<exact::Interval> to_face<exact::Interval>(const SpanCone<exact::Interval>&, const DdBudget&);
template SpanCone<exact::Mpfr> to_span<exact::Mpfr>(const FaceCone<exact::Mpfr>&, const DdBudget&);
template SpanCone<exact::Interval> to_span<exact::Interval>(const FaceCone<exact::Interval>&, const DdBudget&);

}  // namespace contactcert::geometry
