#include "exact/simplex_tableau.h"

#include <algorithm>
#include <cassert>

#include "exact/field_ops.h"
#include "exact/interval_number.h"
#include "exact/mpfr_number.h"

namespace contactcert::exact {

template <class T>
SimplexTableau<T>::SimplexTableau(Index m, Index n)
    : m_(m),
      n_(n),
      t_(static_cast<size_t>(m * (n + 1)), T(0)),
      basis_(static_cast<size_t>(m), -1),
      row_of_(static_cast<size_t>(n), -1),
      d_(static_cast<size_t>(n), T(0)) {}

template <class T>
std::optional<SimplexTableau<T>> SimplexTableau<T>::from_basis(const Mat<T>& A, const Vec<T>& b,
                                                               const std::vector<Index>& basis) {
  const Index m = A.rows(), n = A.cols();
  SimplexTableau tab(m, n);
  for (Index r = 0; r < m; ++r) {
    for (Index j = 0; j < n; ++j) tab.at(r, j) = A(r, j);
    tab.at(r, n) = b(r);
  }
  for (Index j : basis) {
    if (j < 0 || j >= n || tab.is_basic(j)) return std::nullopt;
    Index p = -1;
    for (Index r = 0; r < m; ++r) {
      if (tab.basis_[static_cast<size_t>(r)] >= 0 || exact::is_zero(tab.entry(r, j))) continue;
      if (p < 0 || NumberTraits<T>::better_pivot(tab.entry(r, j), tab.entry(p, j))) p = r;
    }
    if (p < 0) return std::nullopt;  // dependent columns
    tab.pivot(p, j);
  }
  // Rows left without a basic variable must be 0 = 0 (redundant), else the basis is too small or b is
  // outside the column space.
  std::vector<Index> redundant;
  for (Index r = m - 1; r >= 0; --r) {
    if (tab.basis_[static_cast<size_t>(r)] >= 0) continue;
    for (Index j = 0; j <= n; ++j)
      if (!exact::is_zero(tab.entry(r, j))) return std::nullopt;
    redundant.push_back(r);
  }
  tab.remove_rows(redundant);
  return tab;
}

template <class T>
SimplexTableau<T> SimplexTableau<T>::artificial_start(const Mat<T>& A, const Vec<T>& b) {
  const Index m = A.rows(), n = A.cols();
  SimplexTableau tab(m, n);
  for (Index r = 0; r < m; ++r) {
    const bool negate = exact::sign(b(r)) < 0;
    for (Index j = 0; j < n; ++j) tab.at(r, j) = negate ? T(-A(r, j)) : A(r, j);
    tab.at(r, n) = negate ? T(-b(r)) : b(r);
    tab.basis_[static_cast<size_t>(r)] = n + r;
  }
  return tab;
}

template <class T>
bool SimplexTableau<T>::has_artificial() const {
  for (Index v : basis_)
    if (v >= n_) return true;
  return false;
}

template <class T>
void SimplexTableau<T>::pivot(Index r, Index s) {
  assert(r >= 0 && r < m_ && s >= 0 && s < n_ && !exact::is_zero(entry(r, s)));
  const Index w = n_ + 1;
  T* row = &t_[static_cast<size_t>(r * w)];
  const T inv = T(1) / row[s];
  nz_.clear();
  for (Index j = 0; j < w; ++j) {
    if (exact::is_negligible(row[j])) continue;
    mul_by(row[j], inv);
    nz_.push_back(j);
  }
  row[s] = T(1);
  T tmp;
  for (Index i = 0; i < m_; ++i) {
    if (i == r) continue;
    T* other = &t_[static_cast<size_t>(i * w)];
    if (exact::is_negligible(other[s])) continue;
    const T f = other[s];
    for (Index j : nz_) sub_mul(other[j], f, row[j], tmp);
    other[s] = T(0);
  }
  if (!exact::is_negligible(d_[static_cast<size_t>(s)])) {
    const T f = d_[static_cast<size_t>(s)];
    for (Index j : nz_) {
      if (j < n_)
        sub_mul(d_[static_cast<size_t>(j)], f, row[j], tmp);
      else
        sub_mul(z_, T(-f), row[j], tmp);  // z = c_B^T x_B grows by d_s * x_s
    }
    d_[static_cast<size_t>(s)] = T(0);
  }
  const Index leaving = basis_[static_cast<size_t>(r)];
  if (leaving >= 0 && leaving < n_) row_of_[static_cast<size_t>(leaving)] = -1;
  basis_[static_cast<size_t>(r)] = s;
  row_of_[static_cast<size_t>(s)] = r;
}

template <class T>
void SimplexTableau<T>::remove_rows(const std::vector<Index>& rows) {
  if (rows.empty()) return;
  const Index w = n_ + 1;
  std::vector<bool> drop(static_cast<size_t>(m_), false);
  for (Index r : rows) drop[static_cast<size_t>(r)] = true;
  Index kept = 0;
  for (Index r = 0; r < m_; ++r) {
    const Index v = basis_[static_cast<size_t>(r)];
    if (drop[static_cast<size_t>(r)]) {
      if (v >= 0 && v < n_) row_of_[static_cast<size_t>(v)] = -1;
      continue;
    }
    if (kept != r) {
      std::move(t_.begin() + r * w, t_.begin() + (r + 1) * w, t_.begin() + kept * w);
      basis_[static_cast<size_t>(kept)] = v;
    }
    if (v >= 0 && v < n_) row_of_[static_cast<size_t>(v)] = kept;
    ++kept;
  }
  m_ = kept;
  t_.resize(static_cast<size_t>(m_ * w));
  basis_.resize(static_cast<size_t>(m_));
}

template <class T>
void SimplexTableau<T>::set_objective(const Vec<T>& c, const T& artificial_cost) {
  T tmp;
  for (Index j = 0; j < n_; ++j) d_[static_cast<size_t>(j)] = c(j);
  z_ = T(0);
  for (Index r = 0; r < m_; ++r) {
    const Index v = basis_[static_cast<size_t>(r)];
    const T cb = v >= n_ ? artificial_cost : (v >= 0 ? c(v) : T(0));
    if (exact::is_negligible(cb)) continue;
    for (Index j = 0; j < n_; ++j)
      if (!exact::is_negligible(entry(r, j))) sub_mul(d_[static_cast<size_t>(j)], cb, entry(r, j), tmp);
    sub_mul(z_, T(-cb), rhs(r), tmp);
  }
  for (Index r = 0; r < m_; ++r) {
    const Index v = basis_[static_cast<size_t>(r)];
    if (v >= 0 && v < n_) d_[static_cast<size_t>(v)] = T(0);
  }
}

template <class T>
Vec<T> SimplexTableau<T>::primal() const {
  Vec<T> x = Vec<T>::Zero(n_);
  for (Index r = 0; r < m_; ++r) {
    const Index v = basis_[static_cast<size_t>(r)];
    if (v >= 0 && v < n_) x(v) = rhs(r);
  }
  return x;
}

template class SimplexTableau<double>;
template class SimplexTableau<Q>;
template class SimplexTableau<Mpfr>;
template class SimplexTableau<Interval>;

}  // namespace contactcert::exact
