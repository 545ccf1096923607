// Seeded random LPs for the simplex tests: small integer data in [-3, 3], many degenerate (b often 0,
// rank-deficient A, repeated columns), some with free variables.
#pragma once

#include <random>

#include "exact/lp_problem.h"

namespace contactcert::exact::testing {

inline LpProblem<Q> random_lp(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> small(-3, 3), rows(1, 5), cols(1, 7), pct(0, 99);
  const int m = rows(rng), n = cols(rng);
  LpProblem<Q> p;
  p.A = Mat<Q>(m, n);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) p.A(i, j) = pct(rng) < 30 ? 0 : small(rng);
  if (m >= 2 && pct(rng) < 30) p.A.row(m - 1) = p.A.row(0) * Q(small(rng)) + p.A.row(m - 2);  // rank-deficient
  if (n >= 2 && pct(rng) < 20) p.A.col(n - 1) = -p.A.col(0);  // a column and its negative
  p.b = Vec<Q>(m);
  const int b_kind = pct(rng);
  if (b_kind < 30) {
    p.b.setZero();
  } else if (b_kind < 65) {  // b = A x0 with x0 >= 0 sparse: feasible, often degenerate
    Vec<Q> x0 = Vec<Q>::Zero(n);
    for (int j = 0; j < n; ++j) x0(j) = pct(rng) < 50 ? 0 : (small(rng) + 3) / 2;
    p.b = p.A * x0;
  } else {
    for (int i = 0; i < m; ++i) p.b(i) = small(rng);
  }
  p.c = Vec<Q>(n);
  for (int j = 0; j < n; ++j) p.c(j) = pct(rng) < 20 ? 0 : small(rng);
  if (pct(rng) < 15) {
    p.is_free.assign(static_cast<size_t>(n), false);
    p.is_free[static_cast<size_t>(pct(rng) % n)] = true;
  }
  return p;
}

}  // namespace contactcert::exact::testing
