#include "geometry/nnc_cone.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/ladder_numbers.h"
#include "geometry/canonical.h"

namespace contactcert::geometry {
namespace {

using Index = Eigen::Index;
using exact::is_zero;
using exact::sign;

// For every ring row s of S, the ring rays r with s . r == 0, as a bit per ray.
template <class Rg>
std::vector<std::vector<bool>> ring_zero_sets(const std::vector<std::vector<Rg>>& rays,
                                              const std::vector<std::vector<Rg>>& S) {
  std::vector<std::vector<bool>> z(S.size(), std::vector<bool>(rays.size()));
  Rg x;
  for (std::size_t s = 0; s < S.size(); ++s)
    for (std::size_t r = 0; r < rays.size(); ++r) {
      exact::ring::dot(S[s].data(), rays[r].data(), static_cast<Index>(rays[r].size()), x);
      z[s][r] = exact::ring::sign(x) == 0;
    }
  return z;
}

// For every row s of S, the rays r (rows of R) with s . r == 0. Decided in the ring of T on rows and
// rays scaled by positive factors (the same signs).
template <class T>
std::vector<std::vector<bool>> zero_sets(const Mat<T>& R, const Mat<T>& S) {
  return exact::with_exact_ring<T>([&]<class Rg>() {
    return ring_zero_sets<Rg>(exact::ring::to_ring_rows<Rg>(R), exact::ring::to_ring_rows<Rg>(S));
  });
}

bool subset(const std::vector<bool>& a, const std::vector<bool>& b) {
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i] && !b[i]) return false;
  return true;
}

// The maximal faces missing from the cone: the maximal sets among the Z_s of the strict rows (each a
// bit per closure ray), and for each the facets through it (by their ray sets), which is the facet
// itself when the face is a facet (marked in open_facets).
struct MissingFaces {
  std::vector<std::vector<bool>> maximal;
  std::vector<std::vector<Index>> facets;  ///< per maximal face: the facets whose normals sum to its strict row
  std::vector<bool> open_facets;
};

MissingFaces missing_faces(std::vector<std::vector<bool>> zs, const std::vector<std::vector<bool>>& facet_rays) {
  MissingFaces out;
  std::sort(zs.begin(), zs.end());
  zs.erase(std::unique(zs.begin(), zs.end()), zs.end());
  for (size_t i = 0; i < zs.size(); ++i) {
    bool dominated = false;
    for (size_t j = 0; j < zs.size() && !dominated; ++j) dominated = j != i && subset(zs[i], zs[j]);
    if (!dominated) out.maximal.push_back(zs[i]);
  }
  out.open_facets.assign(facet_rays.size(), false);
  for (const auto& g : out.maximal) {
    std::vector<Index> through;
    for (size_t f = 0; f < facet_rays.size(); ++f) {
      if (!subset(g, facet_rays[f])) continue;
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

// The empty cone's face form: { g = 0, 0 . g < 0 } (canonical equalities: the identity rows, sorted).
template <class T>
FaceCone<T> empty_face(Index d) {
  const Mat<T> all =
      canonical(FaceCone<T>::from_rows(d, Mat<T>(0, d), Mat<T>(Mat<T>::Identity(d, d)), Mat<T>(0, d))).equalities;
  return FaceCone<T>::from_rows(d, Mat<T>(0, d), all, Mat<T>(Mat<T>::Zero(1, d)));
}

template <class T>
Mat<T> stack(const std::vector<Vec<T>>& rows, Index dim) {
  Mat<T> M(static_cast<Index>(rows.size()), dim);
  for (Index i = 0; i < M.rows(); ++i) M.row(i) = rows[static_cast<size_t>(i)].transpose();
  return M;
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
  // Z_s for every strict row; the cone is empty iff some Z_s holds every ray (s vanishes on K').
  const std::vector<std::vector<bool>> zs = zero_sets<T>(R, cone.strict);
  bool empty = false;
  for (const auto& z : zs)
    if (std::all_of(z.begin(), z.end(), [](bool b) { return b; })) empty = true;
  if (empty) {
    out.status = NncStatus::kEmpty;
    out.face = empty_face<T>(d);
    out.closure = SpanCone<T>::from_rows(d, Mat<T>(0, d), Mat<T>(0, d));
    out.closure_face = FaceCone<T>::from_rows(d, Mat<T>(0, d), out.face.equalities, Mat<T>(0, d));
    return out;
  }
  out.status = NncStatus::kNonEmpty;
  out.closure_face = canonical(closure.face);
  const Mat<T>& F = out.closure_face.inequalities;

  const MissingFaces missing = missing_faces(zs, zero_sets<T>(R, F));
  out.open_facets = missing.open_facets;
  std::vector<Vec<T>> strict_rows;
  for (size_t m = 0; m < missing.maximal.size(); ++m) {
    const std::vector<bool>& g = missing.maximal[m];
    std::vector<Index> rays;
    for (size_t r = 0; r < g.size(); ++r)
      if (g[r]) rays.push_back(static_cast<Index>(r));
    out.open_faces.push_back(rays);
    Vec<T> s = Vec<T>::Zero(d);
    for (Index f : missing.facets[m]) s += F.row(f).transpose();
    strict_rows.push_back(s);
  }
  // No missing face: the cone is its closure, whose face form is canonical already.
  if (strict_rows.empty()) {
    out.face = out.closure_face;
    return out;
  }
  std::vector<Vec<T>> closed_rows;
  for (Index f = 0; f < F.rows(); ++f)
    if (!out.open_facets[static_cast<size_t>(f)]) closed_rows.push_back(F.row(f).transpose());
  out.face = canonical(
      FaceCone<T>::from_rows(d, stack<T>(closed_rows, d), out.closure_face.equalities, stack<T>(strict_rows, d)));
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
std::optional<FaceCone<T>> pointed_nnc_face(const std::vector<std::vector<R>>& F, const std::vector<std::vector<R>>& S,
                                            Index d, const DdBudget& budget) {
  namespace rg = exact::ring;
  // The steps of nnc_form in the ring; canonical rows are primitive, deduplicated and sorted, and
  // without equalities or lines nothing else is reduced.
  std::vector<std::vector<R>> rows = F;
  rows.insert(rows.end(), S.begin(), S.end());
  auto rays = pointed_cone_rays<R>(std::move(rows), d, budget);  // K' = { F g <= 0, S g <= 0 }
  if (!rays || rays->empty()) return std::nullopt;
  std::sort(rays->begin(), rays->end());
  const std::vector<std::vector<bool>> zs = ring_zero_sets<R>(*rays, S);
  for (const auto& z : zs)
    if (std::all_of(z.begin(), z.end(), [](bool b) { return b; })) return empty_face<T>(d);
  // Facets of the closure: the extreme rays of its polar, pointed iff the closure is full-dimensional.
  auto facets = pointed_cone_rays<R>(*rays, d, budget);
  if (!facets) return std::nullopt;
  std::sort(facets->begin(), facets->end());
  const MissingFaces missing = missing_faces(zs, ring_zero_sets<R>(*rays, *facets));
  std::vector<std::vector<R>> closed, strict;
  for (size_t f = 0; f < facets->size(); ++f)
    if (!missing.open_facets[f]) closed.push_back((*facets)[f]);
  for (const std::vector<Index>& through : missing.facets) {
    std::vector<R> s(static_cast<size_t>(d), R(0));
    for (Index f : through)
      for (Index j = 0; j < d; ++j)
        s[static_cast<size_t>(j)] =
            rg::add(s[static_cast<size_t>(j)], (*facets)[static_cast<size_t>(f)][static_cast<size_t>(j)]);
    rg::normalize(s.data(), d);
    if (std::any_of(s.begin(), s.end(), [](const R& x) { return rg::sign(x) != 0; })) strict.push_back(std::move(s));
  }
  std::sort(strict.begin(), strict.end());
  strict.erase(std::unique(strict.begin(), strict.end()), strict.end());
  return FaceCone<T>::from_rows(d, rg::to_field_rows<T>(closed, d), Mat<T>(0, d), rg::to_field_rows<T>(strict, d));
}

template <class T>
bool contains_point(const FaceCone<T>& cone, const Vec<T>& g) {
  for (Index i = 0; i < cone.equalities.rows(); ++i)
    if (!is_zero(T(cone.equalities.row(i).dot(g)))) return false;
  for (Index i = 0; i < cone.inequalities.rows(); ++i)
    if (sign(T(cone.inequalities.row(i).dot(g))) > 0) return false;
  for (Index i = 0; i < cone.strict.rows(); ++i)
    if (sign(T(cone.strict.row(i).dot(g))) >= 0) return false;
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

template std::optional<FaceCone<Q>> pointed_nnc_face<Q, std::int64_t>(const std::vector<std::vector<std::int64_t>>&,
                                                                      const std::vector<std::vector<std::int64_t>>&,
                                                                      Index, const DdBudget&);
template std::optional<FaceCone<Q>> pointed_nnc_face<Q, Z>(const std::vector<std::vector<Z>>&,
                                                           const std::vector<std::vector<Z>>&, Index, const DdBudget&);

#define CONTACTCERT_NNC_INSTANTIATE(T)                                  \
  template struct NncForm<T>;                                           \
  template NncForm<T> nnc_form<T>(const FaceCone<T>&, const DdBudget&); \
  template NncForm<T> nnc_form<T>(const SpanCone<T>&, const DdBudget&); \
  template bool contains_point<T>(const FaceCone<T>&, const Vec<T>&);   \
  template PointPosition<T> locate<T>(const FaceCone<T>&, const Vec<T>&);
CONTACTCERT_NNC_INSTANTIATE(double)
CONTACTCERT_NNC_INSTANTIATE(Q)
CONTACTCERT_NNC_INSTANTIATE(exact::Mpfr)
CONTACTCERT_NNC_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_NNC_INSTANTIATE

}  // namespace contactcert::geometry
