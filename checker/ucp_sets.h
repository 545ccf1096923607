// The sets of a UCP certificate as a checker derives them from the embedded problem with its own code (not build_X /
// build_Y: Y's rows are written out from eq. (5)-(10), X of a quasistatic problem is tested through the column space
// of P), and the exact tests of Farkas vectors and points against them: shared by the checkers of the UCP
// certificates (ucp_check.h) and of a step's uniqueness (uniqueness_check.h).
#pragma once

#include <string>
#include <vector>

#include "exact/json_input.h"
#include "exact/number.h"
#include "solvers/ucp/problem.h"

namespace contactcert::checker::ucp_sets {

using exact::Mat;
using exact::Q;
using exact::Vec;

/// The data a checker needs, derived from the problem file by the checker itself (not by build_X / build_Y).
struct CheckData {
  bool quasistatic = false;
  Eigen::Index n = 0;
  // Generic form, or Y of a quasistatic problem: {z >= 0 : A z = b}.
  Mat<Q> AX, AY;
  Vec<Q> bX, bY;
  // Quasistatic X: B x + h in the column space of P (B = [I 0 0; 0 I -I], h = J_alpha theta_dot_alpha).
  Mat<Q> P;
  Vec<Q> h;
};

CheckData derive(const solvers::ucp::UcpProblem& u);

/// Checks that `u` proves {z >= 0 : A z = b, z_j = 0 for zero[j]} empty; returns "" or why not.
std::string check_farkas(const Mat<Q>& A, const Vec<Q>& b, const std::vector<bool>& zero, const Vec<Q>& u);

/// Quasistatic X side: w^T P = 0, (w_n, w_t, -w_t) >= 0 on free columns, w^T h > 0.
std::string check_velocity_farkas(const CheckData& c, const std::vector<bool>& zero, const Vec<Q>& w);

/// Whether u is written as documented: integers with gcd 1 (the zero vector fails the Farkas conditions itself).
bool primitive_or_zero(const Vec<Q>& u);

/// B x (in R^{2nc}) of a quasistatic problem's x = (v_n, v_t^+, v_t^-): (v_n, v_t^+ - v_t^-).
Vec<Q> contact_velocity(const CheckData& c, const Vec<Q>& x);

/// Whether x (of size n) satisfies X's equations (generic: A x = b; quasistatic: B x + h in the column space of P);
/// the signs are the caller's.
bool satisfies_X(const CheckData& c, const Vec<Q>& x);

/// Why the certificate's embedded problem (read as `problem`) is not the one it certifies, or "": its problem_sha256
/// is not the embedded problem's digest, or, with an embedded assembly (`assembly --ucp`, a step of `simulate` with
/// several bodies), the problem is not the one the checker derives from the assembly's geometry
/// (assembly_ucp_check.h).
std::string embedding_violation(const exact::JsonInput& cert, const solvers::ucp::UcpProblem& problem);

}  // namespace contactcert::checker::ucp_sets
