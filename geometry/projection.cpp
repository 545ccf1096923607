#include "geometry/projection.h"

#include <algorithm>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/int_matrix.h"
#include "exact/ladder_numbers.h"
#include "exact/linalg.h"
#include "exact/simplex.h"
#include "exact/verified_lp.h"
#include "geometry/canonical.h"

namespace contactcert::geometry {
namespace {

using Index = Eigen::Index;
using exact::is_zero;
using exact::LpProblem;
using exact::LpResult;
using exact::LpStatus;
using exact::sign;

// The LP in T (verified for Q), stopped at the budget's deadline: then BudgetExceeded with the `lps` solved
// before it (counted here).
template <class T>
LpResult<T> solve(const LpProblem<T>& lp, const DdBudget& budget, long& lps) {
  exact::LpOptions options;
  options.deadline = budget.deadline;
  LpResult<T> r;
  if constexpr (std::is_same_v<T, Q>)
    r = exact::solve_lp_verified(lp, options);
  else
    r = exact::solve_lp<T>(lp, options);
  if (r.status == LpStatus::kTimeLimit)
    throw exact::BudgetExceeded("projection by LPs: " + budget.deadline.reached_text(),
                                std::to_string(lps) + " LPs solved");
  ++lps;
  return r;
}

template <class T>
Mat<T> stack_rows(const std::vector<Vec<T>>& rows, Index dim) {
  Mat<T> M(static_cast<Index>(rows.size()), dim);
  for (Index i = 0; i < M.rows(); ++i) M.row(i) = rows[static_cast<size_t>(i)].transpose();
  return M;
}

bool any_strict(const std::vector<bool>& s) { return std::find(s.begin(), s.end(), true) != s.end(); }

// max f . g over { g : K z = P g, z >= 0, sum z <= 1 }: x = (z, g, slack); returns the optimal g.
template <class T>
LpResult<T> maximise_direction(const Mat<T>& K, const Mat<T>& P, const Vec<T>& f, const DdBudget& budget, long& lps) {
  const Index m = K.rows(), n = K.cols(), d = P.cols();
  LpProblem<T> lp;
  lp.A = Mat<T>::Zero(m + 1, n + d + 1);
  lp.A.block(0, 0, m, n) = K;
  lp.A.block(0, n, m, d) = -P;
  for (Index j = 0; j < n; ++j) lp.A(m, j) = T(1);
  lp.A(m, n + d) = T(1);
  lp.b = Vec<T>::Zero(m + 1);
  lp.b(m) = T(1);
  lp.c = Vec<T>::Zero(n + d + 1);
  for (Index j = 0; j < d; ++j) lp.c(n + j) = -f(j);
  lp.is_free.assign(static_cast<size_t>(n + d + 1), false);
  for (Index j = 0; j < d; ++j) lp.is_free[static_cast<size_t>(n + j)] = true;
  return solve(lp, budget, lps);
}

// Is P w = K z solvable with z >= 0 and z_i > 0 on the strict components? max t s.t. K z = P w,
// z_i - t - u_i = 0 (i strict), t + v = 1, all >= 0; strictly feasible iff t* > 0.
template <class T>
bool strictly_feasible(const Mat<T>& K, const Mat<T>& P, const std::vector<bool>& strict, const Vec<T>& w,
                       const DdBudget& budget, long& lps) {
  const Index m = K.rows(), n = K.cols();
  std::vector<Index> I;
  for (Index i = 0; i < n; ++i)
    if (strict[static_cast<size_t>(i)]) I.push_back(i);
  const Index s = static_cast<Index>(I.size());
  const Index cols = n + 1 + s + 1;  // z, t, u, v
  LpProblem<T> lp;
  lp.A = Mat<T>::Zero(m + s + 1, cols);
  lp.A.block(0, 0, m, n) = K;
  lp.b = Vec<T>::Zero(m + s + 1);
  lp.b.head(m) = P * w;
  for (Index k = 0; k < s; ++k) {
    lp.A(m + k, I[static_cast<size_t>(k)]) = T(1);
    lp.A(m + k, n) = T(-1);
    lp.A(m + k, n + 1 + k) = T(-1);
  }
  lp.A(m + s, n) = T(1);
  lp.A(m + s, cols - 1) = T(1);
  lp.b(m + s) = T(1);
  lp.c = Vec<T>::Zero(cols);
  lp.c(n) = T(-1);
  const LpResult<T> r = solve(lp, budget, lps);
  return r.status == LpStatus::kOptimal && sign(T(-r.value)) > 0;
}

template <class T>
FaceCone<T> whole_space(Index d) {
  return FaceCone<T>::from_rows(d, Mat<T>(0, d), Mat<T>(0, d), Mat<T>(0, d));
}

}  // namespace

template <class T>
FaceCone<T> project_by_polar(const ProjectionProblem<T>& problem, const DdBudget& budget) {
  const Index d = problem.P.cols();
  return exact::with_exact_ring<T>([&]<class R>() {
    // The rows [P | K] as ring rows (positive multiples: the same P g = K z).
    return project_by_polar_rows<T, R>(exact::ring::to_ring_rows<R>(problem.P, problem.K), d, problem.strict, budget);
  });
}

template <class T, class R>
FaceCone<T> project_by_polar_rows(const exact::IntMatrix<R>& rows, Index d, const std::vector<bool>& strict_components,
                                  const DdBudget& budget) {
  namespace rg = exact::ring;
  const Index k = rows.cols() - d;
  const std::vector<bool> strict =
      strict_components.empty() ? std::vector<bool>(static_cast<size_t>(k), false) : strict_components;
  const Index m = rows.rows();
  if (m == 0) return nnc_form(whole_space<T>(d), budget).face;
  // The columns of K (ring rows of K^T, each scaled by a positive factor: the same pos(K) up to
  // scaling z) and of P.
  exact::IntMatrix<R> kc(k, m), pc(d, m);
  for (Index i = 0; i < m; ++i) {
    for (Index j = 0; j < d; ++j) pc(j, i) = rows(i, j);
    for (Index j = 0; j < k; ++j) kc(j, i) = rows(i, d + j);
  }
  for (Index j = 0; j < k; ++j) rg::normalize(kc.row(j), m);
  // K^F: pos(K) = { y : K^F y <= 0, E_K y = 0 } (section 3); its facets are the extreme rays of the
  // polar { f : k_i . f <= 0 }, pointed unless K has a left null space E_K.
  const RingGenerators<R> KF = cone_generators<R>(kc, exact::IntMatrix<R>(0, m), budget);  // in the ring
  // A facet of pos(K) is open iff it misses a column k_i with z_i > 0: the relative interiors of the
  // faces of pos(K) that contain every such column make up { K z : z >= 0, z_i > 0 on strict }.
  exact::IntMatrix<R> closed(0, d), open(0, d), E(0, d);
  R x;
  std::vector<R> row(static_cast<size_t>(d));
  // eq. (18): F = K^F P, row by row.
  auto times_P = [&](const R* f) {
    for (Index j = 0; j < d; ++j) rg::dot(f, pc.row(j), m, row[static_cast<size_t>(j)]);
    return row.data();
  };
  for (Index r = 0; r < KF.rays.rows(); ++r) {
    const R* f = KF.rays.row(r);
    bool is_open = false;
    for (Index i = 0; i < k && !is_open; ++i) {
      if (!strict[static_cast<size_t>(i)]) continue;
      rg::dot(f, kc.row(i), m, x);
      is_open = rg::sign(x) < 0;
    }
    (is_open ? open : closed).append_row(times_P(f));
  }
  for (Index r = 0; r < KF.lines.rows(); ++r) E.append_row(times_P(KF.lines.row(r)));
  if constexpr (exact::NumberTraits<T>::is_exact)  // the float paths keep nnc_form's normal forms
    if (E.rows() == 0)
      if (auto face = pointed_nnc_face<T, R>(closed, open, budget)) return std::move(*face);
  return nnc_form(FaceCone<T>::from_rows(d, rg::to_field_rows<T>(closed, d), rg::to_field_rows<T>(E, d),
                                         rg::to_field_rows<T>(open, d)),
                  budget)
      .face;
}

template <class T>
FaceCone<T> project_by_lp(const ProjectionProblem<T>& problem, const DdBudget& budget) {
  const Mat<T>& K = problem.K;
  const Mat<T>& P = problem.P;
  const Index d = P.cols();
  const std::vector<bool> strict =
      problem.strict.empty() ? std::vector<bool>(static_cast<size_t>(K.cols()), false) : problem.strict;
  if (K.rows() == 0) return nnc_form(whole_space<T>(d), budget).face;
  long lps = 0;
  // Convex hull method: grow an inner cone pos(rays) + span(ker P) until every facet (and both sides
  // of every equality) of it is confirmed valid by an LP; each LP confirms a row or finds a new ray.
  const Mat<T> lines = exact::null_space<T>(P).transpose();
  std::vector<Vec<T>> rays;
  std::set<std::vector<T>> confirmed;
  FaceCone<T> inner;
  for (;;) {
    inner = canonical(to_face(SpanCone<T>::from_rows(d, stack_rows<T>(rays, d), lines), budget));
    std::vector<Vec<T>> candidates;
    for (Index f = 0; f < inner.inequalities.rows(); ++f) candidates.push_back(inner.inequalities.row(f).transpose());
    for (Index e = 0; e < inner.equalities.rows(); ++e) {
      candidates.push_back(inner.equalities.row(e).transpose());
      candidates.push_back(-inner.equalities.row(e).transpose());
    }
    bool grown = false;
    for (const Vec<T>& f : candidates) {
      const std::vector<T> key(f.data(), f.data() + d);
      if (confirmed.count(key)) continue;
      const LpResult<T> r = maximise_direction<T>(K, P, f, budget, lps);
      // Feasible (z = 0, g = 0) and bounded (f is orthogonal to ker P, sum z <= 1).
      if (r.status != LpStatus::kOptimal) throw std::logic_error("project_by_lp: direction LP not optimal");
      if (sign(T(-r.value)) > 0) {
        rays.push_back(r.x.segment(K.cols(), d));
        grown = true;
      } else {
        confirmed.insert(key);
      }
    }
    if (!grown) break;
  }
  if (!any_strict(strict)) return nnc_form(inner, budget).face;

  // Open faces: test the relative interior of each face of the closed cone (largest first) by one
  // strict-feasibility LP, skipping faces inside a face already known to be missing.
  const SpanCone<T> span = canonical(to_span(inner, budget));
  const Mat<T>& R = span.rays;
  const Index nr = R.rows();
  std::vector<std::vector<bool>> facet_sets;
  for (Index f = 0; f < inner.inequalities.rows(); ++f) {
    std::vector<bool> z(static_cast<size_t>(nr));
    for (Index r = 0; r < nr; ++r) z[static_cast<size_t>(r)] = is_zero(T(inner.inequalities.row(f).dot(R.row(r))));
    facet_sets.push_back(z);
  }
  std::set<std::vector<bool>> faces{std::vector<bool>(static_cast<size_t>(nr), true)};
  for (const auto& fs : facet_sets) {
    std::vector<std::vector<bool>> add;
    for (const auto& g : faces) {
      std::vector<bool> h(static_cast<size_t>(nr));
      for (size_t r = 0; r < h.size(); ++r) h[r] = g[r] && fs[r];
      add.push_back(h);
    }
    faces.insert(add.begin(), add.end());
  }
  std::vector<std::vector<bool>> order(faces.begin(), faces.end());
  auto size = [](const std::vector<bool>& v) { return std::count(v.begin(), v.end(), true); };
  std::stable_sort(order.begin(), order.end(), [&](const auto& a, const auto& b) { return size(a) > size(b); });
  std::vector<std::vector<bool>> missing;  // maximal missing faces
  for (const auto& g : order) {
    bool below = false;
    for (const auto& mset : missing) below = below || is_subset(g, mset);
    if (below) continue;
    Vec<T> w = Vec<T>::Zero(d);
    for (Index r = 0; r < nr; ++r)
      if (g[static_cast<size_t>(r)]) w += R.row(r).transpose();
    if (!strictly_feasible<T>(K, P, strict, w, budget, lps)) missing.push_back(g);
  }
  // One strict row per maximal missing face: the sum of the normals of the facets through it.
  std::vector<Vec<T>> strict_rows;
  for (const std::vector<Index>& through : missing_faces(missing, facet_sets).facets) {
    Vec<T> s = Vec<T>::Zero(d);
    for (Index f : through) s += inner.inequalities.row(f).transpose();
    strict_rows.push_back(s);
  }
  return nnc_form(FaceCone<T>::from_rows(d, inner.inequalities, inner.equalities, stack_rows<T>(strict_rows, d)),
                  budget)
      .face;
}

template <class T>
AffineFace<T> theorem1(const Mat<T>& K, const Mat<T>& P, const Vec<T>& k, const DdBudget& budget) {
  // Theorem 1: K z = P g, z >= k  <=>  K^F P g <= K^F K k.
  const FaceCone<T> KF = to_face(SpanCone<T>::from_columns(K), budget);
  AffineFace<T> out;
  out.A = KF.inequalities * P;
  out.b = KF.inequalities * (K * k);
  out.C = KF.equalities * P;
  out.c = KF.equalities * (K * k);
  return out;
}

template FaceCone<double> project_by_polar_rows<double, double>(const exact::IntMatrix<double>&, Index,
                                                                const std::vector<bool>&, const DdBudget&);
template FaceCone<Q> project_by_polar_rows<Q, std::int64_t>(const exact::IntMatrix<std::int64_t>&, Index,
                                                            const std::vector<bool>&, const DdBudget&);
template FaceCone<Q> project_by_polar_rows<Q, Z>(const exact::IntMatrix<Z>&, Index, const std::vector<bool>&,
                                                 const DdBudget&);
template FaceCone<exact::Mpfr> project_by_polar_rows<exact::Mpfr, exact::Mpfr>(const exact::IntMatrix<exact::Mpfr>&,
                                                                               Index, const std::vector<bool>&,
                                                                               const DdBudget&);
template FaceCone<exact::Interval> project_by_polar_rows<exact::Interval, exact::Interval>(
    const exact::IntMatrix<exact::Interval>&, Index, const std::vector<bool>&, const DdBudget&);

#define CONTACTCERT_PROJECTION_INSTANTIATE(T)                                             \
  template FaceCone<T> project_by_polar<T>(const ProjectionProblem<T>&, const DdBudget&); \
  template FaceCone<T> project_by_lp<T>(const ProjectionProblem<T>&, const DdBudget&);    \
  template AffineFace<T> theorem1<T>(const Mat<T>&, const Mat<T>&, const Vec<T>&, const DdBudget&);
CONTACTCERT_PROJECTION_INSTANTIATE(double)
CONTACTCERT_PROJECTION_INSTANTIATE(Q)
CONTACTCERT_PROJECTION_INSTANTIATE(exact::Mpfr)
CONTACTCERT_PROJECTION_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_PROJECTION_INSTANTIATE

}  // namespace contactcert::geometry
