// From a complementary pair (x, y) back to the physics of section 2: contact forces and velocities,
// object and joint velocities, joint efforts; and an exact check of conditions (2)-(10).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "solvers/ucp/problem.h"

namespace contactcert::solvers::ucp {

/// The quantities of the quasistatic contact problem recovered from (x, y) (proof of Proposition 1).
struct PhysicalSolution {
  Vec<Q> c_n, c_t;   ///< contact force intensities; c_t = s_t^+ - U c_n
  Vec<Q> v_n, v_t;   ///< relative contact velocities; v_t = v_t^+ - v_t^-
  Vec<Q> q_dot;      ///< object velocity (nq)
  Vec<Q> theta_dot;  ///< all ntheta joint velocities (given ones and recovered unknown ones)
  Vec<Q> tau;        ///< all ntheta joint efforts net of gravity loads: tau - g_man = Jn^T c_n + Jt^T c_t (3)
};

/// Recovers the physics from x = (v_n, v_t^+, v_t^-) in X and y = (c_n, s_t^+, s_t^-) in Y; nullopt if x is
/// not in X (no q_dot, theta_dot_abar reproduce v).
std::optional<PhysicalSolution> recover(const QuasistaticProblem& p, const Vec<Q>& x, const Vec<Q>& y);

/// Fills the forces c_n, c_t = s_t^+ - U c_n and the efforts tau (3) of s from y = (c_n, s_t^+, s_t^-) in Y.
void recover_forces(const QuasistaticProblem& p, const Vec<Q>& y, PhysicalSolution& s);

// A vertex of X or Y from the zero pattern of a float one, through the physics: the pattern fixes components of
// the contact velocities or forces, and the rest follows from a small system in P's entries, which are the
// data's (11 bits on Data Set 1), where X's rows span the left null space of P (25 bits there) and Y's carry the
// friction identities. Data Set 1's vertices take one 3 x 3 system each (64-bit products) instead of X's 3 x 3
// in 128 bits and Y's 6 x 6. The point is exact and in X (Y) by construction; nullopt sends the caller to the
// rows (float_check.h).

/// The velocities (v_n, v_t, q_dot, theta_dot) at the point of X with the zero pattern x_zero (x_i = 0 where
/// x_zero[i]): u = [q_dot; -theta_abar] solves the rows of (4), (5), P u = v + J_alpha theta_alpha, where the
/// pattern fixes v to 0 (v_n,i, or v_t,i when v_t,i^+ and v_t,i^- are both fixed), then v = P u - J_alpha
/// theta_alpha. nullopt unless those rows fix u and v fits the pattern (v_n >= 0, v_t <= 0 where v_t^+ is fixed,
/// v_t >= 0 where v_t^- is). velocity_point(s) is then the point of X.
std::optional<PhysicalSolution> pattern_velocities(const QuasistaticProblem& p, const std::vector<bool>& x_zero);

/// x = (v_n, v_t^+, v_t^-) of recovered velocities with v_t^+ = max(v_t, 0), v_t^- = max(-v_t, 0).
Vec<Q> velocity_point(const PhysicalSolution& s);

/// The point y = (c_n, s_t^+, s_t^-) of Y with the zero pattern y_zero, and its forces c_n, c_t, tau in s: the
/// pattern fixes c_n,i = 0 (then c_t,i = 0) or c_t,i = -mu_i c_n,i (s_t^+ = 0) or mu_i c_n,i (s_t^- = 0), and the
/// other components solve (2), (3): P^T c + d' = 0 (d' = [g_obj; (g_man - tau)_abar]). nullopt unless those
/// fix c and c is in the friction cones (c_n >= 0, |c_t| <= mu c_n).
std::optional<Vec<Q>> pattern_forces(const QuasistaticProblem& p, const std::vector<bool>& y_zero, PhysicalSolution& s);

enum class ConditionsStatus { kSatisfied, kViolated };

/// The outcome of checking (2)-(10): which conditions fail, with the contact or row.
struct ConditionsCheck {
  ConditionsStatus status = ConditionsStatus::kSatisfied;
  std::vector<std::string> violations;  ///< e.g. "(8) contact 2: c_n > 0 but v_n > 0"
};

/// Checks the paper's conditions (2)-(10) exactly on recovered quantities.
ConditionsCheck check_conditions(const QuasistaticProblem& p, const PhysicalSolution& s);

}  // namespace contactcert::solvers::ucp
