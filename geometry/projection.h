// The cone of eq. (13)-(14) in g: { g : exists z >= 0, z_i > 0 for i in strict, K z = P g }
// (Theorem 1 with k -> 0+, section 5.6), as a minimal face cone, by two independent routes.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/nnc_cone.h"

namespace contactcert::geometry {

/// One projection problem: K is m x n, P is m x d, strict has n entries (z_i > 0 where true).
template <class T>
struct ProjectionProblem {
  Mat<T> K;
  Mat<T> P;
  std::vector<bool> strict;  ///< empty = no strict component
};

/// Route (a), the paper's: K^F from the span-to-face conversion of pos(K), F = K^F P (eq. 18); a
/// facet of pos(K) becomes strict when it misses a column k_i with z_i > 0. Returns nnc_form(...).face
/// of the result (canonical for T = Q; empty cone encoded as in NncForm).
template <class T>
FaceCone<T> project_by_polar(const ProjectionProblem<T>& problem, const DdBudget& budget = {});

/// project_by_polar for K z = P g given as rows [P | K] (d columns of P, the others of K) in the ring R of
/// T (exact/fraction_free.h; each row may be any positive multiple): the same result, with K^F, eq. (18)
/// and, for exact rings, the face form of a pointed full-dimensional result computed in R (T only for
/// the result). std::int64_t throws RingOverflow.
template <class T, class R>
FaceCone<T> project_by_polar_rows(const exact::IntMatrix<R>& rows, Eigen::Index d, const std::vector<bool>& strict,
                                  const DdBudget& budget = {});

extern template FaceCone<double> project_by_polar_rows<double, double>(const exact::IntMatrix<double>&, Eigen::Index,
                                                                       const std::vector<bool>&, const DdBudget&);
extern template FaceCone<Q> project_by_polar_rows<Q, std::int64_t>(const exact::IntMatrix<std::int64_t>&, Eigen::Index,
                                                                   const std::vector<bool>&, const DdBudget&);
extern template FaceCone<Q> project_by_polar_rows<Q, Z>(const exact::IntMatrix<Z>&, Eigen::Index,
                                                        const std::vector<bool>&, const DdBudget&);

/// Route (b), output-sensitive for a low-dimensional target: discovers the generators of the closed
/// cone with one exact LP per facet and per generator (convex hull method), converts in R^d only, and
/// decides open faces by strict-feasibility LPs (maximise t with z_i >= t on strict components).
/// Same result as project_by_polar. The budget's deadline also stops an LP (BudgetExceeded, the LPs solved
/// before it counted).
template <class T>
FaceCone<T> project_by_lp(const ProjectionProblem<T>& problem, const DdBudget& budget = {});

/// Theorem 1 with a constant offset z >= k: { g : K^F P g <= K^F K k, E_K P g = E_K K k } as rows
/// (A g <= b, C g = c); E_K are the equalities of pos(K).
template <class T>
struct AffineFace {
  Mat<T> A;
  Vec<T> b;
  Mat<T> C;
  Vec<T> c;
};
template <class T>
AffineFace<T> theorem1(const Mat<T>& K, const Mat<T>& P, const Vec<T>& k, const DdBudget& budget = {});

#define CONTACTCERT_PROJECTION_EXTERN(T)                                                         \
  extern template FaceCone<T> project_by_polar<T>(const ProjectionProblem<T>&, const DdBudget&); \
  extern template FaceCone<T> project_by_lp<T>(const ProjectionProblem<T>&, const DdBudget&);    \
  extern template AffineFace<T> theorem1<T>(const Mat<T>&, const Mat<T>&, const Vec<T>&, const DdBudget&);
CONTACTCERT_PROJECTION_EXTERN(double)
CONTACTCERT_PROJECTION_EXTERN(Q)
#undef CONTACTCERT_PROJECTION_EXTERN

}  // namespace contactcert::geometry
