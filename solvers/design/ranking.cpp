#include "solvers/design/ranking.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "exact/input_error.h"
#include "exact/rational_text.h"

namespace contactcert::solvers {

long placement_count(long n, int k) {
  if (k < 0 || n < k) return 0;
  exact::Z c = 1;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;  // C(n-k+i, i), exact at every step
  return c > (exact::Z(1) << 62) ? -1 : c.get_si();
}

Placement placement_at(long index, long n, int k) {
  // Lexicographic unranking: the first element is the least a with index < C(n-1-a, k-1) cumulated.
  Placement p;
  long a = 0;
  for (int slot = k; slot > 0; --slot) {
    for (;; ++a) {
      const long below = placement_count(n - 1 - a, slot - 1);
      if (index < below) break;
      index -= below;
    }
    p.push_back(static_cast<int>(a++));
  }
  return p;
}

bool ranks_before(const Ranked& a, const Ranked& b) {
  if (a.figure != b.figure) return a.figure > b.figure;
  return a.placement < b.placement;
}

void TopK::offer(Ranked r) {
  if (k_ == 0) return;
  if (items_.size() == k_ && !ranks_before(r, items_.back())) return;
  items_.insert(std::upper_bound(items_.begin(), items_.end(), r, ranks_before), std::move(r));
  if (items_.size() > k_) items_.pop_back();
}

void TopK::merge(const TopK& other) {
  for (const Ranked& r : other.items_) offer(r);
}

long DesignStatistics::evaluated() const {
  long n = 0;
  for (long c : by_status) n += c;
  return n;
}

void DesignStatistics::add(const DesignStatistics& o) {
  for (int i = 0; i < kPlacementStatusCount; ++i) by_status[i] += o.by_status[i];
  lps += o.lps;
}

ChunkResult run_chunk(const DesignProblem& problem, const CandidateSymmetry& symmetry, long chunk, long size,
                      long total, std::size_t k, const std::function<bool()>& between, bool* complete) {
  ChunkResult out{TopK(k), {}};
  const long first = chunk * size, last = std::min(total, first + size);
  const long n = static_cast<long>(problem.candidates.size());
  Placement p = placement_at(first, n, problem.fixels);
  *complete = true;
  for (long i = first; i < last; ++i) {
    const Evaluation e = evaluate_placement(problem, symmetry, p);
    ++out.statistics.by_status[static_cast<int>(e.status)];
    out.statistics.lps += e.lps;
    if (e.status == PlacementStatus::kAccepted) out.top.offer({p, e.figure});
    // Next k-subset in lexicographic order.
    int j = problem.fixels - 1;
    while (j >= 0 && p[static_cast<std::size_t>(j)] == n - problem.fixels + j) --j;
    if (j >= 0) {
      ++p[static_cast<std::size_t>(j)];
      for (int m = j + 1; m < problem.fixels; ++m)
        p[static_cast<std::size_t>(m)] = p[static_cast<std::size_t>(m - 1)] + 1;
    }
    if (between && !between() && i + 1 < last) {
      *complete = false;
      break;
    }
  }
  return out;
}

std::string chunk_result_text(const ChunkResult& r) {
  nlohmann::json top = nlohmann::json::array();
  for (const Ranked& x : r.top.items())
    top.push_back({{"placement", x.placement}, {"figure", exact::to_string(x.figure)}});
  nlohmann::json by = nlohmann::json::array();
  for (long c : r.statistics.by_status) by.push_back(c);
  return nlohmann::json{{"top", top}, {"by_status", by}, {"lps", r.statistics.lps}}.dump();
}

ChunkResult parse_chunk_result(const std::string& text, std::size_t k) {
  const nlohmann::json j = nlohmann::json::parse(text);  // written by chunk_result_text
  ChunkResult out{TopK(k), {}};
  for (const auto& x : j.at("top"))
    out.top.offer({x.at("placement").get<Placement>(), exact::parse_rational(x.at("figure").get<std::string>())});
  for (int i = 0; i < kPlacementStatusCount; ++i) out.statistics.by_status[i] = j.at("by_status").at(i).get<long>();
  out.statistics.lps = j.at("lps").get<long>();
  return out;
}

}  // namespace contactcert::solvers
