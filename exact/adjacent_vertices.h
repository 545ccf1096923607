// Adjacent extreme points and extreme rays of the polyhedron {x >= 0 : A x = b} at a vertex given by a
// basis (Murty, Linear Programming, section 3.7.1; Step 3 of the bilinear algorithm). Correct at degenerate
// vertices: every basis of the vertex is reached by degenerate pivots (breadth-first, under a budget), and
// every edge of a vertex is a single pivot from one of its bases.
#pragma once

#include <vector>

#include "exact/lp_problem.h"

namespace contactcert::exact {

struct AdjacencyOptions {
  /// Budget on the number of bases of the vertex explored (a degenerate vertex can have exponentially many).
  long max_bases = 100000;
};

enum class AdjacencyStatus { kComplete, kBudgetExceeded };

/// One edge of the polyhedron leaving the vertex.
template <class T>
struct Edge {
  Vec<T> direction;  ///< edge direction, scaled so that its first non-zero entry is +-1
  bool bounded = true;  ///< true: the edge ends at `neighbour`; false: an extreme ray of the polyhedron
  Vec<T> neighbour;  ///< the adjacent vertex (bounded edges only)
  std::vector<Eigen::Index> neighbour_basis;  ///< a basis of `neighbour` (bounded edges only)
  std::vector<Eigen::Index> basis;  ///< a basis of the vertex from which the pivot on `entering` follows the edge
  Eigen::Index entering = -1;
};

/// All edges leaving the vertex, deduplicated exactly (by direction), and all bases of the vertex explored.
template <class T>
struct AdjacentResult {
  AdjacencyStatus status = AdjacencyStatus::kComplete;  ///< kBudgetExceeded: edges may be incomplete
  Vec<T> vertex;
  std::vector<Edge<T>> edges;
  std::vector<std::vector<Eigen::Index>> vertex_bases;  ///< each sorted
  long pivots = 0;

  /// The adjacent vertices (endpoints of bounded edges).
  std::vector<Vec<T>> neighbours() const;
  /// The extreme rays leaving the vertex (directions of unbounded edges).
  std::vector<Vec<T>> rays() const;
};

/// Every adjacent vertex and every extreme ray leaving the vertex of {x >= 0 : A x = b} given by `basis`
/// (columns of A, |basis| = rank A, primal feasible). Only problem.A and problem.b are used; free variables
/// are not allowed. Throws std::invalid_argument if `basis` is not a feasible basis.
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
