// Adjacent extreme points and extreme rays of the polyhedron {x >= 0 : A x = b} at a vertex given by a
// basis (Murty, Linear Programming, section 3.7.1; Step 3 of the bilinear algorithm). Correct at degenerate
// vertices without enumerating their bases: the edges are the extreme rays of the tangent cone
// {d : A d = 0, d_j >= 0 where x_j = 0}, computed in the non-basic coordinates of the given basis by the double
// description method (tangent_cone.h), each followed by one exact ratio test (ANCHORS.md).
#pragma once

#include <vector>

#include "exact/lp_problem.h"

namespace contactcert::exact {

struct AdjacencyOptions {
  /// Work budget at a degenerate vertex: the number of intermediate rays of the tangent cone conversion
  /// (the name is kept from the first version, which enumerated bases).
  long max_bases = 100000;
};

/// kBasisNotFeasible: in T's arithmetic the given basis is singular or its vertex has a negative entry. It cannot
/// happen in exact arithmetic for a basis an exact LP returned; a float rung's basis, rebuilt by another pivot order,
/// can round that way at extreme magnitudes, and then no edge is known (a float verdict is checked exactly anyway).
enum class AdjacencyStatus { kComplete, kBudgetExceeded, kBasisNotFeasible };

/// One edge of the polyhedron leaving the vertex.
template <class T>
struct Edge {
  Vec<T> direction;     ///< edge direction, scaled so that its first non-zero entry is +-1
  bool bounded = true;  ///< true: the edge ends at `neighbour`; false: an extreme ray of the polyhedron
  Vec<T> neighbour;     ///< the adjacent vertex (bounded edges only)
  std::vector<Eigen::Index> neighbour_basis;  ///< a basis of `neighbour` (bounded edges only)
  std::vector<Eigen::Index> basis;            ///< the given basis of the vertex
  Eigen::Index entering = -1;  ///< the column whose pivot from `basis` follows the edge, -1 if not a single pivot
};

/// All edges leaving the vertex, each once (distinct extreme rays of the tangent cone).
template <class T>
struct AdjacentResult {
  AdjacencyStatus status =
      AdjacencyStatus::kComplete;  ///< kBudgetExceeded: only the edges that are single pivots from the given basis
  Vec<T> vertex;
  std::vector<Edge<T>> edges;
  std::vector<std::vector<Eigen::Index>> vertex_bases;  ///< bases of the vertex used (sorted): the given one
  long pivots = 0;                                      ///< pivots done to find the neighbours' bases

  /// The adjacent vertices (endpoints of bounded edges).
  std::vector<Vec<T>> neighbours() const;
  /// The extreme rays leaving the vertex (directions of unbounded edges).
  std::vector<Vec<T>> rays() const;
};

/// Every adjacent vertex and every extreme ray leaving the vertex of {x >= 0 : A x = b} given by `basis`
/// (columns of A, |basis| = rank A, primal feasible). Only problem.A and problem.b are used; free variables
/// are not allowed. Status kBasisNotFeasible, and no edges, if `basis` is not a feasible basis in T.
template <class T>
AdjacentResult<T> adjacent_vertices(const LpProblem<T>& problem, const std::vector<Eigen::Index>& basis,
                                    const AdjacencyOptions& options = {});

extern template struct AdjacentResult<double>;
extern template struct AdjacentResult<Q>;
extern template AdjacentResult<double> adjacent_vertices<double>(const LpProblem<double>&,
                                                                 const std::vector<Eigen::Index>&,
                                                                 const AdjacencyOptions&);
extern template AdjacentResult<Q> adjacent_vertices<Q>(const LpProblem<Q>&, const std::vector<Eigen::Index>&,
                                                       const AdjacencyOptions&);

}  // namespace contactcert::exact
