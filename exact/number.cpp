#include "exact/number.h"

#include <CGAL/Exact_rational.h>
#include <mpfr.h>

#include <type_traits>

#include "exact/nearest_double.h"

namespace contactcert::exact {

static_assert(std::is_same_v<Q, CGAL::Exact_rational>,
              "contactcert's Q must be CGAL::Exact_rational (see exact/number.h)");

Mat<double> to_double(const Mat<Q>& A) {
  Mat<double> D(A.rows(), A.cols());
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (Eigen::Index j = 0; j < A.cols(); ++j) D(i, j) = A(i, j).get_d();
  return D;
}

Vec<double> to_double(const Vec<Q>& v) {
  Vec<double> d(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) d(i) = v(i).get_d();
  return d;
}

double nearest_double(const Q& q) {
  mpfr_t x;
  mpfr_init2(x, 53);
  mpfr_set_q(x, q.get_mpq_t(), MPFR_RNDN);
  const double d = mpfr_get_d(x, MPFR_RNDN);
  mpfr_clear(x);
  return d;
}

Vec<double> nearest_doubles(const Vec<Q>& v) {
  Vec<double> d(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) d(i) = nearest_double(v(i));
  return d;
}

}  // namespace contactcert::exact
