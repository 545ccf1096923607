#include "solvers/assembly/assembly_certificate_memory.h"

#include <algorithm>

namespace contactcert::solvers::assembly {

using Eigen::Index;

bool motzkin_holds(const AssemblySystem& s, const Vec<Q>& y) {
  const exact::SparseStrictSystem<Q>& S = s.system;
  if (y.size() != S.rows) return false;
  std::vector<Q> yA(static_cast<std::size_t>(S.cols));
  for (const exact::Entry<Q>& e : S.entries)
    if (sgn(y(e.row)) != 0) yA[static_cast<std::size_t>(e.col)] += y(e.row) * e.value;
  bool strict_positive = false;
  for (std::size_t j = 0; j < yA.size(); ++j) {
    const int sign = sgn(yA[j]);
    if (S.is_free[j] ? sign != 0 : sign < 0) return false;
    strict_positive = strict_positive || (sign > 0 && S.strict[j]);
  }
  Q yb = 0;
  for (Index i = 0; i < y.size(); ++i)
    if (sgn(s.b(i)) != 0) yb += y(i) * s.b(i);
  return sgn(yb) < 0 || (sgn(yb) == 0 && strict_positive);
}

std::optional<Vec<Q>> CertificateMemory::recall(const AssemblySystem& s, std::size_t length) {
  if (length >= by_length_.size()) return std::nullopt;
  std::deque<Labelled>& list = by_length_[length];
  const Index labels = s.row_label.empty() ? 0 : *std::max_element(s.row_label.begin(), s.row_label.end()) + 1;
  by_label_.assign(static_cast<std::size_t>(labels), nullptr);
  for (auto it = list.begin(); it != list.end(); ++it) {
    for (const auto& [label, value] : *it)
      if (label < labels) by_label_[static_cast<std::size_t>(label)] = &value;
    Vec<Q> y = Vec<Q>::Zero(s.system.rows);
    for (Index r = 0; r < y.size(); ++r)
      if (const Q* v = by_label_[static_cast<std::size_t>(s.row_label[static_cast<std::size_t>(r)])]) y(r) = *v;
    for (const auto& [label, value] : *it)
      if (label < labels) by_label_[static_cast<std::size_t>(label)] = nullptr;
    if (!motzkin_holds(s, y)) continue;
    std::rotate(list.begin(), it, it + 1);
    return y;
  }
  return std::nullopt;
}

void CertificateMemory::remember(const AssemblySystem& s, std::size_t length, const Vec<Q>& y) {
  if (length >= by_length_.size()) by_length_.resize(length + 1);
  Labelled l;
  for (Index r = 0; r < y.size(); ++r)
    if (sgn(y(r)) != 0) l.emplace_back(s.row_label[static_cast<std::size_t>(r)], y(r));
  std::deque<Labelled>& list = by_length_[length];
  list.push_front(std::move(l));
  if (list.size() > per_length_) list.pop_back();
}

}  // namespace contactcert::solvers::assembly
