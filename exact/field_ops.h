// Allocation-free field primitives used in the inner loops of pivoting (not algorithms: the plain operation for
// every number type, and an overload for Q that reuses scratch storage).
#pragma once

#include "exact/number.h"

namespace contactcert::exact {

/// x -= a * b, using `tmp` as scratch (avoids a temporary rational per operation).
template <class T>
void sub_mul(T& x, const T& a, const T& b, T&) {
  x -= a * b;
}
inline void sub_mul(Q& x, const Q& a, const Q& b, Q& tmp) {
  mpq_mul(tmp.get_mpq_t(), a.get_mpq_t(), b.get_mpq_t());
  mpq_sub(x.get_mpq_t(), x.get_mpq_t(), tmp.get_mpq_t());
}
/// x *= a.
template <class T>
void mul_by(T& x, const T& a) {
  x *= a;
}
inline void mul_by(Q& x, const Q& a) { mpq_mul(x.get_mpq_t(), x.get_mpq_t(), a.get_mpq_t()); }

}  // namespace contactcert::exact
