// The number types of exact/ under their short names in the namespace of solvers/: Q the rationals, Vec<T> and Mat<T>
// the column vectors and matrices over a number type T (exact/number.h).
#pragma once

#include "exact/number.h"

namespace contactcert::solvers {

using exact::Mat;
using exact::Q;
using exact::Vec;

}  // namespace contactcert::solvers
