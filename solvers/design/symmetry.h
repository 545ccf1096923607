// Exact symmetries of a design problem: the isometries x -> com + A (x - com) (A a rational orthogonal 2x2
// matrix) that map the workpiece, the candidate set, the push points and the wrench set onto themselves
// (a wrench (f, tau) maps to (A f, det(A) tau)). Placements related by one are equivalent (same verdicts and
// figures: the map is an isometry of wrench space), so only the lexicographically least image is evaluated.
#pragma once

#include <vector>

#include "solvers/design/problem.h"

namespace contactcert::solvers {

/// The symmetry group as permutations of the candidate indices (the identity excluded).
struct CandidateSymmetry {
  std::vector<std::vector<int>> permutations;
  /// Is the placement the least (sorted, lexicographic) of its images?
  bool is_canonical(const Placement& placement) const;
};

/// Candidate maps: the 8 signed coordinate permutations, and for a polygon every map of edge 0's end points
/// onto an edge's end points (either direction), each kept only if it preserves everything above.
CandidateSymmetry candidate_symmetry(const DesignProblem& problem);

}  // namespace contactcert::solvers
