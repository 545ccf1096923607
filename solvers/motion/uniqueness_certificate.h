// The certificate of a step's uniqueness verdict, "motion_uniqueness" (its independent checker, `contactcert check`:
// checker/uniqueness_check.h). Like the UCP certificates (solvers/ucp/certificate.h) it embeds the quasistatic
// problem under "problem" (and the step's assembly under "assembly" with several bodies), with "verdict":
//
// "unique" -- every solution has the body velocity "motion" (nq exact strings):
//   - "dead": the prefix tree's pruned prefixes, each {"prefix": one letter s r + - per contact, '?' for the contacts
//     the tree left undecided (it decides the last contact first, so the letters are a suffix), "empty": "X" | "Y",
//     "farkas": [integers with gcd 1]} proving the prefix's face of that side empty (as a ucp_jammed leaf: X by
//     w in R^{2nc} with w^T P = 0, Y over the rows of [C | -d]);
//   - "solution_modes": every other mode, each {"mode", "x", "y"}: a point of its face of X and of Y. Together with
//     "dead" they partition the 4^nc modes, and every complementary pair lies in some mode;
//   - "bounds": per bounded mode {"mode", "low", "high"}, nq dual vectors y in R^{2nc} each: with B = [I 0 0;
//     0 I -I] and h = J_alpha theta_dot_alpha, P^T y = +e_k (low) or -e_k (high) and (B^T y)_j >= 0 for every
//     component j of x the mode leaves free. For (u, x) in the face (P u = B x + h, x >= 0, x_j = 0 off the free
//     components), +-u_k = y^T P u = y^T B x + y^T h >= h^T y (weak LP duality), so q_dot_k >= h^T y_low and
//     q_dot_k <= -h^T y_high: both are motion_k. A mode whose free components are among a bounded mode's has its
//     face inside that one's, so every solution mode's face has q_dot = motion.
// "not_unique" -- "witnesses": two solutions {"mode", "u", "x", "y"} (u = [q_dot; P's other columns], P u = B x + h,
//   x and y in the mode's faces) whose q_dot differ.
#pragma once

#include <string>

#include "solvers/motion/uniqueness.h"

namespace contactcert::solvers::motion {

/// The certificate text of a decided verdict that carries its evidence (motion_uniqueness(..., evidence = true));
/// "" otherwise, and for a problem without a solution (its `unique` is vacuous: the ucp_jammed certificate proves it).
/// `assembly_text`: the step's assembly (several bodies), embedded as the UCP certificates do.
std::string uniqueness_certificate(const ucp::UcpProblem& problem, const MotionUniqueness& u,
                                   const std::string& assembly_text = "");

}  // namespace contactcert::solvers::motion
