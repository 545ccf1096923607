// Strong stability of a body in space under an external wrench (issue 34): the wrench cone paper's section 7
// (Balkcom and Trinkle 2002) with the linearised friction pyramid of solvers/spatial/spatial_modes.h. From rest the
// body's motion is Newton-Euler with its six accelerations vdot = (a, alpha):
//     M vdot = g + sum_i sum_j beta_ij w_i(n_i + d_ij),   M = diag(m, m, m, I),   beta_ij >= 0,
// g = (f, tau) the external force and its torque about the com, w_i(u) = (u, r_i x u) the wrench of a force u at
// contact i (its force c_i = sum_j beta_ij (n_i + d_ij) lies in the pyramid), and complementarity per letter of
// the contact's mode: s (a_n > 0) carries no force, f (a = 0) any force of the pyramid, a sliding letter only the
// pyramid edges the maximal-dissipation law allows - edge j alone (letter 2j) or edges j, j + 1 (letter 2j + 1).
//   strongly_stable: some solution has vdot = 0 and none has vdot != 0;
//   weakly_stable:   both kinds exist;
//   unstable:        no solution has vdot = 0 (a Motzkin certificate of the resting system).
// As in the plane (solvers/stability/strong_stability.h): every mode but f..f has a strict row, so vdot != 0; an
// f..f solution beside a resting one has vdot = 0 (two of them differ by dv with J dv = 0 and M dv in the range of
// J^T, so dv^T M dv = 0). The moving modes are not listed one by one ((2 + 2m)^k strings): the kinematic prefix tree
// (spatial_modes) proves whole subtrees empty for every g, and each feasible moving mode gets one LP in g, unless
// the Motzkin vector of one of the last modes proven (in tree order, they share most letters) moved to its rows by
// functional (move_rows, as the tree moves its dead prefixes' certificates) is one of its system: checked exactly.
#pragma once

#include <string>
#include <vector>

#include "solvers/spatial/spatial_modes.h"
#include "solvers/stability/strong_stability.h"

namespace contactcert::solvers::spatial {

/// The pyramid edges on which letter L of a contact with m edges may carry force: all (f), none (s), j (2j), or
/// j and j + 1 mod m (2j + 1), in this order.
std::vector<std::size_t> force_edges(std::size_t m, char L);

/// A solution of the model: its mode, the weights beta_ij (contact by contact, every edge of its pyramid, zero
/// where the letter allows no force) and vdot.
struct SpatialMotion {
  std::string mode;
  Vec<Q> weights;
  Vec<Q> acceleration;
};

/// A proof that moving mode `mode` does not admit g: the Motzkin vector of its system for g (spatial_motion_system).
struct SpatialModeProof {
  std::string mode;
  Vec<Q> motzkin;
};

struct SpatialStability {
  StabilityVerdict verdict = StabilityVerdict::kUnstable;
  bool has_resting = false;
  Vec<Q> resting_weights;  ///< a zero-acceleration solution's beta, if has_resting
  Vec<Q> resting_motzkin;  ///< else: no resting solution exists
  bool has_moving = false;
  SpatialMotion moving;  ///< a solution with vdot != 0, if has_moving
  /// Strongly stable: the mode tree's dead prefixes with their sparse proofs (spatial_modes.h; no moving mode that
  /// extends one admits any g; dead_motzkin gives a prefix's vector), its modes not kept.
  SpatialModeTree tree;
  std::vector<SpatialModeProof> proofs;  ///< strongly stable: one per feasible moving mode
  long lps = 0;                          ///< the tree's and the verdict's
  long modes_checked = 0;                ///< moving modes whose system in g was decided
  long modes_by_reuse = 0;               ///< of them, proven by an earlier mode's Motzkin vector moved (no LP)
  long modes_kinematically_feasible = 0;
  long tree_nodes = 0;
  long dead_prefixes = 0;
};

/// The system of a mode (one letter per contact) for the wrench g = rhs: columns vdot (6, free), one slack sigma > 0
/// per strict kinematic row, then per contact the weights beta >= 0 of its force_edges; rows the letters' kinematic
/// rows (spatial_modes.h's table and order; b = 0), then the six rows M vdot - sum beta w(n + d) = g. With
/// `zero_acceleration` (mode f..f), vdot = 0: no vdot columns and no kinematic rows (the resting system).
exact::SparseStrictSystem<Q> spatial_motion_system(const geometry::SpatialBody& body, const SpatialModel& model,
                                                   const std::string& mode, bool zero_acceleration = false);

/// The verdict for g = (f, tau about the com) with its witness or certificate. The mode tree's budgets and
/// deadline (also tested per mode) throw exact::BudgetExceeded.
SpatialStability spatial_stability(const geometry::SpatialScene& scene, const Vec<Q>& g,
                                   const SpatialModeOptions& options = {});

/// Contact i's force c_i = sum_j beta_ij (n_i + d_ij) in world coordinates, from a solution's weights.
std::vector<geometry::Vec3> contact_forces(const geometry::SpatialScene& scene, const Vec<Q>& weights);

}  // namespace contactcert::solvers::spatial
