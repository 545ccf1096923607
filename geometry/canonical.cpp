#include "geometry/canonical.h"

#include <algorithm>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/ladder_numbers.h"
#include "exact/linalg.h"

namespace contactcert::geometry {
namespace {

using Index = Eigen::Index;
using exact::is_zero;

// The row's representative of its direction, the ring's (exact/fraction_free.h): the primitive integer row
// (Q), the row of max-norm 1 (a float).
template <class T>
void normalize_row(std::vector<T>& v) {
  exact::with_exact_ring<T>([&]<class R>() {
    std::vector<R> r(v.size());
    exact::ring::to_ring(v.data(), static_cast<Index>(v.size()), r.data());
    for (size_t i = 0; i < v.size(); ++i) v[i] = exact::ring::to_field<T>(r[i]);
  });
}

template <class T>
Mat<T> to_matrix(const std::vector<std::vector<T>>& rows, Index dim) {
  Mat<T> M(static_cast<Index>(rows.size()), dim);
  for (Index i = 0; i < M.rows(); ++i)
    for (Index j = 0; j < dim; ++j) M(i, j) = rows[static_cast<size_t>(i)][static_cast<size_t>(j)];
  return M;
}

// Basis of a subspace in canonical form: reduced row echelon rows, normalised.
template <class T>
struct Subspace {
  exact::Rref<T> rref;
  Mat<T> canonical_rows;
};

template <class T>
Subspace<T> canonical_subspace(const Mat<T>& rows, Index dim) {
  Subspace<T> s;
  s.rref = exact::rref<T>(rows.rows() == 0 ? Mat<T>(0, dim) : rows);
  std::vector<std::vector<T>> out;
  for (Index r = 0; r < s.rref.rank(); ++r) {
    std::vector<T> v(static_cast<size_t>(dim));
    for (Index j = 0; j < dim; ++j) v[static_cast<size_t>(j)] = s.rref.R(r, j);
    normalize_row(v);
    out.push_back(std::move(v));
  }
  std::sort(out.begin(), out.end());
  s.canonical_rows = to_matrix<T>(out, dim);
  return s;
}

// Rows reduced modulo the subspace (zero in its pivot columns), normalised, deduplicated, sorted.
template <class T>
Mat<T> canonical_rows(const Mat<T>& rows, const Subspace<T>& s, Index dim) {
  std::vector<std::vector<T>> out;
  for (Index i = 0; i < rows.rows(); ++i) {
    std::vector<T> v(static_cast<size_t>(dim));
    for (Index j = 0; j < dim; ++j) v[static_cast<size_t>(j)] = rows(i, j);
    for (Index r = 0; r < s.rref.rank(); ++r) {
      const Index p = s.rref.pivots[static_cast<size_t>(r)];
      const T f = v[static_cast<size_t>(p)];
      if (is_zero(f)) continue;
      for (Index j = 0; j < dim; ++j) v[static_cast<size_t>(j)] -= f * s.rref.R(r, j);
      v[static_cast<size_t>(p)] = T(0);
    }
    if (std::all_of(v.begin(), v.end(), [](const T& x) { return is_zero(x); })) continue;
    normalize_row(v);
    out.push_back(std::move(v));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return to_matrix<T>(out, dim);
}

template <class T>
bool same(const Mat<T>& a, const Mat<T>& b) {
  if (a.rows() != b.rows() || (a.rows() > 0 && a.cols() != b.cols())) return false;
  for (Index i = 0; i < a.rows(); ++i)
    for (Index j = 0; j < a.cols(); ++j)
      if (!(a(i, j) == b(i, j))) return false;
  return true;
}

}  // namespace

template <class T>
SpanCone<T> canonical(const SpanCone<T>& cone) {
  const Subspace<T> lines = canonical_subspace<T>(cone.lines, cone.dim);
  return SpanCone<T>::from_rows(cone.dim, canonical_rows<T>(cone.rays, lines, cone.dim), lines.canonical_rows);
}

template <class T>
FaceCone<T> canonical(const FaceCone<T>& cone) {
  const Subspace<T> eq = canonical_subspace<T>(cone.equalities, cone.dim);
  return FaceCone<T>::from_rows(cone.dim, canonical_rows<T>(cone.inequalities, eq, cone.dim), eq.canonical_rows,
                                canonical_rows<T>(cone.strict, eq, cone.dim));
}

template <class T>
bool identical(const FaceCone<T>& a, const FaceCone<T>& b) {
  return a.dim == b.dim && same<T>(a.inequalities, b.inequalities) && same<T>(a.equalities, b.equalities) &&
         same<T>(a.strict, b.strict);
}

template <class T>
bool identical(const SpanCone<T>& a, const SpanCone<T>& b) {
  return a.dim == b.dim && same<T>(a.rays, b.rays) && same<T>(a.lines, b.lines);
}

#define CONTACTCERT_CANONICAL_INSTANTIATE(T)                          \
  template SpanCone<T> canonical<T>(const SpanCone<T>&);              \
  template FaceCone<T> canonical<T>(const FaceCone<T>&);              \
  template bool identical<T>(const FaceCone<T>&, const FaceCone<T>&); \
  template bool identical<T>(const SpanCone<T>&, const SpanCone<T>&);
CONTACTCERT_CANONICAL_INSTANTIATE(double)
CONTACTCERT_CANONICAL_INSTANTIATE(Q)
CONTACTCERT_CANONICAL_INSTANTIATE(exact::Mpfr)
CONTACTCERT_CANONICAL_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_CANONICAL_INSTANTIATE

}  // namespace contactcert::geometry
