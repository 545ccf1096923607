#include "exact/adjacent_vertices.h"

#include <algorithm>
#include <deque>
#include <set>
#include <stdexcept>

#include "exact/simplex_tableau.h"

namespace contactcert::exact {

namespace {

using Index = Eigen::Index;

/// Scales d so that its first non-zero entry is +-1.
template <class T>
Vec<T> normalised(Vec<T> d) {
  for (Index i = 0; i < d.size(); ++i) {
    if (is_zero(d(i))) continue;
    const T scale = sign(d(i)) > 0 ? T(d(i)) : T(-d(i));
    for (Index k = 0; k < d.size(); ++k) d(k) /= scale;
    return d;
  }
  return d;
}

template <class T>
bool same_vector(const Vec<T>& a, const Vec<T>& b) {
  for (Index i = 0; i < a.size(); ++i)
    if (!is_zero(T(a(i) - b(i)))) return false;
  return true;
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
  std::optional<SimplexTableau<T>> start = SimplexTableau<T>::from_basis(problem.A, problem.b, basis);
  if (!start) throw std::invalid_argument("adjacent_vertices: not a basis of A x = b");
  for (Index r = 0; r < start->rows(); ++r)
    if (is_negative(start->rhs(r))) throw std::invalid_argument("adjacent_vertices: basis is not feasible");

  AdjacentResult<T> res;
  res.vertex = start->primal();
  const Index n = problem.cols();
  std::set<std::vector<Index>> seen{sorted(start->basis())};
  std::deque<SimplexTableau<T>> queue;
  queue.push_back(std::move(*start));

  // Breadth-first search over the bases of the vertex: a pivot in a row at level 0 (any non-zero entry)
  // keeps the vertex. From each basis, every non-basic column with a positive step (or none) is an edge.
  while (!queue.empty()) {
    SimplexTableau<T> tab = std::move(queue.front());
    queue.pop_front();
    res.vertex_bases.push_back(sorted(tab.basis()));
    for (Index j = 0; j < n; ++j) {
      if (tab.is_basic(j)) continue;
      Index r = -1;
      T step = T(0);
      for (Index i = 0; i < tab.rows(); ++i) {
        if (!is_positive(tab.entry(i, j))) continue;
        const T ratio = tab.rhs(i) / tab.entry(i, j);
        if (r < 0 || sign(T(ratio - step)) < 0) {
          r = i;
          step = ratio;
        }
      }
      if (r < 0 || is_positive(step)) {
        Vec<T> d = Vec<T>::Zero(n);
        d(j) = T(1);
        for (Index i = 0; i < tab.rows(); ++i) d(tab.basis()[static_cast<size_t>(i)]) = -tab.entry(i, j);
        Edge<T> edge;
        edge.direction = normalised(d);
        const bool known = std::any_of(res.edges.begin(), res.edges.end(),
                                       [&](const Edge<T>& e) { return same_vector(e.direction, edge.direction); });
        if (!known) {
          edge.bounded = r >= 0;
          edge.basis = tab.basis();
          edge.entering = j;
          if (edge.bounded) {
            edge.neighbour = res.vertex + step * d;
            edge.neighbour_basis = tab.basis();
            edge.neighbour_basis[static_cast<size_t>(r)] = j;
          }
          res.edges.push_back(std::move(edge));
        }
      }
      for (Index i = 0; i < tab.rows(); ++i) {
        if (!is_zero(tab.rhs(i)) || is_zero(tab.entry(i, j))) continue;
        std::vector<Index> next = tab.basis();
        next[static_cast<size_t>(i)] = j;
        if (!seen.insert(sorted(next)).second) continue;
        if (static_cast<long>(seen.size()) > options.max_bases) {
          res.status = AdjacencyStatus::kBudgetExceeded;
          continue;
        }
        SimplexTableau<T> child = tab;
        child.pivot(i, j);
        ++res.pivots;
        queue.push_back(std::move(child));
      }
    }
  }
  return res;
}

template struct AdjacentResult<double>;
template struct AdjacentResult<Q>;
template AdjacentResult<double> adjacent_vertices<double>(const LpProblem<double>&, const std::vector<Index>&,
                                                          const AdjacencyOptions&);
template AdjacentResult<Q> adjacent_vertices<Q>(const LpProblem<Q>&, const std::vector<Index>&,
                                                const AdjacencyOptions&);

}  // namespace contactcert::exact
