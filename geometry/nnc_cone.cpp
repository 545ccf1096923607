#include "geometry/nnc_cone.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <type_traits>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/int_matrix.h"
#include "exact/ladder_numbers.h"
#include "geometry/canonical.h"

namespace contactcert::geometry {
namespace {

using Index = Eigen::Index;
using exact::is_zero;
using exact::sign;

// For every ring row s of S, the ring rays r with s . r == 0, as a bit per ray.
template <class Rg>
std::vector<std::vector<bool>> ring_zero_sets(const exact::IntMatrix<Rg>& rays, const exact::IntMatrix<Rg>& S) {
  std::vector<std::vector<bool>> z(static_cast<std::size_t>(S.rows()),
                                   std::vector<bool>(static_cast<std::size_t>(rays.rows())));
  Rg x;
  for (Index s = 0; s < S.rows(); ++s)
    for (Index r = 0; r < rays.rows(); ++r) {
      exact::ring::dot(S.row(s), rays.row(r), rays.cols(), x);
      z[static_cast<std::size_t>(s)][static_cast<std::size_t>(r)] = exact::ring::sign(x) == 0;
    }
  return z;
}

}  // namespace

// Rationals: the numerator of the sum over the positive denominator prod den(M_ri) den(g_i),
// accumulated as n / d + p / q = (n q + p d) / (d q) in integers (no gcd); other types: the dot's sign.
template <class T>
int dot_sign(const Mat<T>& M, Eigen::Index r, const Vec<T>& g) {
  if constexpr (std::is_same_v<T, Q>) {
    exact::Z n = 0, d = 1, p, q;
    for (Index i = 0; i < g.size(); ++i) {
      const Q &a = M(r, i), &b = g(i);
      if (sgn(a) == 0 || sgn(b) == 0) continue;
      mpz_mul(p.get_mpz_t(), a.get_num_mpz_t(), b.get_num_mpz_t());
      mpz_mul(q.get_mpz_t(), a.get_den_mpz_t(), b.get_den_mpz_t());
      if (mpz_cmp_ui(q.get_mpz_t(), 1) != 0) mpz_mul(n.get_mpz_t(), n.get_mpz_t(), q.get_mpz_t());
      mpz_addmul(n.get_mpz_t(), p.get_mpz_t(), d.get_mpz_t());
      if (mpz_cmp_ui(q.get_mpz_t(), 1) != 0) mpz_mul(d.get_mpz_t(), d.get_mpz_t(), q.get_mpz_t());
    }
    return sgn(n);
  } else {
    return sign(T(M.row(r).dot(g)));
  }
}

bool is_subset(const std::vector<bool>& a, const std::vector<bool>& b) {
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i] && !b[i]) return false;
  return true;
}

MissingFaces missing_faces(std::vector<std::vector<bool>> zs, const std::vector<std::vector<bool>>& facet_rays) {
  MissingFaces out;
  std::sort(zs.begin(), zs.end());
  zs.erase(std::unique(zs.begin(), zs.end()), zs.end());
  for (size_t i = 0; i < zs.size(); ++i) {
    bool dominated = false;
    for (size_t j = 0; j < zs.size() && !dominated; ++j) dominated = j != i && is_subset(zs[i], zs[j]);
    if (!dominated) out.maximal.push_back(zs[i]);
  }
  out.open_facets.assign(facet_rays.size(), false);
  for (const auto& g : out.maximal) {
    std::vector<Index> through;
    for (size_t f = 0; f < facet_rays.size(); ++f) {
      if (!is_subset(g, facet_rays[f])) continue;
      if (facet_rays[f] == g) {
        out.open_facets[f] = true;
        through.assign(1, static_cast<Index>(f));
        break;
      }
      through.push_back(static_cast<Index>(f));
    }
    out.facets.push_back(std::move(through));
  }
  return out;
}

namespace {

// The cone { F g <= 0, S g < 0 } resolved in a ring R from its closure K' = { F g <= 0, S g <= 0 }, given by
// its minimal rays and facets (both in lexicographic order) and the zero sets zs of the strict rows on
// the rays (ring_zero_sets): the cone is empty iff some strict row vanishes on every ray (empty()); otherwise
// the closure's facets split into closed ones (in the cone) and one strict row per maximal missing face,
// the sum of the normals of the facets through it (normalized, deduplicated, sorted).
bool empty(const std::vector<std::vector<bool>>& zs) {
  return std::any_of(zs.begin(), zs.end(),
                     [](const auto& z) { return std::all_of(z.begin(), z.end(), std::identity{}); });
}

template <class R>
struct RingNnc {
  MissingFaces missing;
  exact::IntMatrix<R> closed, strict;
};

template <class R>
RingNnc<R> resolve_in_ring(const std::vector<std::vector<bool>>& zs, const exact::IntMatrix<R>& rays,
                           const exact::IntMatrix<R>& facets) {
  namespace rg = exact::ring;
  const Index d = facets.cols();
  RingNnc<R> out{missing_faces(zs, ring_zero_sets<R>(rays, facets)), exact::IntMatrix<R>(0, d),
                 exact::IntMatrix<R>(0, d)};
  for (Index f = 0; f < facets.rows(); ++f)
    if (!out.missing.open_facets[static_cast<size_t>(f)]) out.closed.append_row(facets.row(f));
  std::vector<R> s(static_cast<size_t>(d));
  for (const std::vector<Index>& through : out.missing.facets) {
    std::fill(s.begin(), s.end(), R(0));
    for (Index f : through)
      for (Index j = 0; j < d; ++j) s[static_cast<size_t>(j)] = rg::add(s[static_cast<size_t>(j)], facets(f, j));
    rg::normalize(s.data(), d);
    out.strict.append_row(s.data());
  }
  exact::sort_rows(out.strict);  // (the zero sums dropped)
  return out;
}

// The steps of resolve_in_ring for field rows (canonical rays R and facets F of the closure, strict rows S):
// nullopt if the cone is empty.
template <class T>
struct FieldNnc {
  MissingFaces missing;
  Mat<T> closed, strict;
};

template <class T>
std::optional<FieldNnc<T>> resolve(const Mat<T>& R, const Mat<T>& F, const Mat<T>& S) {
  return exact::with_exact_ring<T>([&]<class Rg>() -> std::optional<FieldNnc<T>> {
    namespace rg = exact::ring;
    const exact::IntMatrix<Rg> rays = rg::to_ring_rows<Rg>(R);
    const std::vector<std::vector<bool>> zs = ring_zero_sets<Rg>(rays, rg::to_ring_rows<Rg>(S));
    if (empty(zs)) return std::nullopt;
    RingNnc<Rg> r = resolve_in_ring<Rg>(zs, rays, rg::to_ring_rows<Rg>(F));
    return FieldNnc<T>{std::move(r.missing), rg::to_field_rows<T>(r.closed, F.cols()),
                       rg::to_field_rows<T>(r.strict, F.cols())};
  });
}

// The empty cone's face form: { g = 0, 0 . g < 0 } (canonical equalities: the identity rows, sorted).
template <class T>
FaceCone<T> empty_face(Index d) {
  const Mat<T> all =
      canonical(FaceCone<T>::from_rows(d, Mat<T>(0, d), Mat<T>(Mat<T>::Identity(d, d)), Mat<T>(0, d))).equalities;
  return FaceCone<T>::from_rows(d, Mat<T>(0, d), all, Mat<T>(Mat<T>::Zero(1, d)));
}

}  // namespace

template <class T>
Eigen::Index NncForm<T>::dimension() const {
  if (status == NncStatus::kEmpty) return -1;
  return closure_face.dim - closure_face.equalities.rows();
}

template <class T>
NncForm<T> nnc_form(const FaceCone<T>& cone, const DdBudget& budget) {
  const Index d = cone.dim;
  NncForm<T> out;
  // K' = { F g <= 0, S g <= 0, E g = 0 }: minimal generators and facets, from one conversion.
  ConePair<T> closure = both_forms(cone, budget);
  out.closure = canonical(closure.span);
  const Mat<T>& R = out.closure.rays;
  out.closure_face = canonical(closure.face);
  const std::optional<FieldNnc<T>> res = resolve<T>(R, out.closure_face.inequalities, cone.strict);
  if (!res) {
    out.status = NncStatus::kEmpty;
    out.face = empty_face<T>(d);
    out.closure = SpanCone<T>::from_rows(d, Mat<T>(0, d), Mat<T>(0, d));
    out.closure_face = FaceCone<T>::from_rows(d, Mat<T>(0, d), out.face.equalities, Mat<T>(0, d));
    return out;
  }
  out.status = NncStatus::kNonEmpty;
  out.open_facets = res->missing.open_facets;
  for (const std::vector<bool>& g : res->missing.maximal) {
    std::vector<Index> rays;
    for (size_t r = 0; r < g.size(); ++r)
      if (g[r]) rays.push_back(static_cast<Index>(r));
    out.open_faces.push_back(rays);
  }
  // No missing face: the cone is its closure, whose face form is canonical already.
  if (res->strict.rows() == 0) {
    out.face = out.closure_face;
    return out;
  }
  out.face = canonical(FaceCone<T>::from_rows(d, res->closed, out.closure_face.equalities, res->strict));
  return out;
}

template <class T>
NncForm<T> nnc_form(const SpanCone<T>& cone, const DdBudget& budget) {
  // Closed and not empty: the cone is its closure.
  const ConePair<T> pair = both_forms(cone, budget);
  NncForm<T> out;
  out.status = NncStatus::kNonEmpty;
  out.closure = canonical(pair.span);
  out.closure_face = canonical(pair.face);
  out.face = out.closure_face;
  out.open_facets.assign(static_cast<size_t>(out.closure_face.inequalities.rows()), false);
  return out;
}

template <class T, class R>
std::optional<FaceCone<T>> pointed_nnc_face(const exact::IntMatrix<R>& F, const exact::IntMatrix<R>& S,
                                            const DdBudget& budget) {
  namespace rg = exact::ring;
  const Index d = F.cols();
  // The steps of nnc_form in the ring; canonical rows are primitive, deduplicated and sorted, and
  // without equalities or lines nothing else is reduced.
  const auto closure_rows = [&] {  // K' = { F g <= 0, S g <= 0 }
    exact::IntMatrix<R> rows = F;
    for (Index i = 0; i < S.rows(); ++i) rows.append_row(S.row(i));
    return rows;
  };
  auto rays = pointed_cone_rays<R>(closure_rows(), budget);
  if (!rays || rays->rows() == 0) return std::nullopt;
  exact::sort_rows(*rays);  // (extreme rays: none zero, none twice)
  // Facets of the closure: the extreme rays of its polar, pointed iff the closure is full-dimensional
  // (not needed when a strict row vanishes on every ray: the cone is empty).
  const std::vector<std::vector<bool>> zs = ring_zero_sets<R>(*rays, S);
  if (empty(zs)) return empty_face<T>(d);
  auto facets = pointed_cone_rays<R>(*rays, budget);
  if (!facets) return std::nullopt;
  exact::sort_rows(*facets);
  const RingNnc<R> r = resolve_in_ring<R>(zs, *rays, *facets);
  return FaceCone<T>::from_rows(d, rg::to_field_rows<T>(r.closed, d), Mat<T>(0, d), rg::to_field_rows<T>(r.strict, d));
}

template <class T>
bool contains_point(const FaceCone<T>& cone, const Vec<T>& g) {
  for (Index i = 0; i < cone.equalities.rows(); ++i)
    if (dot_sign(cone.equalities, i, g) != 0) return false;
  for (Index i = 0; i < cone.inequalities.rows(); ++i)
    if (dot_sign(cone.inequalities, i, g) > 0) return false;
  for (Index i = 0; i < cone.strict.rows(); ++i)
    if (dot_sign(cone.strict, i, g) >= 0) return false;
  return true;
}

template <class T>
PointPosition<T> locate(const FaceCone<T>& cone, const Vec<T>& g) {
  using Kind = typename PointPosition<T>::RowKind;
  PointPosition<T> p;
  auto outside = [&](Kind kind, Index row) {
    p.location = PointLocation::kOutside;
    p.violated_kind = kind;
    p.violated_row = row;
    p.tight.clear();
    return p;
  };
  for (Index i = 0; i < cone.equalities.rows(); ++i)
    if (!is_zero(T(cone.equalities.row(i).dot(g)))) return outside(Kind::kEquality, i);
  for (Index i = 0; i < cone.strict.rows(); ++i)
    if (sign(T(cone.strict.row(i).dot(g))) >= 0) return outside(Kind::kStrict, i);
  for (Index i = 0; i < cone.inequalities.rows(); ++i) {
    const int s = sign(T(cone.inequalities.row(i).dot(g)));
    if (s > 0) return outside(Kind::kInequality, i);
    if (s == 0) p.tight.push_back(i);
  }
  p.location = p.tight.empty() ? PointLocation::kInterior : PointLocation::kBoundary;
  return p;
}

template std::optional<FaceCone<Q>> pointed_nnc_face<Q, std::int64_t>(const exact::IntMatrix<std::int64_t>&,
                                                                      const exact::IntMatrix<std::int64_t>&,
                                                                      const DdBudget&);
template std::optional<FaceCone<Q>> pointed_nnc_face<Q, Z>(const exact::IntMatrix<Z>&, const exact::IntMatrix<Z>&,
                                                           const DdBudget&);

#define CONTACTCERT_NNC_INSTANTIATE(T)                                  \
  template struct NncForm<T>;                                           \
  template NncForm<T> nnc_form<T>(const FaceCone<T>&, const DdBudget&); \
  template NncForm<T> nnc_form<T>(const SpanCone<T>&, const DdBudget&); \
  template bool contains_point<T>(const FaceCone<T>&, const Vec<T>&);   \
  template int dot_sign<T>(const Mat<T>&, Eigen::Index, const Vec<T>&); \
  template PointPosition<T> locate<T>(const FaceCone<T>&, const Vec<T>&);
CONTACTCERT_NNC_INSTANTIATE(double)
CONTACTCERT_NNC_INSTANTIATE(Q)
CONTACTCERT_NNC_INSTANTIATE(exact::Mpfr)
CONTACTCERT_NNC_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_NNC_INSTANTIATE

}  // namespace contactcert::geometry
