// Pang, Trinkle and Lo's quasistatic problem (eqs. (1)-(10)) for several bodies, built exactly from an assembly
// (`"kind": "quasistatic_scene"` with `bodies`, docs/formats.md section 2): q = (q_0, ..., q_{N-1}), nq = 3N,
// torques about the world origin as for one workpiece (solvers/ucp/scene_builder.h). Contact i (point r_i, normal
// n_i from `from` into `to`, t_i = perp(n_i)) gives the columns of W (eq. (1)): (n_i, r_i x n_i) in the rows of
// `to`, minus it in the rows of `from`, none for a fixed party; likewise for t_i. Each finger adds two joints,
// finger k's are 2k and 2k + 1 (its contact's n and t, or x and y), with Jn and Jt rows as for one workpiece; an
// obstacle, a fixel or a body adds none. g_obj = per body (f_x, f_y, torque + com x f) of its load.
#pragma once

#include "geometry/assembly.h"
#include "solvers/ucp/problem.h"

namespace contactcert::solvers::assembly {

/// The quasistatic problem of an assembly, validated as a `"kind": "quasistatic"` problem. Each finger must be the
/// `from` party of exactly one contact (its normal points from the finger into the body, as for one workpiece);
/// `mu` is each contact's mu_s. Throws exact::InputError naming `file` otherwise.
ucp::QuasistaticProblem assembly_quasistatic(const geometry::Assembly& a, const std::string& file = "");

}  // namespace contactcert::solvers::assembly
