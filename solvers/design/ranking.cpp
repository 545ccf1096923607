#include "solvers/design/ranking.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

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

long placement_index(const Placement& p, long n) {
  const int k = static_cast<int>(p.size());
  long index = 0, lo = 0;
  for (int s = 0; s < k; ++s) {
    const long a = p[static_cast<std::size_t>(s)];
    index += placement_count(n - lo, k - s) - placement_count(n - a, k - s);
    lo = a + 1;
  }
  return index;
}

long chunk_count(long total, long size) { return total / size + (total % size != 0 ? 1 : 0); }

long chunk_length(long chunk, long size, long total) {
  const long first = chunk * size;  // chunk < chunk_count(total, size): below total, no overflow
  return std::min(size, total - first);
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
                      long total, std::size_t k, const std::function<bool()>& between, bool* complete,
                      InsertionCones<exact::Q>* cones) {
  ChunkResult out{TopK(k), {}};
  const long first = chunk * size, last = first + chunk_length(chunk, size, total);
  const long n = static_cast<long>(problem.candidates.size());
  Placement p = placement_at(first, n, problem.fixels);
  *complete = true;
  for (long i = first; i < last; ++i) {
    const Evaluation e = evaluate_placement(problem, symmetry, p, nullptr, cones);
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

bool figure_from_text(std::string_view text, exact::Q& out) {
  std::size_t i = text.size() > 0 && text[0] == '-' ? 1 : 0;
  const std::size_t slash = text.find('/');
  const std::string_view num = text.substr(i, slash == std::string_view::npos ? text.npos : slash - i);
  const std::string_view den = slash == std::string_view::npos ? std::string_view() : text.substr(slash + 1);
  auto digits = [](std::string_view d) {
    return !d.empty() && d.find_first_not_of("0123456789") == std::string_view::npos && (d[0] != '0' || d.size() == 1);
  };
  if (!digits(num) || (slash != std::string_view::npos && !digits(den))) return false;
  if (mpq_set_str(out.get_mpq_t(), std::string(text).c_str(), 10) != 0 || sgn(out.get_den()) == 0) return false;
  const exact::Z den_before = out.get_den();
  out.canonicalize();
  // The lowest-terms form: nothing cancelled, a denominator above 1, no "-0".
  return out.get_den() == den_before && (slash == std::string_view::npos || out.get_den() != 1) &&
         !(i == 1 && sgn(out) == 0);
}

ChunkResult parse_chunk_result(const std::string& text, std::size_t k) {
  const nlohmann::json j = nlohmann::json::parse(text);  // written by chunk_result_text
  ChunkResult out{TopK(k), {}};
  for (const auto& x : j.at("top")) {
    exact::Q figure;
    if (!figure_from_text(x.at("figure").get<std::string>(), figure))
      throw std::logic_error("a chunk result with a malformed figure");
    out.top.offer({x.at("placement").get<Placement>(), figure});
  }
  for (int i = 0; i < kPlacementStatusCount; ++i) out.statistics.by_status[i] = j.at("by_status").at(i).get<long>();
  out.statistics.lps = j.at("lps").get<long>();
  return out;
}

}  // namespace contactcert::solvers
