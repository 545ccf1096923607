// GoogleTest expectations shared by the LP tests: a result must carry the same status and optimal value as a
// reference, and a certificate (optimal duals, Farkas vector, or ray) that verifies exactly.
#pragma once

#include <gtest/gtest.h>

#include "exact/simplex.h"

namespace contactcert::exact::testing {

/// Options that ask for the optimal duals, the certificate of an optimum these expectations verify.
inline LpOptions with_duals() {
  LpOptions o;
  o.duals = true;
  return o;
}

/// `r` has the reference status and (when optimal) optimal value on problem `p`, and every certificate of
/// `r` verifies (case `t`).
inline void expect_certified_like(const LpProblem<Q>& p, const LpResult<Q>& r, LpStatus status, const Q& value, int t) {
  ASSERT_EQ(r.status, status) << "case " << t;
  switch (r.status) {
    case LpStatus::kOptimal:
      ASSERT_EQ(r.value, value) << "case " << t;
      ASSERT_EQ(Q(p.c.dot(r.x)), r.value) << "case " << t;
      ASSERT_TRUE(verify_optimal(p, r.x, r.duals)) << "case " << t;
      break;
    case LpStatus::kInfeasible:
      ASSERT_TRUE(verify_farkas(p, r.farkas)) << "case " << t;
      break;
    case LpStatus::kUnbounded:
      ASSERT_TRUE(verify_ray(p, r.ray)) << "case " << t;
      ASSERT_EQ(p.A * r.x, p.b) << "case " << t;
      break;
    case LpStatus::kPivotLimit:
      FAIL() << "case " << t << ": pivot limit";
    case LpStatus::kTimeLimit:
      FAIL() << "case " << t << ": time limit";
  }
}

/// `r` agrees with the reference result `e` on problem `p`, and every certificate of `r` verifies (case `t`).
inline void expect_certified_like(const LpProblem<Q>& p, const LpResult<Q>& r, const LpResult<Q>& e, int t) {
  expect_certified_like(p, r, e.status, e.value, t);
}

}  // namespace contactcert::exact::testing
