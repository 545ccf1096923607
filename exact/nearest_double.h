// The float view of an exact number that every `_approx` output prints: the nearest double.
#pragma once

#include "exact/number.h"

namespace contactcert::exact {

/// q rounded to the nearest double (ties to even; GMP's get_d truncates: 1/10 would print as 0.09999999999999999,
/// the nearest double prints as 0.1).
double nearest_double(const Q& q);
Vec<double> nearest_doubles(const Vec<Q>& v);

}  // namespace contactcert::exact
