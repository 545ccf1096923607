// A cheap enclosure of a rational for interval filters: n / d from the doubles of n and d, widened by its bound on
// their error, instead of to_interval's smallest interval (an exact MPFR division, ~1.1 k instructions a number).
#pragma once

#include "exact/interval_number.h"

namespace contactcert::exact {

/// An interval holding q = n / d: n and d truncated to doubles (mpz_get_d) and divided give r within 3 units of
/// 2^-52 |q| whatever the rounding mode (a run under valgrind ignores it), so [r - 2^-49 |r|, r + 2^-49 |r|], each
/// end rounded by at most 2^-52 |r|, holds q. A small integer is its own point; outside the normal doubles,
/// to_interval(q).
Interval enclose(const Q& q);

}  // namespace contactcert::exact
