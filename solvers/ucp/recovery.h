// From a complementary pair (x, y) back to the physics of section 2: contact forces and velocities,
// object and joint velocities, joint efforts; and an exact check of conditions (2)-(10).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "exact/rational_vector.h"
#include "solvers/ucp/problem.h"

namespace contactcert::solvers::ucp {

/// The quantities of the quasistatic contact problem recovered from (x, y) (proof of Proposition 1), exact. They
/// are computed in integers over common denominators and kept so (exact::RationalVector: v(i) or v.to_q() give
/// rationals): an adaptive solve would otherwise build 27 GMP rationals (Data Set 1) for every report, read or not.
struct PhysicalSolution {
  exact::RationalVector c_n, c_t;   ///< contact force intensities; c_t = s_t^+ - U c_n
  exact::RationalVector v_n, v_t;   ///< relative contact velocities; v_t = v_t^+ - v_t^-
  exact::RationalVector q_dot;      ///< object velocity (nq)
  exact::RationalVector theta_dot;  ///< all ntheta joint velocities (given ones and recovered unknown ones)
  exact::RationalVector tau;  ///< all ntheta joint efforts net of gravity loads: tau - g_man = Jn^T c_n + Jt^T c_t (3)
};

/// Recovers the physics from x = (v_n, v_t^+, v_t^-) in X and y = (c_n, s_t^+, s_t^-) in Y; nullopt if x is
/// not in X (no q_dot, theta_dot_abar reproduce v).
std::optional<PhysicalSolution> recover(const QuasistaticProblem& p, const Vec<Q>& x, const Vec<Q>& y);

enum class ConditionsStatus { kSatisfied, kViolated };

/// The outcome of checking (2)-(10): which conditions fail, with the contact or row.
struct ConditionsCheck {
  ConditionsStatus status = ConditionsStatus::kSatisfied;
  std::vector<std::string> violations;  ///< e.g. "(8) contact 2: c_n > 0 but v_n > 0"
};

// A complementary pair from the zero patterns of a float one, through the physics: the patterns fix components
// of the contact velocities and forces, and the rest follows from small systems in P's entries, which are the
// data's (11 bits on Data Set 1), where X's rows span the left null space of P (25 bits there) and Y's carry the
// friction identities. On Data Set 1 that is one 3 x 3 system per side in 64-bit products instead of X's 3 x 3 in
// 128 bits and Y's 6 x 6, and the physics comes with the pair. The pair is exact and in X and Y by construction;
// nullopt sends the caller to the rows (float_check.h).

/// A complementary pair with its physics and the check of (2)-(10) on it (as check_conditions, from the same
/// integer copy of the data).
struct PatternSolution {
  exact::RationalVector x, y;
  PhysicalSolution physical;
  ConditionsCheck conditions;
};

/// The vertices x of X and y of Y with the zero patterns x_zero and y_zero (x_i = 0 where x_zero[i], y_i = 0 where
/// y_zero[i]; every index in one of them, so x^T y = 0), and their physics. Velocities: u = [q_dot; -theta_abar]
/// solves the rows of (4), (5), P u = v + J_alpha theta_alpha, where x_zero fixes v to 0 (v_n,i, or v_t,i when
/// v_t,i^+ and v_t,i^- are both fixed), then v = P u - J_alpha theta_alpha and x = (v_n, v_t^+, v_t^-) with
/// v_t^+ = max(v_t, 0), v_t^- = max(-v_t, 0). Forces: y_zero fixes c_n,i = 0 (then c_t,i = 0) or c_t,i = -mu_i
/// c_n,i (s_t^+ = 0) or mu_i c_n,i (s_t^- = 0), and the other components solve (2), (3): P^T c + d' = 0 with
/// d' = [g_obj; (g_man - tau)_abar]; y = (c_n, s_t^+, s_t^-). nullopt unless both systems have one solution and
/// it fits the patterns (v_n >= 0, v_t <= 0 where v_t^+ is fixed and >= 0 where v_t^- is, c_n >= 0,
/// |c_t| <= mu c_n).
std::optional<PatternSolution> pattern_solution(const QuasistaticProblem& p, const std::vector<bool>& x_zero,
                                                const std::vector<bool>& y_zero);

/// Checks the paper's conditions (2)-(10) exactly on recovered quantities.
ConditionsCheck check_conditions(const QuasistaticProblem& p, const PhysicalSolution& s);

}  // namespace contactcert::solvers::ucp
