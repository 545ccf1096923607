#include "exact/enclose.h"

#include <cmath>

#include "exact/fraction_free.h"

namespace contactcert::exact {

Interval enclose(const Q& q) {
  const mpz_srcptr n = mpq_numref(q.get_mpq_t());
  if (ring::is_integer(q) && mpz_sizeinbase(n, 2) <= 53) return Interval(mpz_get_d(n));
  const double r = mpz_get_d(n) / mpz_get_d(mpq_denref(q.get_mpq_t()));
  const double margin = std::ldexp(std::abs(r), -49);
  if (!std::isfinite(r) || std::abs(r) < 0x1p-960) return to_interval(q);
  return Interval(r - margin, r + margin);
}

}  // namespace contactcert::exact
