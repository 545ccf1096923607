// Small helpers for the geometry tests.
#pragma once

#include <initializer_list>

#include "exact/number.h"

namespace contactcert::geometry::testing {

/// An exact matrix from integer rows.
inline exact::Mat<exact::Q> rows(std::initializer_list<std::initializer_list<long>> r) {
  exact::Mat<exact::Q> M(static_cast<Eigen::Index>(r.size()), static_cast<Eigen::Index>(r.begin()->size()));
  Eigen::Index i = 0;
  for (auto& row : r) {
    Eigen::Index j = 0;
    for (long v : row) M(i, j++) = v;
    ++i;
  }
  return M;
}

/// An exact vector from integers.
inline exact::Vec<exact::Q> vec(std::initializer_list<long> v) {
  exact::Vec<exact::Q> x(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (long e : v) x(i++) = e;
  return x;
}

}  // namespace contactcert::geometry::testing
