#include "geometry/double_description.h"

#include <cstdint>
#include <string>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/int_matrix.h"
#include "exact/ladder_numbers.h"

namespace contactcert::geometry {
namespace {

using Index = Eigen::Index;
namespace rg = exact::ring;

// Rows of one side of a cone C sorted out by their zero sets over the minimal generators D of the other
// side (C's facets for generators, C's extreme rays for inequality rows): a row vanishing on all of D
// lies in the lineality space (is an implicit equality); otherwise it is extreme (a facet) iff no other
// row's zero set strictly contains its own (a face is determined by its zero set), and of rows with
// equal zero sets one is kept.
struct Incidence {
  std::vector<Index> lineal, extreme;
};

template <class R>
Incidence sort_by_incidence(const exact::IntMatrix<R>& G, const exact::IntMatrix<R>& D, const DdBudget& budget) {
  const auto g_rows = static_cast<std::size_t>(G.rows()), d_rows = static_cast<std::size_t>(D.rows());
  const std::size_t words = (d_rows + 63) / 64;
  std::vector<std::uint64_t> z(g_rows * words, 0);
  std::vector<std::size_t> pop(g_rows, 0);
  R x;
  for (std::size_t i = 0; i < g_rows; ++i)
    for (std::size_t j = 0; j < d_rows; ++j) {
      rg::dot(G.row(static_cast<Index>(i)), D.row(static_cast<Index>(j)), G.cols(), x);
      if (rg::sign(x) != 0) continue;
      z[i * words + j / 64] |= std::uint64_t{1} << (j % 64);
      ++pop[i];
    }
  Incidence out;
  exact::WorkMeter meter(budget);
  std::vector<std::size_t> candidates;
  for (std::size_t i = 0; i < g_rows; ++i)
    if (pop[i] == d_rows)
      out.lineal.push_back(static_cast<Index>(i));
    else
      candidates.push_back(i);
  for (std::size_t i : candidates) {
    meter.charge(candidates.size(), [&] { return std::to_string(out.extreme.size()) + " extreme rows found"; });
    bool keep = true;
    for (std::size_t j : candidates) {
      if (j == i || pop[j] < pop[i] || (pop[j] == pop[i] && j > i)) continue;  // equal sets: the first is kept
      bool contains = true;
      for (std::size_t w = 0; w < words && contains; ++w) contains = (z[i * words + w] & ~z[j * words + w]) == 0;
      if ((keep = !contains) == false) break;
    }
    if (keep) out.extreme.push_back(static_cast<Index>(i));
  }
  return out;
}

}  // namespace

namespace {

// One side of a cone given by rows G (generators, or inequalities) and L (lines, or equalities): the
// other side's minimal form by the double description, and the minimal form of this side picked from
// the given rows by incidence (rows vanishing on every dual generator join L).
template <class R>
struct RingPair {
  RingGenerators<R> dual;
  exact::IntMatrix<R> extreme, lineal;
};

template <class R>
RingPair<R> ring_pair(exact::IntMatrix<R> G, exact::IntMatrix<R> L, const DdBudget& budget) {
  exact::sort_rows(G);
  exact::sort_rows(L);
  RingPair<R> out;
  out.dual = cone_generators<R>(G, L, budget);
  const Incidence inc = sort_by_incidence<R>(G, out.dual.rays, budget);
  out.extreme = G.select_rows(inc.extreme);
  out.lineal = std::move(L);
  for (Index i : inc.lineal) out.lineal.append_row(G.row(i));
  return out;
}

// The inequality rows of the closure of a face cone (strict rows read as non-strict) as ring rows.
template <class R, class T>
exact::IntMatrix<R> closure_rows(const FaceCone<T>& cone) {
  exact::IntMatrix<R> A = rg::to_ring_rows<R>(cone.inequalities);
  const exact::IntMatrix<R> S = rg::to_ring_rows<R>(cone.strict);
  for (Index i = 0; i < S.rows(); ++i) A.append_row(S.row(i));
  return A;
}

}  // namespace

// Facets of C = pos(rays) + span(lines) are the extreme rays of its polar { f : R f <= 0, L f = 0 }; the
// polar's lineality space is the orthogonal complement of C's linear hull (the equalities). The
// iteration runs in std::int64_t and restarts in Z if a number outgrows it (T = Q), in T for a float T.
template <class T>
FaceCone<T> to_face(const SpanCone<T>& cone, const DdBudget& budget) {
  const Index n = cone.dim;
  return exact::with_exact_ring<T>([&]<class R>() {
    const RingGenerators<R> polar =
        cone_generators<R>(rg::to_ring_rows<R>(cone.rays), rg::to_ring_rows<R>(cone.lines), budget);
    return FaceCone<T>::from_rows(n, rg::to_field_rows<T>(polar.rays, n), rg::to_field_rows<T>(polar.lines, n),
                                  Mat<T>(0, n));
  });
}

template <class T>
SpanCone<T> to_span(const FaceCone<T>& cone, const DdBudget& budget) {
  const Index n = cone.dim;
  return exact::with_exact_ring<T>([&]<class R>() {
    const RingGenerators<R> g = cone_generators<R>(closure_rows<R>(cone), rg::to_ring_rows<R>(cone.equalities), budget);
    return SpanCone<T>::from_rows(n, rg::to_field_rows<T>(g.rays, n), rg::to_field_rows<T>(g.lines, n));
  });
}

template <class T>
ConePair<T> both_forms(const SpanCone<T>& cone, const DdBudget& budget) {
  const Index n = cone.dim;
  return exact::with_exact_ring<T>([&]<class R>() {
    const RingPair<R> p = ring_pair<R>(rg::to_ring_rows<R>(cone.rays), rg::to_ring_rows<R>(cone.lines), budget);
    ConePair<T> out;
    out.face = FaceCone<T>::from_rows(n, rg::to_field_rows<T>(p.dual.rays, n), rg::to_field_rows<T>(p.dual.lines, n),
                                      Mat<T>(0, n));
    out.span = SpanCone<T>::from_rows(n, rg::to_field_rows<T>(p.extreme, n), rg::to_field_rows<T>(p.lineal, n));
    return out;
  });
}

template <class T>
ConePair<T> both_forms(const FaceCone<T>& cone, const DdBudget& budget) {
  const Index n = cone.dim;
  return exact::with_exact_ring<T>([&]<class R>() {
    const RingPair<R> p = ring_pair<R>(closure_rows<R>(cone), rg::to_ring_rows<R>(cone.equalities), budget);
    ConePair<T> out;
    out.span = SpanCone<T>::from_rows(n, rg::to_field_rows<T>(p.dual.rays, n), rg::to_field_rows<T>(p.dual.lines, n));
    out.face =
        FaceCone<T>::from_rows(n, rg::to_field_rows<T>(p.extreme, n), rg::to_field_rows<T>(p.lineal, n), Mat<T>(0, n));
    return out;
  });
}

#define CONTACTCERT_DD_INSTANTIATE(T)                                      \
  template FaceCone<T> to_face<T>(const SpanCone<T>&, const DdBudget&);    \
  template SpanCone<T> to_span<T>(const FaceCone<T>&, const DdBudget&);    \
  template ConePair<T> both_forms<T>(const SpanCone<T>&, const DdBudget&); \
  template ConePair<T> both_forms<T>(const FaceCone<T>&, const DdBudget&);
CONTACTCERT_DD_INSTANTIATE(double)
CONTACTCERT_DD_INSTANTIATE(Q)
CONTACTCERT_DD_INSTANTIATE(exact::Mpfr)
CONTACTCERT_DD_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_DD_INSTANTIATE

}  // namespace contactcert::geometry
