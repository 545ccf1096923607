#include "exact/interval_number.h"

#include <CGAL/mpq_class.h>

namespace contactcert::exact {

Interval to_interval(const Q& q) { return Interval(CGAL::to_interval(q)); }

Interval to_interval(const Z& z) {
  if (mpz_sizeinbase(z.get_mpz_t(), 2) <= 53) return Interval(z.get_d());  // a double exactly
  return to_interval(Q(z));
}

Q to_rational(const Interval& x) { return (Q(x.inf()) + Q(x.sup())) / 2; }

LpProblem<Interval> to_interval(const LpProblem<Q>& problem) {
  return convert_lp<Interval>(problem, [](const Q& q) { return to_interval(q); });
}

}  // namespace contactcert::exact
