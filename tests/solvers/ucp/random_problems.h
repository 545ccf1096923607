// The seeded random quasistatic problems of the UCP solver tests (section 5 generator).
#pragma once

#include <random>

#include "solvers/ucp/generate.h"

namespace contactcert::solvers::ucp::testing {

/// The problem of test seed `seed`: nc = 2 + seed % nc_values contacts, friction coefficients in
/// (0, (1 + seed % 4) / 2), |abar| = seed % (nc + 1), the generator seeded with `seed`. Consecutive seeds
/// cycle through every (nc, mu_max) pair within lcm(nc_values, 4) seeds.
inline UcpProblem random_problem(int seed, int nc_values) {
  std::mt19937_64 gen(static_cast<std::uint64_t>(seed));
  RandomProblemOptions o;
  o.nc = 2 + seed % nc_values;
  o.mu_max = Q(1 + seed % 4, 2);
  o.mu_max.canonicalize();
  o.abar_size = seed % (o.nc + 1);
  return generate_random_problem(o, gen);
}

}  // namespace contactcert::solvers::ucp::testing
