// The rigid-body model of an assembly from rest (Balkcom-Trinkle eqs. 3-6 and Table 2 for N bodies), written in
// the body accelerations vdot = (vdot_0, ..., vdot_{N-1}), vdot_b = (a_x, a_y, alpha) of body b's com, and the
// contact forces. Contact i (point p_i, normal n_i from `from` into `to`, t_i = perp(n_i)) has the relative
// accelerations a_in = sum_b w^b_in . vdot_b and a_it = sum_b w^b_it . vdot_b (eq. 6, velocity products neglected),
// with w^b_in = +-(n_i, (p_i - com_b) x n_i) (+ for `to`, - for `from`, absent for a fixed party); its force
// c_in n_i + c_it t_i on `to` gives the Newton-Euler rows M_b vdot_b - sum_i (c_in w^b_in + c_it w^b_it) = g_b,
// M_b = diag(m_b, m_b, I_b), g_b the load of body b. The letters of a mode are Table 2's s l r n (every contact
// touches); a prefix of a mode leaves the later contacts `*`: relaxed to the convex hull of the four letters,
// a_n >= 0 and |c_t| <= max(mu_s, mu_k) c_n, so a prefix whose system is infeasible has no feasible completion.
// The energy row. In every solution of every mode, c_in a_in = 0 (s: c = 0, else a_n = 0) and c_it a_it <= 0 (l r:
// friction opposes sliding, n: a_t = 0), so vdot^T M vdot = g^T vdot + sum_i (c_in a_in + c_it a_it) <= g^T vdot:
// a moving solution (vdot != 0, M positive definite) has g^T vdot > 0, and every solution with g^T vdot > 0 moves.
// So the moving solutions of a mode are exactly the solutions of its system with the row g^T vdot > 0; the row
// holds for every mode, n..n included (a body pivoting about a rolling contact), and it cuts every partial system.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "exact/strict_feasibility.h"
#include "geometry/assembly.h"

namespace contactcert::solvers::assembly {

using exact::Q;
using exact::Vec;

/// One contact as the model reads it: per side (body index or -1 if fixed) its signed unit-force wrenches.
struct ContactJacobian {
  struct Side {
    long body = -1;
    std::array<Q, 3> w_n, w_t;  ///< +-(n, (p - com) x n), +-(t, (p - com) x t)
  };
  std::array<Side, 2> sides;  ///< from, to
  Q mu_s, mu_k;
};

/// The model of an assembly: per body M_b's diagonal and the load g_b; per contact its Jacobian.
struct AssemblyModel {
  std::vector<std::array<Q, 3>> M, g;
  std::vector<ContactJacobian> contacts;
  std::size_t bodies() const { return M.size(); }
};

AssemblyModel assembly_model(const geometry::Assembly& a);

/// The system of a mode or prefix (letters s l r n, `*` for a relaxed contact; docs/formats.md section 5a fixes
/// this layout for certificates). Columns: vdot (3N, free, body by body) and e > 0, unless resting; then per contact
///   s: sigma > 0   l r: sigma > 0, c_n   n: c_n, c_t (free), rho+, rho-   *: sigma >= 0, c_n, c_t (free), rho+, rho-
///   resting (vdot = 0): c_n, c_t (free), rho+, rho-        (every other column >= 0)
/// Rows: unless resting, the energy row sum_b g_b . vdot_b - e = 0; then per contact  s: a_n - sigma = 0   l: a_n = 0,
/// a_t - sigma = 0   r: a_n = 0, a_t + sigma = 0
///   n: a_n = 0, a_t = 0, then the friction rows mu c_n - c_t - rho+ = 0, mu c_n + c_t - rho- = 0 (mu = mu_s)
///   *: a_n - sigma = 0, then the friction rows with mu = max(mu_s, mu_k)     resting: the friction rows (mu_s)
/// then the 3N Newton-Euler rows, body by body, with c_t = -mu_k c_n for l and +mu_k c_n for r; b = g there.
struct AssemblySystem {
  exact::SparseStrictSystem<Q> system;
  Vec<Q> b;
  bool resting = false;
  Eigen::Index vdot_size = 0;                        ///< 3N, or 0 when resting
  std::vector<Eigen::Index> c_n_column, c_t_column;  ///< per contact, -1 if none
  std::vector<Q> c_t_per_c_n;                        ///< l: -mu_k, r: mu_k, else 0
  /// What each row says, the same in every prefix's system: 0 the energy row; 1 + 4i + 0, 1, 2, 3 contact i's rows
  /// a_n, a_t, friction with -c_t, with +c_t; 1 + 4k + 3b + d body b's Newton-Euler row d.
  std::vector<Eigen::Index> row_label;
  /// vdot (3N) and the forces (c_1n..c_kn, c_1t..c_kt) of a point x of the system.
  Vec<Q> acceleration(const Vec<Q>& x) const;
  Vec<Q> forces(const Vec<Q>& x) const;
};

AssemblySystem assembly_system(const AssemblyModel& model, const std::string& letters, bool resting = false);
/// The same written into `out`, whose storage is reused (the stability walk builds one system per prefix: the
/// fractions of the last one are overwritten, not allocated anew).
void assembly_system(const AssemblyModel& model, const std::string& letters, AssemblySystem& out, bool resting = false);

/// a_in and a_it of contact i for accelerations vdot.
std::array<Q, 2> contact_acceleration(const AssemblyModel& model, std::size_t i, const Vec<Q>& vdot);

}  // namespace contactcert::solvers::assembly
