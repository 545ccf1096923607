#include "exact/rational_vector.h"

namespace contactcert::exact {

RationalVector::RationalVector(const Vec<Q>& v) {
  // v over its least common denominator, in Int128 or, when a number does not fit, in Z.
  *this = with_exact_ring<Q, Int128>([&v]<class R>() {
    boost::container::small_vector<R, 8> num(static_cast<std::size_t>(v.size()));
    const R den = ring::to_common_denominator<R>(
        v.size(), [&v](Eigen::Index i) -> const Q& { return v(i); }, num.data());
    return RationalVector(num.data(), v.size(), den);
  });
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

void RationalVector::entry(Eigen::Index i, Z& num, Z& den) const {
  const auto k = static_cast<std::size_t>(i);
  num = wide_ ? wide_num_[k] : ring::to_z(num_[k]);
  den = wide_ ? wide_den_ : ring::to_z(den_);
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
