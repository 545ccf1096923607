#include "solvers/ucp/integer_rows.h"

#include <algorithm>
#include <utility>

#include "exact/fraction_free.h"

namespace contactcert::solvers::ucp {

namespace {

using exact::Int128;
using exact::Mat;
using exact::Q;
using exact::Z;
using Index = Eigen::Index;
namespace ring = exact::ring;

/// Divides v[0..k) by the positive gcd of its entries (all zero: unchanged).
template <class R>
void divide_by_gcd(R* v, Index k) {
  R g(0);
  for (Index i = 0; i < k && g != R(1); ++i)
    if (ring::sign(v[i]) != 0) g = ring::gcd(g, v[i]);
  if (ring::sign(g) == 0 || g == R(1)) return;
  for (Index i = 0; i < k; ++i) v[i] = ring::divexact(v[i], g);
}

template <class R>
R magnitude(const R& x) {
  return ring::sign(x) < 0 ? ring::sub(R(0), x) : x;
}

Z to_z(Int128 x) { return ring::to_z(x); }
const Z& to_z(const Z& x) { return x; }

/// out = x as a rational, without throwing (so that a restart in Z never sees half-written output).
void assign(Int128 x, Q& out) {
  if (x >= std::numeric_limits<long>::min() && x <= std::numeric_limits<long>::max())
    mpq_set_si(out.get_mpq_t(), static_cast<long>(x), 1);
  else
    out = Q(ring::to_z(x));
}
void assign(const Z& x, Q& out) { out = Q(x); }

/// left_null_rows in the ring R (Int128: throws RingOverflow when a number does not fit).
template <class R>
std::vector<SparseRow> left_null_rows_in(const Mat<Q>& P) {
  const Index n = P.rows(), m = P.cols();
  // A = P^T, each row (a column of P) scaled to primitive integers: the same null space.
  std::vector<R> A(static_cast<std::size_t>(m * n));
  const auto row_of = [&](Index i) { return A.data() + i * n; };
  for (Index k = 0; k < m; ++k) {
    ring::to_common_denominator<R>(
        n, [&](Index i) -> const Q& { return P(i, k); }, row_of(k));
    divide_by_gcd(row_of(k), n);
  }
  // Fraction-free Gauss-Jordan elimination: row i -= (a_i,col / a_row,col) row, scaled by a_row,col / g to stay
  // integral, then divided by its gcd. Afterwards row r is a positive or negative multiple of row r of the RREF.
  std::vector<Index> pivots;
  for (Index col = 0, row = 0; col < n && row < m; ++col) {
    Index p = row;
    while (p < m && ring::sign(row_of(p)[col]) == 0) ++p;
    if (p == m) continue;
    if (p != row) std::swap_ranges(row_of(p), row_of(p) + n, row_of(row));
    const R* pr = row_of(row);
    for (Index i = 0; i < m; ++i) {
      R* ri = row_of(i);
      if (i == row || ring::sign(ri[col]) == 0) continue;
      const R g = ring::gcd(pr[col], ri[col]);
      const R a = ring::divexact(pr[col], g), c = ring::divexact(ri[col], g);
      for (Index j = 0; j < n; ++j) ri[j] = ring::sub(ring::mul(a, ri[j]), ring::mul(c, pr[j]));
      divide_by_gcd(ri, n);
    }
    pivots.push_back(col);
    ++row;
  }
  // The null vector of free column f: z_f = 1, z_pivot(r) = -a_r,f / a_r,pivot(r); here times the lcm L of the
  // pivots that divide, then primitive.
  std::vector<bool> is_pivot(static_cast<std::size_t>(n), false);
  for (Index c : pivots) is_pivot[static_cast<std::size_t>(c)] = true;
  std::vector<SparseRow> rows;
  std::vector<std::pair<Index, R>> z;
  std::vector<R> values;
  for (Index f = 0; f < n; ++f) {
    if (is_pivot[static_cast<std::size_t>(f)]) continue;
    R L(1);
    for (std::size_t r = 0; r < pivots.size(); ++r)
      if (ring::sign(row_of(static_cast<Index>(r))[f]) != 0)
        L = ring::lcm(L, magnitude(row_of(static_cast<Index>(r))[pivots[r]]));
    z.assign(1, {f, L});
    for (std::size_t r = 0; r < pivots.size(); ++r) {
      const R* a = row_of(static_cast<Index>(r));
      if (ring::sign(a[f]) != 0)
        z.emplace_back(pivots[r], ring::sub(R(0), ring::mul(a[f], ring::divexact(L, a[pivots[r]]))));
    }
    std::sort(z.begin(), z.end(), [](const auto& u, const auto& v) { return u.first < v.first; });
    values.clear();
    for (const auto& e : z) values.push_back(e.second);
    divide_by_gcd(values.data(), static_cast<Index>(values.size()));
    SparseRow row;
    for (std::size_t k = 0; k < z.size(); ++k) {
      row.col.push_back(z[k].first);
      row.value.push_back(to_z(values[k]));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

template <class R>
void make_primitive_in(const std::vector<Q*>& v) {
  const auto k = static_cast<Index>(v.size());
  std::vector<R> out(v.size());
  ring::to_common_denominator<R>(
      k, [&](Index i) -> const Q& { return *v[static_cast<std::size_t>(i)]; }, out.data());
  divide_by_gcd(out.data(), k);
  for (std::size_t i = 0; i < v.size(); ++i) assign(out[i], *v[i]);
}

}  // namespace

std::vector<SparseRow> left_null_rows(const Mat<Q>& P) {
  return exact::with_exact_ring<Q, Int128>([&]<class R>() { return left_null_rows_in<R>(P); });
}

void make_primitive(const std::vector<Q*>& v) {
  exact::with_exact_ring<Q, Int128>([&]<class R>() { make_primitive_in<R>(v); });
}

}  // namespace contactcert::solvers::ucp
