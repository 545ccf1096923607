#include "geometry/nnc_cone.h"

#include <algorithm>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/ladder_numbers.h"
#include "geometry/canonical.h"

namespace contactcert::geometry {
namespace {

using Index = Eigen::Index;
using exact::is_zero;
using exact::sign;

// For every row s of S, the rays r (rows of R) with s . r == 0, as a bit per ray. Decided in the ring
// of T on rows and rays scaled by positive factors (the same signs).
template <class T>
std::vector<std::vector<bool>> zero_sets(const Mat<T>& R, const Mat<T>& S) {
  return exact::with_exact_ring<T>([&]<class Rg>() {
    namespace rg = exact::ring;
    const Index k = R.cols();
    const std::vector<Rg> rays = rg::to_ring_rows<Rg>(R), rows = rg::to_ring_rows<Rg>(S);
    std::vector<std::vector<bool>> z(static_cast<size_t>(S.rows()), std::vector<bool>(static_cast<size_t>(R.rows())));
    Rg x;
    for (Index s = 0; s < S.rows(); ++s)
      for (Index r = 0; r < R.rows(); ++r) {
        rg::dot(&rows[static_cast<size_t>(s * k)], &rays[static_cast<size_t>(r * k)], k, x);
        z[static_cast<size_t>(s)][static_cast<size_t>(r)] = rg::sign(x) == 0;
      }
    return z;
  });
}

bool subset(const std::vector<bool>& a, const std::vector<bool>& b) {
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i] && !b[i]) return false;
  return true;
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
  // K' = { F g <= 0, S g <= 0, E g = 0 }: minimal generators and facets.
  out.closure = canonical(to_span(cone, budget));
  const Mat<T>& R = out.closure.rays;
  // Z_s for every strict row; the cone is empty iff some Z_s holds every ray (s vanishes on K').
  std::vector<std::vector<bool>> zs = zero_sets<T>(R, cone.strict);
  bool empty = false;
  for (const auto& z : zs)
    if (std::all_of(z.begin(), z.end(), [](bool b) { return b; })) empty = true;
  if (empty) {
    out.status = NncStatus::kEmpty;
    // Encoded as { g = 0, 0 . g < 0 } (canonical equalities: the identity rows, sorted).
    const Mat<T> all =
        canonical(FaceCone<T>::from_rows(d, Mat<T>(0, d), Mat<T>(Mat<T>::Identity(d, d)), Mat<T>(0, d))).equalities;
    out.face = FaceCone<T>::from_rows(d, Mat<T>(0, d), all, Mat<T>(Mat<T>::Zero(1, d)));
    out.closure = SpanCone<T>::from_rows(d, Mat<T>(0, d), Mat<T>(0, d));
    out.closure_face = FaceCone<T>::from_rows(d, Mat<T>(0, d), out.face.equalities, Mat<T>(0, d));
    return out;
  }
  out.status = NncStatus::kNonEmpty;
  out.closure_face = canonical(to_face(out.closure, budget));
  const Mat<T>& F = out.closure_face.inequalities;

  // Maximal missing faces: the maximal sets among the Z_s (duplicates removed).
  std::sort(zs.begin(), zs.end());
  zs.erase(std::unique(zs.begin(), zs.end()), zs.end());
  std::vector<std::vector<bool>> maximal;
  for (size_t i = 0; i < zs.size(); ++i) {
    bool dominated = false;
    for (size_t j = 0; j < zs.size() && !dominated; ++j) dominated = j != i && subset(zs[i], zs[j]);
    if (!dominated) maximal.push_back(zs[i]);
  }
  const std::vector<std::vector<bool>> facet_rays = zero_sets<T>(R, F);
  out.open_facets.assign(static_cast<size_t>(F.rows()), false);
  std::vector<Vec<T>> strict_rows;
  for (const auto& g : maximal) {
    std::vector<Index> rays;
    for (size_t r = 0; r < g.size(); ++r)
      if (g[r]) rays.push_back(static_cast<Index>(r));
    out.open_faces.push_back(rays);
    // The facets through g; g is one of them iff it is a facet itself (same ray set).
    Vec<T> s = Vec<T>::Zero(d);
    for (Index f = 0; f < F.rows(); ++f) {
      if (!subset(g, facet_rays[static_cast<size_t>(f)])) continue;
      if (facet_rays[static_cast<size_t>(f)] == g) {
        out.open_facets[static_cast<size_t>(f)] = true;
        s = F.row(f).transpose();
        break;
      }
      s += F.row(f).transpose();
    }
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

#define CONTACTCERT_NNC_INSTANTIATE(T)                                  \
  template struct NncForm<T>;                                           \
  template NncForm<T> nnc_form<T>(const FaceCone<T>&, const DdBudget&); \
  template bool contains_point<T>(const FaceCone<T>&, const Vec<T>&);   \
  template PointPosition<T> locate<T>(const FaceCone<T>&, const Vec<T>&);
CONTACTCERT_NNC_INSTANTIATE(double)
CONTACTCERT_NNC_INSTANTIATE(Q)
CONTACTCERT_NNC_INSTANTIATE(exact::Mpfr)
CONTACTCERT_NNC_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_NNC_INSTANTIATE

}  // namespace contactcert::geometry
