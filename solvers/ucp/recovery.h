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

enum class ConditionsStatus { kSatisfied, kViolated };

/// The outcome of checking (2)-(10): which conditions fail, with the contact or row.
struct ConditionsCheck {
  ConditionsStatus status = ConditionsStatus::kSatisfied;
  std::vector<std::string> violations;  ///< e.g. "(8) contact 2: c_n > 0 but v_n > 0"
};

/// Checks the paper's conditions (2)-(10) exactly on recovered quantities.
ConditionsCheck check_conditions(const QuasistaticProblem& p, const PhysicalSolution& s);

}  // namespace contactcert::solvers::ucp
