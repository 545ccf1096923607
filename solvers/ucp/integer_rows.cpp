#include "solvers/ucp/integer_rows.h"

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

}  // namespace

SparseRows left_null_rows(const Mat<Q>& P) {
  return exact::with_exact_ring<Q, Int128>([&]<class R>() { return left_null_rows_in<R>(P); });
}

std::vector<Z> primitive_integers(const std::vector<const Q*>& v) {
  return exact::with_exact_ring<Q, Int128>([&]<class R>() { return primitive_integers_in<R>(v); });
}

}  // namespace contactcert::solvers::ucp
