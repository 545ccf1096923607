// The float number types of the precision ladder besides double (MPFR floats, double intervals), for the
// .cpp files that instantiate an algorithm for them. Pulls in CGAL: never include it from a header that
// everything includes.
#pragma once

#include "exact/interval_number.h"
#include "exact/mpfr_number.h"
