#include "solvers/ucp/integer_rows.h"

#include "exact/int_matrix.h"

namespace contactcert::solvers::ucp {

namespace {

using exact::Int128;
using exact::IntMatrix;
using exact::Mat;
using exact::Q;
using exact::Vec;
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

IntegerPolyhedron integer_polyhedron(const Mat<Q>& A, const Vec<Q>& b) {
  IntegerPolyhedron P{SparseRows(A.cols()), std::vector<Z>(static_cast<std::size_t>(A.rows())), b};
  std::vector<Z> row(static_cast<std::size_t>(A.cols()));
  for (Index i = 0; i < A.rows(); ++i) {
    P.den[static_cast<std::size_t>(i)] = ring::to_common_denominator<Z>(
        A.cols(), [&](Index j) -> const Q& { return A(i, j); }, row.data());
    P.A.add_row();
    for (Index j = 0; j < A.cols(); ++j)
      if (sgn(row[static_cast<std::size_t>(j)]) != 0) P.A.push(j, std::move(row[static_cast<std::size_t>(j)]));
  }
  return P;
}

template <class R>
exact::IntegerSystem<R> integer_system(const IntegerPolyhedron& P) {
  // Row i of [A | b] is [A[i] | L_b b_i] / den_i over den_i and L_b the denominator of b_i: over L = lcm(den_i, L_b),
  // A[i] (L / den_i) and num(b_i) (L / L_b), as ring::to_common_denominator makes the rational row.
  exact::IntegerSystem<R> s;
  s.A = IntMatrix<R>(P.rows(), P.cols());
  s.b.resize(static_cast<std::size_t>(P.rows()));
  s.row_scale.resize(static_cast<std::size_t>(P.rows()));
  R den, den_b, f;
  for (Index i = 0; i < P.rows(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    ring::from_integer(P.den[k], den);
    ring::from_integer(P.b(i).get_den(), den_b);
    R& L = s.row_scale[k];
    L = ring::lcm(den, den_b);
    f = ring::divexact(L, den);
    for (Index t = P.A.begin(i); t < P.A.end(i); ++t) {
      R& a = s.A(i, P.A.col(t));
      ring::from_integer(P.A.value(t), a);
      if (f != 1) a = ring::mul(a, f);
    }
    ring::from_integer(P.b(i).get_num(), s.b[k]);
    if (L != den_b) s.b[k] = ring::mul(s.b[k], ring::divexact(L, den_b));
  }
  return s;
}
template exact::IntegerSystem<Int128> integer_system<Int128>(const IntegerPolyhedron&);
template exact::IntegerSystem<Z> integer_system<Z>(const IntegerPolyhedron&);

}  // namespace contactcert::solvers::ucp
