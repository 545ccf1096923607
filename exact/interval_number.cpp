#include "exact/interval_number.h"

#include <CGAL/mpq_class.h>
#include <CGAL/mpz_class.h>

namespace contactcert::exact {

Interval to_interval(const Q& q) { return Interval(CGAL::to_interval(q)); }

Interval to_interval(const Z& z) { return Interval(CGAL::to_interval(z)); }

Q to_rational(const Interval& x) { return (Q(x.inf()) + Q(x.sup())) / 2; }

LpProblem<Interval> to_interval(const LpProblem<Q>& problem) {
  return convert_lp<Interval>(problem, [](const Q& q) { return to_interval(q); });
}

}  // namespace contactcert::exact
