#include "exact/adjacent_vertices.h"

#include <algorithm>
#include <stdexcept>

#include "exact/field_ops.h"
#include "exact/interval_number.h"
#include "exact/mpfr_number.h"
#include "exact/simplex_tableau.h"
#include "exact/tangent_cone.h"

namespace contactcert::exact {

namespace {

using Index = Eigen::Index;

/// Scales d so that its first non-zero entry is +-1.
template <class T>
Vec<T> normalised(Vec<T> d) {
  for (Index i = 0; i < d.size(); ++i) {
    if (exact::is_zero(d(i))) continue;
    const T scale = exact::sign(d(i)) > 0 ? T(d(i)) : T(-d(i));
    for (Index k = 0; k < d.size(); ++k) d(k) /= scale;
    return d;
  }
  return d;
}

std::vector<Index> sorted(std::vector<Index> v) {
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

template <class T>
std::vector<Vec<T>> AdjacentResult<T>::neighbours() const {
  std::vector<Vec<T>> out;
  for (const Edge<T>& e : edges)
    if (e.bounded) out.push_back(e.neighbour);
  return out;
}

template <class T>
std::vector<Vec<T>> AdjacentResult<T>::rays() const {
  std::vector<Vec<T>> out;
  for (const Edge<T>& e : edges)
    if (!e.bounded) out.push_back(e.direction);
  return out;
}

template <class T>
AdjacentResult<T> adjacent_vertices(const LpProblem<T>& problem, const std::vector<Index>& basis,
                                    const AdjacencyOptions& options) {
  for (Index j = 0; j < problem.cols(); ++j)
    if (problem.free(j)) throw std::invalid_argument("adjacent_vertices: free variables are not allowed");
  AdjacentResult<T> res;
  std::optional<SimplexTableau<T>> start = SimplexTableau<T>::from_basis(problem.A, problem.b, basis);
  const auto infeasible = [](const SimplexTableau<T>& t) {
    for (Index r = 0; r < t.rows(); ++r)
      if (exact::is_negative(t.rhs(r))) return true;
    return false;
  };
  if (!start || infeasible(*start)) {
    res.status = AdjacencyStatus::kBasisNotFeasible;
    return res;
  }
  const SimplexTableau<T>& tab = *start;
  res.vertex = tab.primal();
  res.vertex_bases.push_back(sorted(tab.basis()));
  const Index n = problem.cols(), m = tab.rows();

  // The tangent cone {d : A d = 0, d_j >= 0 where x_j = 0} in the non-basic coordinates w = d_N:
  // w >= 0 and, for each degenerate row r (basic variable at 0), d_B(r) = -(T_N w)_r >= 0.
  std::vector<Index> N, degenerate;
  for (Index j = 0; j < n; ++j)
    if (!tab.is_basic(j)) N.push_back(j);
  for (Index r = 0; r < m; ++r)
    if (exact::is_zero(tab.rhs(r))) degenerate.push_back(r);
  const Index p = static_cast<Index>(N.size());
  Mat<T> G(static_cast<Index>(degenerate.size()), p);
  for (size_t i = 0; i < degenerate.size(); ++i)
    for (Index k = 0; k < p; ++k) G(static_cast<Index>(i), k) = tab.entry(degenerate[i], N[static_cast<size_t>(k)]);
  std::optional<std::vector<Vec<T>>> cone = orthant_cone_rays<T>(G, options.max_bases);
  if (!cone) {
    // Keep the edges that are single pivots from this basis: non-basic columns with G e_k <= 0.
    res.status = AdjacencyStatus::kBudgetExceeded;
    cone.emplace();
    for (Index k = 0; k < p; ++k) {
      bool feasible = true;
      for (Index i = 0; i < G.rows() && feasible; ++i) feasible = !exact::is_positive(G(i, k));
      if (!feasible) continue;
      Vec<T> e = Vec<T>::Zero(p);
      e(k) = T(1);
      cone->push_back(std::move(e));
    }
  }

  // Each extreme ray of the tangent cone is an edge; one ratio test along it finds its other end.
  T tmp;
  for (const Vec<T>& w : *cone) {
    Vec<T> d = Vec<T>::Zero(n);
    Index single = -1, support = 0;
    for (Index k = 0; k < p; ++k) {
      if (exact::is_zero(w(k))) continue;
      d(N[static_cast<size_t>(k)]) = w(k);
      single = N[static_cast<size_t>(k)];
      ++support;
    }
    for (Index r = 0; r < m; ++r) {
      T& dr = d(tab.basis()[static_cast<size_t>(r)]);
      for (Index k = 0; k < p; ++k)
        if (!exact::is_zero(w(k))) sub_mul(dr, tab.entry(r, N[static_cast<size_t>(k)]), w(k), tmp);
    }
    Index block = -1;
    T step = T(0);
    for (Index r = 0; r < m; ++r) {
      const T& dr = d(tab.basis()[static_cast<size_t>(r)]);
      if (!exact::is_negative(dr)) continue;
      const T ratio = tab.rhs(r) / T(-dr);
      if (block < 0 || exact::sign(T(ratio - step)) < 0) {
        block = r;
        step = ratio;
      }
    }
    Edge<T> edge;
    edge.direction = normalised(d);
    edge.bounded = block >= 0;
    edge.basis = tab.basis();
    edge.entering = support == 1 ? single : -1;
    if (edge.bounded && support == 1) {
      // A simplex pivot: the entering column replaces the blocking row's basic variable.
      edge.neighbour = res.vertex + step * d;
      for (Index j = 0; j < n; ++j)
        if (!exact::is_positive(edge.neighbour(j))) edge.neighbour(j) = T(0);
      edge.neighbour_basis = tab.basis();
      edge.neighbour_basis[static_cast<size_t>(block)] = single;
    } else if (edge.bounded) {
      // A basis of the neighbour: pivot each column of its support into a row whose basic variable is 0 there.
      Vec<T> u = res.vertex + step * d;
      for (Index j = 0; j < n; ++j)
        if (!exact::is_positive(u(j))) u(j) = T(0);
      SimplexTableau<T> next = tab;
      for (Index j = 0; j < n; ++j) {
        if (exact::is_zero(u(j)) || next.is_basic(j)) continue;
        Index r = -1;
        for (Index i = 0; i < next.rows(); ++i) {
          if (exact::is_zero(next.entry(i, j)) || !exact::is_zero(u(next.basis()[static_cast<size_t>(i)]))) continue;
          if (r < 0 || NumberTraits<T>::better_pivot(next.entry(i, j), next.entry(r, j))) r = i;
        }
        if (r >= 0) next.pivot(r, j);
        ++res.pivots;
      }
      edge.neighbour = next.primal();
      edge.neighbour_basis = next.basis();
    }
    res.edges.push_back(std::move(edge));
  }
  return res;
}

template struct AdjacentResult<double>;
template struct AdjacentResult<Q>;
template AdjacentResult<double> adjacent_vertices<double>(const LpProblem<double>&, const std::vector<Index>&,
                                                          const AdjacencyOptions&);
template AdjacentResult<Q> adjacent_vertices<Q>(const LpProblem<Q>&, const std::vector<Index>&,
                                                const AdjacencyOptions&);
template struct AdjacentResult<Mpfr>;
template struct AdjacentResult<Interval>;
template AdjacentResult<Mpfr> adjacent_vertices<Mpfr>(const LpProblem<Mpfr>&, const std::vector<Index>&,
                                                      const AdjacencyOptions&);
template AdjacentResult<Interval> adjacent_vertices<Interval>(const LpProblem<Interval>&, const std::vector<Index>&,
                                                              const AdjacencyOptions&);

}  // namespace contactcert::exact
