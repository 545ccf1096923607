#include "exact/rational_vector.h"

namespace contactcert::exact {

RationalVector::RationalVector(const Vec<Q>& v) {
  const auto entry = [&v](Eigen::Index i) -> const Q& { return v(i); };
  try {
    num_.resize(static_cast<std::size_t>(v.size()));
    den_ = ring::to_common_denominator<Int128>(v.size(), entry, num_.data());
  } catch (const RingOverflow&) {
    num_.clear();
    wide_ = true;
    wide_num_.resize(static_cast<std::size_t>(v.size()));
    wide_den_ = ring::to_common_denominator<Z>(v.size(), entry, wide_num_.data());
  }
}

RationalVector::RationalVector(const Int128* num, Eigen::Index k, Int128 den) : num_(num, num + k), den_(den) {
  if (den_ < 0) {
    den_ = ring::sub(0, den_);
    for (Int128& n : num_) n = ring::sub(0, n);
  }
}

RationalVector::RationalVector(const Z* num, Eigen::Index k, Z den)
    : wide_num_(num, num + k), wide_den_(std::move(den)), wide_(true) {
  if (sgn(wide_den_) < 0) {
    wide_den_ = -wide_den_;
    for (Z& n : wide_num_) n = -n;
  }
}

Q RationalVector::operator()(Eigen::Index i) const {
  Q q;
  const auto k = static_cast<std::size_t>(i);
  if (wide_)
    ring::to_rational(wide_num_[k], wide_den_, q);
  else
    ring::to_rational(num_[k], den_, q);
  return q;
}

Vec<Q> RationalVector::to_q() const {
  Vec<Q> v(size());
  for (Eigen::Index i = 0; i < size(); ++i) v(i) = (*this)(i);
  return v;
}

void RationalVector::numerators(Int128* out, Int128& den) const {
  if (wide_) {
    for (std::size_t k = 0; k < wide_num_.size(); ++k) ring::from_integer(wide_num_[k], out[k]);
    ring::from_integer(wide_den_, den);
  } else {
    std::copy(num_.begin(), num_.end(), out);
    den = den_;
  }
}

void RationalVector::numerators(Z* out, Z& den) const {
  if (wide_) {
    std::copy(wide_num_.begin(), wide_num_.end(), out);
    den = wide_den_;
  } else {
    for (std::size_t k = 0; k < num_.size(); ++k) out[k] = ring::to_z(num_[k]);
    den = ring::to_z(den_);
  }
}

}  // namespace contactcert::exact
