// Exact checks of UCP verdicts found in floating point (the rungs of --arith adaptive below exact). A float
// complementary pair is trusted only through its zero pattern and a float search tree only through its
// shape: the numbers that prove the verdict are recomputed or checked in exact arithmetic, so a verdict that
// passes is the exact one (SPEC section 7).
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "solvers/ucp/search.h"

namespace contactcert::solvers::ucp {

/// An exact complementary pair with the zero pattern of a float one (x_approx, y_approx): x in X with x_i = 0
/// where x_zero[i], y in Y with y_i = 0 where y_zero[i]. Every index must be in one pattern (then x^T y = 0).
/// Each side is first the exact solution on the float point's support if it is unique and >= 0 (a vertex:
/// exact::IntMatrix::solve), else the float point rounded to fractions and checked (exact::rounded_point), both
/// in 128-bit integers with a restart in GMP on overflow, else an exact face LP. nullopt if one of the two faces is
/// empty in exact arithmetic.
std::optional<std::pair<Vec<Q>, Vec<Q>>> exact_pair(const UcpProblem& problem, const Vec<double>& x_approx,
                                                    const Vec<double>& y_approx, const std::vector<bool>& x_zero,
                                                    const std::vector<bool>& y_zero, LpCounters& count);

/// The search tree of a float "jammed" verdict: its shape (branches, children, the side of each leaf and the
/// basis of its LP; no Farkas vectors) and, per node, the float Farkas vector of a leaf (empty where there is
/// none).
struct FloatTree {
  std::vector<SearchNode<Q>> nodes;
  std::vector<Vec<double>> farkas;
};

/// How prove_leaves proved the leaves of a float tree, one count per way (in the order it tries them).
struct LeafProofs {
  long reused = 0;    ///< an earlier leaf's exact Farkas vector covers the leaf's fixings
  long rounded = 0;   ///< the leaf's float Farkas vector rounded to fractions and checked (rounded_farkas)
  long basis = 0;     ///< recomputed exactly from the basis of the leaf's float LP (basis_farkas)
  long lp = 0;        ///< an exact face LP
  long repaired = 0;  ///< the face was not empty: searched exactly below the leaf
  long total() const { return reused + rounded + basis + lp + repaired; }
};

/// The outcome of prove_leaves.
struct ProvenTree {
  /// kJammed: result.tree is an exact proof; kSolvable: a repaired subtree holds the complementary pair
  /// result.x, result.y; kUnknown: a leaf's face is not empty and no repair was asked for, or the repair ran
  /// out of budget.
  SearchResult<Q> result;
  LeafProofs leaves;
};

/// Turns a float search tree into an exact proof: every leaf gets an exact Farkas vector for the face its
/// path fixes on its side: an earlier leaf's vector if it covers the fixings (as the search's learning does),
/// else the leaf's float vector rounded to fractions and checked in integers (rounded_farkas), else the
/// duals of its float LP's basis solved exactly (basis_farkas), else that of an exact face LP. A leaf whose face
/// is not empty in exact arithmetic is repaired when `repair` is given: the exact search continues below it with those
/// options (search_subtree), and only there.
ProvenTree prove_leaves(const UcpProblem& problem, FloatTree tree, const std::optional<SearchOptions>& repair);

}  // namespace contactcert::solvers::ucp
