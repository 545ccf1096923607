#include "exact/mpfr_number.h"

#include <cassert>

namespace contactcert::exact {

Mpfr to_mpfr(const Q& q, long bits) {
  assert(bits >= Mpfr::get_default_precision());
  Mpfr x(0, static_cast<Mpfr::Precision_type>(bits));
  mpfr_set_q(x.fr(), q.get_mpq_t(), MPFR_RNDN);
  return x;
}

Mpfr to_mpfr(const Z& z, long bits) {
  assert(bits >= Mpfr::get_default_precision());
  Mpfr x(0, static_cast<Mpfr::Precision_type>(bits));
  mpfr_set_z(x.fr(), z.get_mpz_t(), MPFR_RNDN);
  return x;
}

Q to_rational(const Mpfr& x) {
  Q q;
  mpfr_get_q(q.get_mpq_t(), x.fr());
  return q;
}

LpProblem<Mpfr> to_mpfr(const LpProblem<Q>& problem, long bits) {
  return convert_lp<Mpfr>(problem, [bits](const Q& q) { return to_mpfr(q, bits); });
}

}  // namespace contactcert::exact
