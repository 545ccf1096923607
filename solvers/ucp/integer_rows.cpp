#include "solvers/ucp/integer_rows.h"

#include <algorithm>
#include <functional>
#include <numeric>

#include "exact/int_matrix.h"

namespace contactcert::solvers::ucp {

namespace {

using exact::Int128;
using exact::IntMatrix;
using exact::Mat;
using exact::Q;
using exact::Z;
using Index = Eigen::Index;
namespace ring = exact::ring;

Z to_z(Int128 x) { return ring::to_z(x); }
const Z& to_z(const Z& x) { return x; }

/// left_null_rows in the ring R (Int128: throws RingOverflow when a number does not fit): the kernel of P^T, whose
/// rows (the columns of P) are scaled to primitive integers first (the same kernel), its non-zero entries.
template <class R>
SparseRows left_null_rows_in(const Mat<Q>& P) {
  const IntMatrix<R> N =
      IntMatrix<R>::primitive_rows(P.cols(), P.rows(), [&](Index i, Index j) -> const Q& { return P(j, i); }).kernel();
  return SparseRows::nonzeros(N, [](const R& x) { return to_z(x); });
}

template <class R>
std::vector<Z> primitive_integers_in(const std::vector<const Q*>& v) {
  const IntMatrix<R> row = IntMatrix<R>::primitive_rows(
      1, static_cast<Index>(v.size()), [&](Index, Index j) -> const Q& { return *v[static_cast<std::size_t>(j)]; });
  std::vector<Z> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[i] = to_z(row(0, static_cast<Index>(i)));
  return out;
}

std::size_t bits(const Z& x) { return mpz_sizeinbase(x.get_mpz_t(), 2); }

/// A lower bound on the bits of the largest entry of the row q(0..k) over its common denominator L: q = a / b
/// becomes a L / b, of at least bits(a) + bits(L) - bits(b) - 1 bits, and L >= every b.
template <class Get>
std::size_t row_bits(Index k, Get q) {
  std::size_t max_den = 0, out = 0;
  for (Index i = 0; i < k; ++i) max_den = std::max(max_den, bits(q(i).get_den()));
  for (Index i = 0; i < k; ++i)
    if (sgn(q(i)) != 0) out = std::max(out, bits(q(i).get_num()) + max_den - bits(q(i).get_den()) - 1);
  return out;
}

}  // namespace

std::size_t elimination_bits(const Mat<Q>& M, bool by_rows) {
  // Minors over up to min(rows, cols) of the rows, each a sum of products of one entry per row: the largest rows'
  // bits, summed.
  const Index n = by_rows ? M.rows() : M.cols(), k = by_rows ? M.cols() : M.rows();
  std::vector<std::size_t> b(static_cast<std::size_t>(n));
  for (Index r = 0; r < n; ++r)
    b[static_cast<std::size_t>(r)] = row_bits(k, [&](Index i) -> const Q& { return by_rows ? M(r, i) : M(i, r); });
  std::sort(b.begin(), b.end(), std::greater<>());
  const auto depth = static_cast<std::ptrdiff_t>(std::min(n, k));
  return std::accumulate(b.begin(), b.begin() + depth, std::size_t{0});
}

SparseRows left_null_rows(const Mat<Q>& P) {
  // The kernel of P^T: an elimination over the columns of P.
  return in_ring(elimination_bits(P, false), [&]<class R>() { return left_null_rows_in<R>(P); });
}

std::vector<Z> primitive_integers(const std::vector<const Q*>& v) {
  return in_ring(
      row_bits(static_cast<Index>(v.size()), [&](Index i) -> const Q& { return *v[static_cast<std::size_t>(i)]; }),
      [&]<class R>() { return primitive_integers_in<R>(v); });
}

}  // namespace contactcert::solvers::ucp
