// Motzkin certificates carried from one wrench of a batch to the next. Every system of a stability verdict has the
// right-hand side b(g) = (0, ..., 0, g) (motion_system.h), and of the Motzkin conditions on y (strict_feasibility.h)
// only y^T b <= 0 and "y^T b < 0 or (y^T A)_j > 0 for a strict j" involve b: the others hold for every g once they
// hold for one. So a certificate y that proved the system infeasible for an earlier wrench proves it for g exactly
// when y_dyn . g < 0, or y_dyn . g = 0 and (y^T A)_j > 0 for some strict column j (y_dyn: y's last 3 entries): one
// exact dot product instead of an LP. Only exact numbers are reused (a float certificate is not a proof).
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "exact/number.h"
#include "exact/strict_feasibility.h"

namespace contactcert::solvers {

/// The last certificates of each system of one oracle (slot 0: the resting system, then one slot per mode), for
/// the verdicts of one batch (one caller: not shared between threads).
template <class T>
class ReusedCertificates {
 public:
  /// A certificate of slot `slot` that proves its system infeasible for wrench g, or nullptr.
  const exact::Vec<T>* find(std::size_t slot, const exact::Vec<T>& g) {
    if constexpr (!exact::NumberTraits<T>::is_exact) return nullptr;
    if (slot >= slots_.size()) return nullptr;
    std::vector<Kept>& kept = slots_[slot];
    for (std::size_t i = 0; i < kept.size(); ++i) {
      const int s = exact::sign(T(kept[i].y.tail(3).dot(g)));
      if (s < 0 || (s == 0 && kept[i].strict_positive)) {
        std::rotate(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(i),
                    kept.begin() + static_cast<std::ptrdiff_t>(i) + 1);  // the ones that keep proving come first
        return &kept.front().y;
      }
    }
    return nullptr;
  }

  /// Keeps y, a certificate (exactly checked) that `system` is infeasible for some wrench; at most kPerSlot per
  /// slot, the oldest dropped.
  void keep(std::size_t slot, const exact::SparseStrictSystem<T>& system, const exact::Vec<T>& y) {
    if constexpr (!exact::NumberTraits<T>::is_exact) return;
    if (slot >= slots_.size()) slots_.resize(slot + 1);
    // (y^T A)_j on the strict columns.
    std::vector<T> yA(static_cast<std::size_t>(system.cols), T(0));
    for (const auto& e : system.entries) yA[static_cast<std::size_t>(e.col)] += y(e.row) * e.value;
    bool strict_positive = false;
    for (std::size_t j = 0; j < yA.size() && !strict_positive; ++j)
      strict_positive = j < system.strict.size() && system.strict[j] && exact::sign(yA[j]) > 0;
    std::vector<Kept>& kept = slots_[slot];
    if (kept.size() == kPerSlot) kept.pop_back();
    kept.insert(kept.begin(), Kept{y, strict_positive});
  }

 private:
  static constexpr std::size_t kPerSlot = 4;
  struct Kept {
    exact::Vec<T> y;
    bool strict_positive = false;
  };
  std::vector<std::vector<Kept>> slots_;
};

}  // namespace contactcert::solvers
