// The checker's own statement of Pang, Trinkle and Lo's quasistatic problem (eqs. (1)-(10)) for the N bodies of an
// assembly, for the certificates of `contactcert assembly --ucp`, which embed the assembly beside the problem: the
// checker derives P, Jn, Jt, d and the joints from the assembly's geometry and refuses an embedded problem that is
// not exactly that. Derived from the contact kinematics, not from solvers/assembly/assembly_ucp.h: body b with
// q_dot_b = (v_x, v_y, w) (about the world origin) moves a point p with u_b(p) = (v_x - w p_y, v_y + w p_x), and the
// relative velocity at contact i (point p_i, normal n_i from `from` into `to`, t_i = perp(n_i)) is
//   v_in = n_i . (u_to(p_i) - u_from(p_i)) + (J_n theta_dot)_i,   v_it likewise with t_i           (eqs. (1), (3))
// so W^T's entry for contact i and coordinate k of body b is n_i . u_b(p_i) at the unit q_dot_b = e_k, with the
// sign of the body's side. Finger f (the `from` party of one contact i) has joints 2f, 2f + 1 along its axes a_0,
// a_1: x and y (J_n(i, 2f + k) = n_i . a_k, J_t likewise), or n_i and t_i of its contact (J_n(i, 2f) = 1,
// J_t(i, 2f + 1) = 1); a joint with a given velocity is in alpha, one with a given force tau in abar. Then
// P = [W^T  J_abar] and d = [0; g_obj; -tau_abar], g_obj per body its load about the world origin
// (f_x, f_y, torque + com x f) (eqs. (4)-(10)), and mu_i is contact i's mu_s.
#pragma once

#include <string>

#include "geometry/assembly.h"
#include "solvers/ucp/problem.h"

namespace contactcert::checker {

/// "" if `p` is exactly the quasistatic problem of assembly `a` (above), else the first entry that is not. Every
/// contact frame is re-verified first (assembly_check.h), so a frame the reader derived (a finger's) is checked too.
std::string assembly_problem_violation(const geometry::Assembly& a, const solvers::ucp::QuasistaticProblem& p);

}  // namespace contactcert::checker
