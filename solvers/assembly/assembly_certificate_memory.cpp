#include "solvers/assembly/assembly_certificate_memory.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contactcert::solvers::assembly {

using Eigen::Index;

MotzkinTest::MotzkinTest(const AssemblySystem& s) : s_(s), start_(static_cast<std::size_t>(s.system.rows) + 1, 0) {
  // A counting sort of the entries by row.
  const std::vector<exact::Entry<Q>>& E = s.system.entries;
  for (const exact::Entry<Q>& e : E) ++start_[static_cast<std::size_t>(e.row) + 1];
  for (std::size_t r = 1; r < start_.size(); ++r) start_[r] += start_[r - 1];
  order_.resize(E.size());
  std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
  for (std::size_t t = 0; t < E.size(); ++t) order_[next[static_cast<std::size_t>(E[t].row)]++] = t;
}

bool MotzkinTest::plausible(const std::vector<Multiplier>& y) {
  const exact::SparseStrictSystem<Q>& S = s_.system;
  constexpr double kSlack = 1e-9;
  approx_.resize(S.entries.size(), std::numeric_limits<double>::quiet_NaN());
  yA_approx_.resize(static_cast<std::size_t>(S.cols), 0.0);
  magnitude_.resize(static_cast<std::size_t>(S.cols), 0.0);
  for (const Multiplier& m : y)
    for (std::size_t t = start_[static_cast<std::size_t>(m.row)]; t < start_[static_cast<std::size_t>(m.row) + 1];
         ++t) {
      const exact::Entry<Q>& e = S.entries[order_[t]];
      double& a = approx_[order_[t]];
      if (std::isnan(a)) a = e.value.get_d();
      const auto j = static_cast<std::size_t>(e.col);
      if (magnitude_[j] == 0) touched_.push_back(e.col);
      yA_approx_[j] += m.approx * a;
      magnitude_[j] += std::abs(m.approx * a);
    }
  bool ok = true;
  for (const Index j : touched_) {
    const auto u = static_cast<std::size_t>(j);
    const double v = yA_approx_[u], slack = kSlack * magnitude_[u];
    ok = ok && (!std::isfinite(slack) || (S.is_free[u] ? std::abs(v) <= slack : v >= -slack));
    yA_approx_[u] = magnitude_[u] = 0;
  }
  touched_.clear();
  double yb = 0, yb_magnitude = 0;
  for (const Multiplier& m : y)
    if (sgn(s_.b(m.row)) != 0) {
      const double t = m.approx * s_.b(m.row).get_d();
      yb += t;
      yb_magnitude += std::abs(t);
    }
  return ok && (!std::isfinite(yb_magnitude) || yb <= kSlack * yb_magnitude);
}

bool MotzkinTest::holds(const std::vector<Multiplier>& y) {
  if (!plausible(y)) return false;
  const exact::SparseStrictSystem<Q>& S = s_.system;
  yA_.resize(static_cast<std::size_t>(S.cols));
  // y^T A over the entries of y's rows; the columns they miss have (y^T A)_j = 0, which every sign allows.
  for (const Multiplier& m : y)
    for (std::size_t t = start_[static_cast<std::size_t>(m.row)]; t < start_[static_cast<std::size_t>(m.row) + 1];
         ++t) {
      const exact::Entry<Q>& e = S.entries[order_[t]];
      Q& acc = yA_[static_cast<std::size_t>(e.col)];
      if (sgn(acc) == 0) touched_.push_back(e.col);
      product_ = *m.value * e.value;
      acc += product_;
    }
  bool sign_ok = true, strict_positive = false;
  for (const Index j : touched_) {
    Q& v = yA_[static_cast<std::size_t>(j)];
    const int sign = sgn(v);
    sign_ok = sign_ok && (S.is_free[static_cast<std::size_t>(j)] ? sign == 0 : sign >= 0);
    strict_positive = strict_positive || (sign > 0 && S.strict[static_cast<std::size_t>(j)]);
    v = 0;
  }
  touched_.clear();
  if (!sign_ok) return false;
  Q yb = 0;
  for (const Multiplier& m : y)
    if (sgn(s_.b(m.row)) != 0) yb += *m.value * s_.b(m.row);
  return sgn(yb) < 0 || (sgn(yb) == 0 && strict_positive);
}

bool motzkin_holds(const AssemblySystem& s, const Vec<Q>& y) {
  if (y.size() != s.system.rows) return false;
  std::vector<Multiplier> support;
  for (Index i = 0; i < y.size(); ++i)
    if (sgn(y(i)) != 0) support.push_back({i, &y(i), y(i).get_d()});
  return MotzkinTest(s).holds(support);
}

std::optional<Vec<Q>> CertificateMemory::recall(const AssemblySystem& s, std::size_t length) {
  if (length >= by_length_.size()) return std::nullopt;
  std::deque<Labelled>& list = by_length_[length];
  if (list.empty()) return std::nullopt;
  const Index labels = s.row_label.empty() ? 0 : *std::max_element(s.row_label.begin(), s.row_label.end()) + 1;
  row_of_label_.assign(static_cast<std::size_t>(labels), -1);
  for (std::size_t r = 0; r < s.row_label.size(); ++r)
    row_of_label_[static_cast<std::size_t>(s.row_label[r])] = static_cast<Index>(r);
  MotzkinTest test(s);
  std::vector<Multiplier> y;  // a remembered certificate on the rows of s (zero on the others)
  for (auto it = list.begin(); it != list.end(); ++it) {
    y.clear();
    for (const Weight& w : *it)
      if (w.label < labels && row_of_label_[static_cast<std::size_t>(w.label)] >= 0)
        y.push_back({row_of_label_[static_cast<std::size_t>(w.label)], &w.value, w.approx});
    if (!test.holds(y)) continue;
    Vec<Q> out = Vec<Q>::Zero(s.system.rows);
    for (const Multiplier& m : y) out(m.row) = *m.value;
    std::rotate(list.begin(), it, it + 1);
    return out;
  }
  return std::nullopt;
}

void CertificateMemory::remember(const AssemblySystem& s, std::size_t length, const Vec<Q>& y) {
  if (length >= by_length_.size()) by_length_.resize(length + 1);
  Labelled l;
  for (Index r = 0; r < y.size(); ++r)
    if (sgn(y(r)) != 0) l.push_back({s.row_label[static_cast<std::size_t>(r)], y(r), y(r).get_d()});
  std::deque<Labelled>& list = by_length_[length];
  list.push_front(std::move(l));
  if (list.size() > per_length_) list.pop_back();
}

}  // namespace contactcert::solvers::assembly
