#include "solvers/ucp/integer_rows.h"

#include <limits>

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

/// out = x as a rational, without throwing (so that a restart in Z never sees half-written output).
void assign(Int128 x, Q& out) {
  if (x >= std::numeric_limits<long>::min() && x <= std::numeric_limits<long>::max())
    mpq_set_si(out.get_mpq_t(), static_cast<long>(x), 1);
  else
    out = Q(ring::to_z(x));
}
void assign(const Z& x, Q& out) { out = Q(x); }

/// left_null_rows in the ring R (Int128: throws RingOverflow when a number does not fit): the kernel of P^T, whose
/// rows (the columns of P) are scaled to primitive integers first (the same kernel), its non-zero entries.
template <class R>
std::vector<SparseRow> left_null_rows_in(const Mat<Q>& P) {
  const IntMatrix<R> N =
      IntMatrix<R>::primitive_rows(P.cols(), P.rows(), [&](Index i, Index j) -> const Q& { return P(j, i); }).kernel();
  std::vector<SparseRow> rows(static_cast<std::size_t>(N.rows()));
  for (Index r = 0; r < N.rows(); ++r)
    for (Index j = 0; j < N.cols(); ++j)
      if (ring::sign(N(r, j)) != 0) {
        rows[static_cast<std::size_t>(r)].col.push_back(j);
        rows[static_cast<std::size_t>(r)].value.push_back(to_z(N(r, j)));
      }
  return rows;
}

template <class R>
void make_primitive_in(const std::vector<Q*>& v) {
  const IntMatrix<R> row = IntMatrix<R>::primitive_rows(
      1, static_cast<Index>(v.size()), [&](Index, Index j) -> const Q& { return *v[static_cast<std::size_t>(j)]; });
  for (std::size_t i = 0; i < v.size(); ++i) assign(row(0, static_cast<Index>(i)), *v[i]);
}

}  // namespace

std::vector<SparseRow> left_null_rows(const Mat<Q>& P) {
  return exact::with_exact_ring<Q, Int128>([&]<class R>() { return left_null_rows_in<R>(P); });
}

void make_primitive(const std::vector<Q*>& v) {
  exact::with_exact_ring<Q, Int128>([&]<class R>() { make_primitive_in<R>(v); });
}

}  // namespace contactcert::solvers::ucp
