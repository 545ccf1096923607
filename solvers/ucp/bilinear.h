// The LP-based bilinear algorithm of Pang, Trinkle, Lo (section 4, Steps 0-3) for the UCP: minimise x^T y
// over X x Y by alternating LPs (14), (15); at a stationary pair (16) search the adjacent extreme points of
// both vertices (Step 3), with the paper's random move or the modified Step 3 of section 5.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "exact/deadline.h"
#include "solvers/ucp/face_lp.h"

namespace contactcert::solvers::ucp {

/// What Step 3 does when no adjacent pair decreases x^T y: the paper repeats Step 3 from a random adjacent
/// pair; the modified algorithm of section 5 returns to Step 1 from it.
enum class Step3Rule { kPaper, kModified };

struct BilinearOptions {
  Step3Rule step3 = Step3Rule::kPaper;
  int max_random_moves =
      20;  ///< section 5: "Step 1 was reinvoked 20 times, after which the algorithm was set to terminate"
  long max_pairs = 2000;    ///< safety bound on the iteration counter nu
  long max_bases = 100000;  ///< Step 3: bases explored per degenerate vertex (AdjacencyOptions::max_bases)
  Arith arith = Arith::kVerified;
  exact::Deadline deadline;  ///< tested before each new pair and each pivot of its LPs; kTimeLimit when it expires
};

enum class BilinearStatus {
  kComplementary,  ///< Step 2: x^T y = 0 exactly
  kStopped,        ///< random-move limit reached at a stationary, non-complementary pair
  kXEmpty,         ///< Step 0: X is empty (farkas proves it)
  kYEmpty,         ///< Step 0: Y is empty
  kTimeLimit,      ///< the deadline expired before a verdict (the best pair so far is kept)
};

/// The outcome with the evidence: the final (best) pair and the counts of Table 1.
template <class T>
struct BilinearResult {
  BilinearStatus status = BilinearStatus::kStopped;
  FaceVertex<T> x, y;    ///< the best pair found (the complementary one if status is kComplementary)
  T xTy = T(0);          ///< x^T y of that pair
  Vec<T> farkas;         ///< kXEmpty / kYEmpty: Farkas vector of the empty polyhedron's face
  long pairs = 0;        ///< pairs (x^nu, y^nu), nu >= 1, generated (Table 1 "No. of pairs")
  int random_moves = 0;  ///< Step 3 random choices
  LpCounters counters;   ///< LPs (Step 0's two included) and adjacency enumerations
};

/// Runs Steps 0-3 on the faces FX of X and FY of Y (the whole X and Y, or a node of the complete search).
template <class T>
BilinearResult<T> bilinear(const Face<T>& FX, const Face<T>& FY, const BilinearOptions& opts, std::mt19937_64& rng);

/// Step 1 only, from a given pair, until x^T y stops decreasing (a stationary pair) or reaches 0; used as the
/// primal heuristic at search nodes. Both faces must be non-empty and x, y vertices of them. Returns
/// kComplementary (x^T y = 0), kStopped, or kTimeLimit if `deadline` passed inside an LP (x, y then the last
/// pair reached).
template <class T>
BilinearStatus alternate_lps(const Face<T>& FX, const Face<T>& FY, FaceVertex<T>& x, FaceVertex<T>& y, Arith arith,
                             int max_rounds, LpCounters& count, const exact::Deadline& deadline = {});

#define CONTACTCERT_BILINEAR_EXTERN(T)                                                                            \
  extern template BilinearResult<T> bilinear<T>(const Face<T>&, const Face<T>&, const BilinearOptions&,           \
                                                std::mt19937_64&);                                                \
  extern template BilinearStatus alternate_lps<T>(const Face<T>&, const Face<T>&, FaceVertex<T>&, FaceVertex<T>&, \
                                                  Arith, int, LpCounters&, const exact::Deadline&);
CONTACTCERT_BILINEAR_EXTERN(double)
CONTACTCERT_BILINEAR_EXTERN(Q)
#undef CONTACTCERT_BILINEAR_EXTERN

}  // namespace contactcert::solvers::ucp
