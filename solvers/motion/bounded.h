// The grid on which the motion's numbers keep a bounded size (docs/motion.md, "Bounded numbers"): the applied
// twist's rotation and centre, a carried finger's slide and the free part of the translation correction.
#pragma once

#include "exact/number.h"

namespace contactcert::solvers::motion {

using exact::Q;

/// x rounded to the nearest multiple of 2^-40 (x itself for double): the grid of the applied twist, on which the
/// pose's numbers keep a bounded size (mpq_class keeps lowest terms, so a pose reached by an exact motion has the
/// size of its own value, not of the path to it).
/// The rounding in integers: n = floor(x 2^40 + 1/2) = floor((2^41 num + den) / (2 den)), then n / 2^40 in lowest
/// terms (GMP's rational operations take their operands so: == compares numerators and denominators).
inline Q on_grid(const Q& x) {
  exact::Z n, d;
  mpz_mul_2exp(n.get_mpz_t(), x.get_num_mpz_t(), 41);
  mpz_add(n.get_mpz_t(), n.get_mpz_t(), x.get_den_mpz_t());
  mpz_mul_2exp(d.get_mpz_t(), x.get_den_mpz_t(), 1);
  mpz_fdiv_q(n.get_mpz_t(), n.get_mpz_t(), d.get_mpz_t());
  Q out(n, exact::Z(1) << 40);
  out.canonicalize();
  return out;
}

/// x itself while its numerator and denominator take at most 128 bits together, else on_grid(x): exact where that
/// is cheap (the derived contact times of simple scenes stay exact), bounded where it is not.
inline Q bounded(const Q& x) {
  const std::size_t bits = mpz_sizeinbase(x.get_num_mpz_t(), 2) + mpz_sizeinbase(x.get_den_mpz_t(), 2);
  return bits <= 128 ? x : on_grid(x);
}
inline double bounded(double x) { return x; }

}  // namespace contactcert::solvers::motion
