// Complete exact search for the UCP, beyond the paper: branch and bound over the complementarity
// conditions x_i y_i = 0. A node fixes x_i = 0 for i in Fx and y_i = 0 for i in Fy; because the problem is
// uncoupled, the node is dead as soon as the face X_Fx or the face Y_Fy is empty, each decided by its own LP
// and proven by a Farkas vector. The bilinear algorithm is the primal heuristic. The tree with a Farkas
// vector at every dead leaf is the certificate that no complementary pair exists ("jammed").
#pragma once

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "solvers/ucp/bilinear.h"

namespace contactcert::solvers::ucp {

/// The verdict of SPEC section 7.
enum class UcpStatus { kSolvable, kJammed, kUnknown };

/// Which polyhedron a dead leaf proves empty.
enum class Side { kX, kY };

/// One node of the search tree. Internal: branch index i, child with x_i = 0 and child with y_i = 0.
/// Leaf: the face of `side` under the node's fixings is empty, proven by `farkas` (over the rows of that
/// polyhedron's A: farkas^T A_j >= 0 for every column j not fixed to 0 on that side, farkas^T b < 0).
template <class T>
struct SearchNode {
  Eigen::Index branch = -1;
  long child_x_zero = -1, child_y_zero = -1;
  Side side = Side::kX;
  Vec<T> farkas;
  /// Leaf: the basis of the LP that found `farkas` (FaceLpResult::farkas_basis; empty if unknown). Lets a
  /// float tree's leaf be proven exactly from its basis (float_check.h).
  std::vector<Eigen::Index> farkas_basis;
  bool is_leaf() const { return branch < 0; }
};

struct SearchOptions {
  long max_nodes = 200000;     ///< node budget: the search ends `unknown` when it runs out
  bool bilinear_first = true;  ///< run the bilinear algorithm on X x Y before branching (SPEC default)
  BilinearOptions heuristic{Step3Rule::kModified, 20, 2000, 100000, Arith::kVerified, {}};
  int node_rounds = 3;       ///< Step-1 rounds of the heuristic at each node
  exact::Deadline deadline;  ///< time budget (also passed to the heuristic): the search ends `unknown`
  std::function<void(long nodes, long lps)> progress;  ///< called at every new node (rate-limit in the callee)
};

/// Result with evidence: a complementary pair (kSolvable), or the search tree (kJammed, node 0 = root).
template <class T>
struct SearchResult {
  UcpStatus status = UcpStatus::kUnknown;
  Vec<T> x, y;
  T xTy = T(0);         ///< best x^T y seen (if paired)
  bool paired = false;  ///< a pair was reached (false only if a budget ran out before the first one)
  std::vector<SearchNode<T>> tree;
  std::string reason;       ///< "X is empty", "Y is empty", "search tree", "bilinear algorithm", ...
  long nodes = 0;           ///< nodes created
  long learned_prunes = 0;  ///< nodes proven dead by an earlier Farkas vector, without an LP
  long pairs = 0;           ///< pairs of the bilinear heuristic at the root
  LpCounters counters;
};

/// How a jammed verdict with this search tree is named: "X is empty" / "Y is empty" for a root leaf, else
/// "search tree".
template <class T>
const char* jammed_reason(const std::vector<SearchNode<T>>& tree) {
  if (tree.size() > 1) return "search tree";
  return tree[0].side == Side::kX ? "X is empty" : "Y is empty";
}

/// Decides the UCP exactly for T = Q (the float path T = double mirrors it without proof).
template <class T>
SearchResult<T> complete_search(const UcpInstance<T>& ucp, const SearchOptions& opts, std::mt19937_64& rng);

/// Searches the subtree of node `id` of out.tree, whose fixings are (zx, zy), as complete_search does below
/// the root (no bilinear phase, no earlier Farkas vectors); new nodes are appended to out.tree and counted in
/// out.counters. kSolvable: out.x, out.y is a complementary pair; kJammed: every leaf of the subtree has its
/// Farkas vector; kUnknown: the node or time budget ran out (the subtree is then incomplete).
template <class T>
UcpStatus search_subtree(const UcpInstance<T>& ucp, const SearchOptions& opts, SearchResult<T>& out, long id,
                         std::vector<bool>& zx, std::vector<bool>& zy);

extern template UcpStatus search_subtree<Q>(const UcpInstance<Q>&, const SearchOptions&, SearchResult<Q>&, long,
                                            std::vector<bool>&, std::vector<bool>&);
extern template SearchResult<double> complete_search<double>(const UcpInstance<double>&, const SearchOptions&,
                                                             std::mt19937_64&);
extern template SearchResult<Q> complete_search<Q>(const UcpInstance<Q>&, const SearchOptions&, std::mt19937_64&);

}  // namespace contactcert::solvers::ucp
