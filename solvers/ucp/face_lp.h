// LPs over a face {x in P : x_j = 0 for the fixed j} of a standard-form polyhedron P = {x >= 0 : A x = b}:
// the one LP primitive of the bilinear algorithm, the complete search and the enumerative baseline.
#pragma once

#include <vector>

#include "exact/arith.h"
#include "exact/lp_problem.h"
#include "solvers/ucp/problem.h"

namespace contactcert::solvers::ucp {

/// Which LP path: exact rationals, doubles (unchecked), the float simplex checked exactly, or the precision
/// ladder (exact::solve_lp_ladder). Only T = Q reads it: other number types solve in T.
using exact::Arith;

/// Work counters (Table 1 counts LPs).
struct LpCounters {
  long lps = 0;                     ///< linear programs solved
  long adjacencies = 0;             ///< adjacent-vertex enumerations (Step 3)
  long incomplete_adjacencies = 0;  ///< enumerations cut short by the basis budget at a degenerate vertex, or
                                    ///< whose float basis T's own tableau found infeasible (no edges then)
};

/// The face of P where the columns in `zero` are fixed to 0, as a smaller standard-form polyhedron.
template <class T>
struct Face {
  StandardPolyhedron<T> reduced;      ///< the free columns of P only
  std::vector<Eigen::Index> columns;  ///< columns of P kept, ascending
  Eigen::Index n = 0;                 ///< columns of P
};

/// The face of P with x_j = 0 for every j with zero[j] (zero empty = P itself).
template <class T>
Face<T> make_face(const StandardPolyhedron<T>& P, const std::vector<bool>& zero);

/// A vertex of a face: the point in P's coordinates and a basis (columns of the reduced problem).
template <class T>
struct FaceVertex {
  Vec<T> x;
  std::vector<Eigen::Index> basis;
};

/// kTimeLimit: the deadline passed inside the LP, before a verdict (the run ends `unknown`).
enum class FaceLpStatus { kOptimal, kEmpty, kTimeLimit };

/// Result of min c^T x over a face: an optimal vertex, or a Farkas vector proving the face empty
/// (farkas^T A_j >= 0 for every free column j, farkas^T b < 0).
template <class T>
struct FaceLpResult {
  FaceLpStatus status = FaceLpStatus::kEmpty;
  FaceVertex<T> vertex;
  Vec<T> farkas;
  /// kEmpty: the phase-1 basis whose duals give `farkas`, in P's columns (n + i: the artificial of row i).
  std::vector<Eigen::Index> farkas_basis;
};

/// Minimises c^T x (c in P's coordinates, c >= 0 so the LP is bounded) over the face; counts one LP. The LP
/// tests `deadline` before each pivot (kTimeLimit once it has passed).
template <class T>
FaceLpResult<T> minimize_on_face(const Face<T>& F, const Vec<T>& c, Arith arith, LpCounters& count,
                                 const exact::Deadline& deadline = {});

/// The adjacent extreme points of a vertex of the face, each with a basis. Exact at degenerate vertices:
/// all bases of the vertex are explored, up to `max_bases` of them (count.incomplete_adjacencies says
/// how often that budget cut an enumeration short).
template <class T>
std::vector<FaceVertex<T>> adjacent_on_face(const Face<T>& F, const FaceVertex<T>& v, long max_bases,
                                            LpCounters& count);

#define CONTACTCERT_FACE_LP_EXTERN(T)                                                                        \
  extern template Face<T> make_face<T>(const StandardPolyhedron<T>&, const std::vector<bool>&);              \
  extern template FaceLpResult<T> minimize_on_face<T>(const Face<T>&, const Vec<T>&, Arith, LpCounters&,     \
                                                      const exact::Deadline&);                               \
  extern template std::vector<FaceVertex<T>> adjacent_on_face<T>(const Face<T>&, const FaceVertex<T>&, long, \
                                                                 LpCounters&);
CONTACTCERT_FACE_LP_EXTERN(double)
CONTACTCERT_FACE_LP_EXTERN(Q)
#undef CONTACTCERT_FACE_LP_EXTERN

}  // namespace contactcert::solvers::ucp
