// Problem generators: random quasistatic problems following section 5 of Pang, Trinkle, Lo, and the
// Proposition 2 reduction of 0-1 integer feasibility to the UCP (hard instances with known answers).
#pragma once

#include <random>

#include "solvers/ucp/problem.h"

namespace contactcert::solvers::ucp {

/// Parameters of a random problem of section 5: point fingers on a workpiece, ntheta = 2nc, nq = 3.
struct RandomProblemOptions {
  int nc = 3;
  Q mu_max = 1;       ///< friction coefficients are drawn from (0, mu_max)
  int abar_size = 0;  ///< |abar|: joints that are effort-controlled (unknown velocity), 0 <= |abar| <= 2nc
};

/// A random quasistatic problem (section 5): random contact frames on a workpiece, friction-consistent
/// forces (c_n, c_t) giving g_obj and g_man (so Y is not empty), non-negative v_n and a random q_dot
/// giving theta_dot by (4), (5) (so X is not empty for any alpha), and a random abar of the given size.
UcpProblem generate_random_problem(const RandomProblemOptions& opts, std::mt19937_64& rng);

/// A 0-1 integer feasibility problem (12): A z = b, z in {0, 1}^n.
struct ZeroOneProblem {
  Mat<Q> A;
  Vec<Q> b;
};

/// Proposition 2: X = {(z, w) >= 0 : A z = b, z + w = e}, Y = {(u, v) >= 0 : A v = b, u + v = e}; the UCP
/// has a solution iff (12) does.
UcpProblem reduction_problem(const ZeroOneProblem& zo);

/// A random 0-1 problem with m rows and n columns, entries in [-3, 3]; if `planted`, b = A z for a
/// random z in {0,1}^n (feasible), otherwise b is random (usually infeasible).
ZeroOneProblem random_zero_one(int m, int n, bool planted, std::mt19937_64& rng);

/// Brute force over {0,1}^n (n <= 20): does (12) have a solution?
bool zero_one_feasible(const ZeroOneProblem& zo);

}  // namespace contactcert::solvers::ucp
