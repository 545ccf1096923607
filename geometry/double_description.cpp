#include "geometry/double_description.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "exact/input_error.h"
#include "exact/linalg.h"

namespace contactcert::geometry {
namespace {

using Index = Eigen::Index;
using exact::is_zero;
using exact::NumberTraits;

// The ring the iteration runs in: Z (fraction-free) for the exact field Q, double for double.
template <class T>
using Ring = std::conditional_t<std::is_same_v<T, Q>, Z, double>;

int ring_sign(const Z& x) { return sgn(x); }
int ring_sign(double x) { return exact::sign(x); }

void dot(const Z* a, const Z* b, Index k, Z& out) {
  out = 0;
  for (Index i = 0; i < k; ++i) mpz_addmul(out.get_mpz_t(), a[i].get_mpz_t(), b[i].get_mpz_t());
}
void dot(const double* a, const double* b, Index k, double& out) {
  out = 0;
  for (Index i = 0; i < k; ++i) out += a[i] * b[i];
}

// Primitive integer vector (gcd 1) / unit max-norm vector: keeps entries small.
void normalize(Z* v, Index k) {
  Z g = 0;
  for (Index i = 0; i < k && g != 1; ++i) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), v[i].get_mpz_t());
  if (g > 1)
    for (Index i = 0; i < k; ++i) mpz_divexact(v[i].get_mpz_t(), v[i].get_mpz_t(), g.get_mpz_t());
}
void normalize(double* v, Index k) {
  // Entries below the sign tolerance are rounding noise of a cancellation: zero them before scaling
  // (scaling would blow them up).
  for (Index i = 0; i < k; ++i)
    if (exact::is_zero(v[i])) v[i] = 0;
  double m = 0;
  for (Index i = 0; i < k; ++i) m = std::max(m, std::abs(v[i]));
  if (m > 0)
    for (Index i = 0; i < k; ++i) v[i] /= m;
}

// out = ap * rm - am * rp with ap > 0 > am: a . out = 0 and out is a positive combination.
void combine(const Z* rp, const Z& ap, const Z* rm, const Z& am, Z* out, Index k) {
  for (Index i = 0; i < k; ++i) {
    mpz_mul(out[i].get_mpz_t(), ap.get_mpz_t(), rm[i].get_mpz_t());
    mpz_submul(out[i].get_mpz_t(), am.get_mpz_t(), rp[i].get_mpz_t());
  }
}
void combine(const double* rp, double ap, const double* rm, double am, double* out, Index k) {
  for (Index i = 0; i < k; ++i) out[i] = ap * rm[i] - am * rp[i];
}

// A field row as a ring row.
void to_ring(const Q* row, Index k, Z* out) {
  Z l = 1;
  for (Index i = 0; i < k; ++i) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), row[i].get_den_mpz_t());
  for (Index i = 0; i < k; ++i) {
    mpz_divexact(out[i].get_mpz_t(), l.get_mpz_t(), row[i].get_den_mpz_t());
    out[i] *= row[i].get_num();
  }
  normalize(out, k);
}
void to_ring(const double* row, Index k, double* out) {
  std::copy(row, row + k, out);
  normalize(out, k);
}
Q to_field(const Z& x, Q*) { return Q(x); }
double to_field(double x, double*) { return x; }

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
    to_ring(col.data(), M.rows(), r.data());
    for (Index i = 0; i < M.rows(); ++i) M(i, j) = to_field(r[static_cast<size_t>(i)], static_cast<T*>(nullptr));
  }
}

// The double description iteration on a pointed cone { y in R^k : a_t . y <= 0 } whose rows have rank k.
// Rays and their zero sets (bitsets over processed rows) are kept in flat arrays.
template <class R>
class DoubleDescription {
 public:
  DoubleDescription(Index k, std::size_t rows, std::size_t max_rays)
      : k_(k), words_((rows + 63) / 64), max_rays_(max_rays) {}

  void add_initial_ray(const R* y, const std::vector<std::size_t>& zero_rows) {
    const std::size_t id = push_ray();
    std::copy(y, y + k_, &coord_[id * static_cast<size_t>(k_)]);
    for (auto t : zero_rows) bits_[id * words_ + t / 64] |= std::uint64_t{1} << (t % 64);
  }

  // Intersects the current cone with { a . y <= 0 }; `t` is the row's position (its bit).
  void add_row(const R* a, std::size_t t) {
    const std::size_t n = count_;
    values_.resize(n);
    std::vector<std::size_t> plus, minus, keep;
    for (std::size_t r = 0; r < n; ++r) {
      dot(a, &coord_[r * static_cast<size_t>(k_)], k_, values_[r]);
      const int s = ring_sign(values_[r]);
      if (s > 0) {
        plus.push_back(r);
      } else {
        if (s < 0)
          minus.push_back(r);
        else
          bits_[r * words_ + t / 64] |= std::uint64_t{1} << (t % 64);
        keep.push_back(r);
      }
    }
    if (plus.empty()) return;
    // New rays from adjacent (plus, minus) pairs: combinatorial test (Fukuda-Prodon).
    std::vector<std::uint64_t> common(words_);
    const std::size_t need = k_ >= 2 ? static_cast<std::size_t>(k_ - 2) : 0;
    std::vector<std::size_t> created;
    for (auto p : plus) {
      for (auto m : minus) {
        // (bits_ may grow below: index it afresh for every pair.)
        const std::uint64_t* bp = &bits_[p * words_];
        const std::uint64_t* bm = &bits_[m * words_];
        std::size_t pop = 0;
        for (std::size_t w = 0; w < words_; ++w) {
          common[w] = bp[w] & bm[w];
          pop += static_cast<std::size_t>(std::popcount(common[w]));
        }
        if (pop < need) continue;
        bool adjacent = true;
        for (std::size_t r = 0; r < n && adjacent; ++r) {
          if (r == p || r == m) continue;
          const std::uint64_t* br = &bits_[r * words_];
          bool subset = true;
          for (std::size_t w = 0; w < words_ && subset; ++w) subset = (common[w] & ~br[w]) == 0;
          if (subset) adjacent = false;
        }
        if (!adjacent) continue;
        const std::size_t id = push_ray();
        combine(&coord_[p * static_cast<size_t>(k_)], values_[p], &coord_[m * static_cast<size_t>(k_)], values_[m],
                &coord_[id * static_cast<size_t>(k_)], k_);
        normalize(&coord_[id * static_cast<size_t>(k_)], k_);
        for (std::size_t w = 0; w < words_; ++w) bits_[id * words_ + w] = common[w];
        bits_[id * words_ + t / 64] |= std::uint64_t{1} << (t % 64);
        created.push_back(id);
      }
    }
    // Compact: kept rays, then created rays.
    keep.insert(keep.end(), created.begin(), created.end());
    for (std::size_t i = 0; i < keep.size(); ++i) {
      const std::size_t from = keep[i];
      if (from == i) continue;
      for (Index j = 0; j < k_; ++j)
        std::swap(coord_[i * static_cast<size_t>(k_) + static_cast<size_t>(j)],
                  coord_[from * static_cast<size_t>(k_) + static_cast<size_t>(j)]);
      for (std::size_t w = 0; w < words_; ++w) bits_[i * words_ + w] = bits_[from * words_ + w];
    }
    count_ = keep.size();
  }

  std::size_t count() const { return count_; }
  const R* ray(std::size_t r) const { return &coord_[r * static_cast<size_t>(k_)]; }

 private:
  std::size_t push_ray() {
    if (count_ >= max_rays_)
      throw exact::BudgetExceeded("double description: more than " + std::to_string(max_rays_) + " rays",
                                  std::to_string(count_) + " rays");
    const std::size_t id = count_++;
    if (coord_.size() < count_ * static_cast<size_t>(k_)) coord_.resize(count_ * static_cast<size_t>(k_) * 2);
    if (bits_.size() < count_ * words_) bits_.resize(count_ * words_ * 2);
    for (std::size_t w = 0; w < words_; ++w) bits_[id * words_ + w] = 0;
    return id;
  }

  Index k_;
  std::size_t words_;
  std::size_t max_rays_;
  std::size_t count_ = 0;
  std::vector<R> coord_;
  std::vector<std::uint64_t> bits_;
  std::vector<R> values_;
};

template <class T>
struct Generators {
  Mat<T> rays;
  Mat<T> lines;
};

// Ring rows of A, without zero rows and duplicates, in lexicographic order.
template <class T>
std::vector<std::vector<Ring<T>>> ring_rows(const Mat<T>& A) {
  using R = Ring<T>;
  const Index k = A.cols();
  std::vector<std::vector<R>> rows;
  std::vector<T> buf(static_cast<size_t>(k));
  std::vector<R> r(static_cast<size_t>(k));
  for (Index i = 0; i < A.rows(); ++i) {
    bool zero = true;
    for (Index j = 0; j < k; ++j) {
      buf[static_cast<size_t>(j)] = A(i, j);
      if (!is_zero(A(i, j))) zero = false;
    }
    if (zero) continue;
    to_ring(buf.data(), k, r.data());
    rows.push_back(r);
  }
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return rows;
}

// Extreme rays of { y in R^k : a . y <= 0 for every row a } if the rows have rank k (the cone is
// pointed), as ring vectors; nullopt if the rank is smaller.
template <class T>
std::optional<std::vector<std::vector<Ring<T>>>> pointed_extreme_rays(const std::vector<std::vector<Ring<T>>>& rows,
                                                                      Index k, const DdBudget& budget) {
  using R = Ring<T>;
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
        if (ring_sign(vp) == 0) continue;
        // v <- piv_b * v - v_p * row_b (zero in column p), kept small.
        const R pb = reduced[b][static_cast<size_t>(pivot[b])];
        const R vpc = vp;
        combine(reduced[b].data(), pb, v.data(), vpc, tmp.data(), k);
        v.swap(tmp);
        normalize(v.data(), k);
      }
      Index p = -1;
      for (Index j = 0; j < k; ++j)
        if (ring_sign(v[static_cast<size_t>(j)]) != 0 &&
            (p < 0 || NumberTraits<T>::better_pivot(to_field(v[static_cast<size_t>(j)], static_cast<T*>(nullptr)),
                                                    to_field(v[static_cast<size_t>(p)], static_cast<T*>(nullptr)))))
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
  Mat<T> B(k, k);
  for (Index i = 0; i < k; ++i)
    for (Index j = 0; j < k; ++j)
      B(i, j) = to_field(rows[basis[static_cast<size_t>(i)]][static_cast<size_t>(j)], static_cast<T*>(nullptr));
  const std::optional<Mat<T>> inv = exact::inverse<T>(B);
  if (!inv) return std::nullopt;  // float path only: independent for the ring test, singular for rref's tolerance
  const Mat<T>& Binv = *inv;

  DoubleDescription<R> dd(k, rows.size(), budget.max_rays);
  {
    std::vector<T> col(static_cast<size_t>(k));
    std::vector<R> y(static_cast<size_t>(k));
    for (Index j = 0; j < k; ++j) {
      for (Index i = 0; i < k; ++i) col[static_cast<size_t>(i)] = -Binv(i, j);
      to_ring(col.data(), k, y.data());
      std::vector<std::size_t> zero_rows;
      for (Index i = 0; i < k; ++i)
        if (i != j) zero_rows.push_back(static_cast<std::size_t>(i));
      dd.add_initial_ray(y.data(), zero_rows);
    }
  }
  for (std::size_t t = static_cast<std::size_t>(k); t < order.size(); ++t) dd.add_row(rows[order[t]].data(), t);
  std::vector<std::vector<R>> out;
  for (std::size_t r = 0; r < dd.count(); ++r) out.emplace_back(dd.ray(r), dd.ray(r) + k);
  return out;
}

// Extreme rays and lineality of { x in R^n : A x <= 0, E x = 0 }.
template <class T>
Generators<T> extreme_rays(const Mat<T>& A, const Mat<T>& E, Index n, const DdBudget& budget) {
  using R = Ring<T>;
  Generators<T> out;
  // Fast path: no equalities and rank A = n (pointed): no change of coordinates.
  if (E.rows() == 0) {
    const auto rays = pointed_extreme_rays<T>(ring_rows<T>(A), n, budget);
    if (rays) {
      out.lines = Mat<T>(0, n);
      out.rays = Mat<T>(static_cast<Index>(rays->size()), n);
      for (Index r = 0; r < out.rays.rows(); ++r)
        for (Index i = 0; i < n; ++i)
          out.rays(r, i) = to_field((*rays)[static_cast<size_t>(r)][static_cast<size_t>(i)], static_cast<T*>(nullptr));
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
  const auto rays = pointed_extreme_rays<T>(ring_rows<T>(multiply<T>(A, M)), k, budget);
  if (!rays) throw std::logic_error("double description: rank deficient after removing the lineality space");

  // Back to x = M y.
  out.rays = Mat<T>(static_cast<Index>(rays->size()), n);
  std::vector<T> x(static_cast<size_t>(n));
  std::vector<R> xr(static_cast<size_t>(n));
  for (std::size_t r = 0; r < rays->size(); ++r) {
    const std::vector<R>& y = (*rays)[r];
    for (Index i = 0; i < n; ++i) {
      T s = T(0);
      for (Index j = 0; j < k; ++j)
        if (ring_sign(y[static_cast<size_t>(j)]) != 0)
          s += M(i, j) * to_field(y[static_cast<size_t>(j)], static_cast<T*>(nullptr));
      x[static_cast<size_t>(i)] = s;
    }
    to_ring(x.data(), n, xr.data());
    for (Index i = 0; i < n; ++i)
      out.rays(static_cast<Index>(r), i) = to_field(xr[static_cast<size_t>(i)], static_cast<T*>(nullptr));
  }
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

}  // namespace contactcert::geometry
