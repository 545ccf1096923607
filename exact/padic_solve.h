// Dixon's p-adic lifting (J. D. Dixon, "Exact solution of linear equations using p-adic expansions", Numer. Math. 40,
// 1982): the solution of a square integer system A x = b from one LU factorisation of A modulo a word-size prime p.
// With r_0 = b and, step by step, x_s = A^-1 r_s mod p and r_{s+1} = (r_s - A x_s) / p (an exact division),
// X = sum_s x_s p^s solves A X = b modulo P = p^S; each entry n / d of x is then read off X mod P by rational
// reconstruction (extended Euclid stopped at sqrt(P / 2); von zur Gathen and Gerhard, Modern Computer Algebra,
// section 5.10), over a common denominator, and A n = d b is checked exactly. Its cost is k^3 / 3 word operations plus
// k^2 per step, against the k^3 operations on growing integers of fraction-free elimination (IntMatrix::solve).
#pragma once

#include <optional>
#include <vector>

#include "exact/int_matrix.h"

namespace contactcert::exact {

/// The solution x of A x = b over a common denominator.
struct LiftedSolution {
  std::vector<Z> U;  ///< x = U / D
  Z D;               ///< > 0, and gcd(D, U_0, ..., U_{k-1}) = 1
};

/// The solution of A x = b for M = [A | b] (k x (k + 1)), checked exactly; nullopt if A is singular modulo each of the
/// primes tried (so possibly singular: the caller decides by fraction-free elimination), or if no reconstruction
/// checks by the step where P exceeds twice the square of the Hadamard bound of [A | b] (not expected: a reconstruction
/// of P > 2 N D with |numerators| <= N, denominator <= D is the solution).
std::optional<LiftedSolution> padic_solve(const IntMatrix<Z>& M);

}  // namespace contactcert::exact
