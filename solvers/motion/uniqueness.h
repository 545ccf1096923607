// Is the motion of a step unique? Every solution of a quasistatic problem lies in a contact mode (per contact:
// separate, roll, slide +, slide -, enumerate.h), and because X and Y are uncoupled the solutions of a mode are
// all of (its face of X) x (its face of Y). So the body velocities of all solutions are, over the solution modes
// (those whose two faces are non-empty), the sets {q_dot : P u = v + J_alpha theta_alpha, u = [q_dot; ...],
// x = (v_n, v_t^+, v_t^-) >= 0 in the mode's face}. The motion is unique iff one LP per component and direction
// (min and max of each q_dot_k over each solution mode's face) gives the same value everywhere.
// The solution modes come from the prefix tree over the contacts (ucp::solution_modes_by_prefix: one LP per
// non-empty prefix and letter, not 4^nc), then 2 nq LPs per solution mode, all exact (or verified).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "exact/arith.h"
#include "solvers/ucp/enumerate.h"
#include "solvers/ucp/problem.h"

namespace contactcert::solvers::motion {

using exact::Q;

enum class UniquenessStatus {
  kUnique,     ///< every solution has the same q_dot (proven: the LP bounds agree over every solution mode)
  kNotUnique,  ///< two solutions with different q_dot (both in `motions`), or a q_dot range unbounded
  kNoMotion,   ///< no solution at all (jammed), so no motion: the prefix tree found no solution mode
  kUnknown     ///< the prefix tree's LP budget (max_modes) ran out
};

const char* uniqueness_name(UniquenessStatus s);

/// What proves the verdict (uniqueness_certificate.h writes it down): the prefix tree's dead prefixes and solution
/// modes' points; per bounded solution mode (`unique`: the widest ones; `not_unique`: all) and q_dot component k the
/// optimal duals y of min q_dot_k (low) and of min -q_dot_k (high) over its face; for `not_unique`, the solutions
/// (mode, u, x) with distinct q_dot found (at least two).
struct UniquenessEvidence {
  struct Bound {
    std::size_t mode = 0;  ///< index in solution_modes
    std::vector<exact::Vec<Q>> low, high;
  };
  struct Witness {
    std::size_t mode = 0;
    exact::Vec<Q> u, x;  ///< u = [q_dot; P's other columns], x = (v_n, v_t^+, v_t^-) with P u = v + J_alpha theta_alpha
  };
  ucp::PrefixEvidence tree;
  std::vector<Bound> bounds;
  std::vector<Witness> witnesses;
};

/// The verdict and its evidence: distinct body velocities reached (each an LP optimum, with its mode).
struct MotionUniqueness {
  UniquenessStatus status = UniquenessStatus::kUnknown;
  std::vector<exact::Vec<Q>> motions;  ///< distinct q_dot, each attained by a solution
  std::vector<std::string> modes;      ///< the mode of each motion (letters s r + - per contact)
  std::vector<std::string> solution_modes;
  bool unbounded = false;  ///< some q_dot component is unbounded over a solution mode
  long lps = 0;            ///< LPs solved (with kUnknown: the prefixes covered before the budget ran out)
  std::optional<UniquenessEvidence> evidence;  ///< with `evidence` asked and a decided verdict
};

/// Decides whether all solutions of a quasistatic problem have the same q_dot (exact or verified LPs; kUnknown
/// when the prefix tree needs more than max_modes LPs); with `evidence`, also what proves a decided verdict.
MotionUniqueness motion_uniqueness(const ucp::UcpProblem& problem, exact::Arith arith, long max_modes,
                                   bool evidence = false);

}  // namespace contactcert::solvers::motion
