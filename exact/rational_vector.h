// A vector of rationals held as integer numerators over one common denominator: the form the exact integer
// routes compute in (the UCP's physical recovery, solvers/ucp/recovery.h). The numbers are kept in 128-bit
// integers when they fit and in GMP integers otherwise; a GMP rational (two heap allocations) is made only when an
// entry is read as one.
#pragma once

#include <boost/container/small_vector.hpp>
#include <vector>

#include "exact/fraction_free.h"

namespace contactcert::exact {

class RationalVector {
 public:
  RationalVector() = default;
  /// The entries of v.
  explicit RationalVector(const Vec<Q>& v);
  /// num[i] / den for i < k (den != 0, either sign; nothing needs to be in lowest terms).
  RationalVector(const Int128* num, Eigen::Index k, Int128 den);
  RationalVector(const Z* num, Eigen::Index k, Z den);

  Eigen::Index size() const { return static_cast<Eigen::Index>(wide_ ? wide_num_.size() : num_.size()); }
  /// The sign of entry i (read from its numerator: no rational is made).
  int sign(Eigen::Index i) const {
    const auto k = static_cast<std::size_t>(i);
    return wide_ ? sgn(wide_num_[k]) : ring::sign(num_[k]);
  }
  /// Entry i as num / den with den > 0, not necessarily in lowest terms (no gcd).
  void entry(Eigen::Index i, Z& num, Z& den) const;
  /// Entry i in lowest terms.
  Q operator()(Eigen::Index i) const;
  /// All entries.
  Vec<Q> to_q() const;
  /// The entries as out[i] / den with den > 0 (Int128: throws RingOverflow if they are held in GMP integers that do
  /// not fit, so that with_exact_ring restarts in Z).
  void numerators(Int128* out, Int128& den) const;
  void numerators(Z* out, Z& den) const;

 private:
  boost::container::small_vector<Int128, 8> num_;  ///< inline up to 8 entries: no heap allocation for small problems
  Int128 den_ = 1;
  std::vector<Z> wide_num_;
  Z wide_den_;         // unused (and unallocated: GMP 6.2 allocates on first assignment) unless wide_
  bool wide_ = false;  ///< held in wide_num_ / wide_den_
};

}  // namespace contactcert::exact
