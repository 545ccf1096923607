#include "exact/tangent_cone.h"

#include <algorithm>

#include "exact/double_description.h"
#include "exact/fraction_free.h"
#include "exact/interval_number.h"
#include "exact/mpfr_number.h"

namespace contactcert::exact {

// The one double description (double_description.h) started from the orthant, the rows of G as given, in the
// ring of T: the rays come in the order of Motzkin's iteration on the orthant (the order in which the UCP
// search visits the adjacent vertices). A ring ray is a positive multiple of the field ray.
template <class T>
std::optional<std::vector<Vec<T>>> orthant_cone_rays(const Mat<T>& G, long max_rays) {
  const Eigen::Index p = G.cols();
  DdBudget budget;
  budget.max_rays = static_cast<std::size_t>(std::max(max_rays, 0L));
  Mat<T> W;
  try {
    W = with_exact_ring<T>(
        [&]<class R>() { return ring::to_field_rows<T>(orthant_rays<R>(ring::to_ring_rows<R>(G), budget), p); });
  } catch (const BudgetExceeded&) {
    return std::nullopt;
  }
  std::vector<Vec<T>> rays;
  for (Eigen::Index r = 0; r < W.rows(); ++r) {
    Vec<T> w = W.row(r).transpose();
    for (Eigen::Index j = 0; j < p; ++j) {
      if (is_zero(w(j))) continue;
      if (w(j) == T(1)) break;
      const T first = w(j);
      for (Eigen::Index l = j; l < p; ++l) w(l) /= first;  // entries before j are 0; w(j) becomes 1
      break;
    }
    rays.push_back(std::move(w));
  }
  return rays;
}

template std::optional<std::vector<Vec<double>>> orthant_cone_rays<double>(const Mat<double>&, long);
template std::optional<std::vector<Vec<Q>>> orthant_cone_rays<Q>(const Mat<Q>&, long);
template std::optional<std::vector<Vec<Mpfr>>> orthant_cone_rays<Mpfr>(const Mat<Mpfr>&, long);
template std::optional<std::vector<Vec<Interval>>> orthant_cone_rays<Interval>(const Mat<Interval>&, long);

}  // namespace contactcert::exact
