// The search space of a design and its results: placements in lexicographic order (C(N, k) of them, split into
// chunks of consecutive indices), the K best under a total order, and the statistics of what was decided.
// Everything here is independent of how the chunks were distributed: the top K of a union is the top K of the
// parts' top Ks, and counts add, so a run gives the same result on any number of ranks.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "solvers/design/evaluate.h"

namespace contactcert::solvers {

/// C(n, k), or -1 when it exceeds 2^62.
long placement_count(long n, int k);

/// The placement with lexicographic index `index` among the k-subsets of {0..n-1}.
Placement placement_at(long index, long n, int k);

/// The lexicographic index of a placement (increasing indices in [0, n)): the inverse of placement_at. Slot s
/// skips the subsets led by each a in (previous, p_s), sum_a C(n-1-a, k-1-s) = C(n-lo, k-s) - C(n-p_s, k-s)
/// (hockey stick), so the index costs k binomials, not n.
long placement_index(const Placement& p, long n);

/// Chunks of `size` consecutive placements covering `total`: ceil(total / size), without overflow.
long chunk_count(long total, long size);
/// Placements in chunk `chunk`: [chunk size, min(total, (chunk + 1) size)), as their count.
long chunk_length(long chunk, long size, long total);

/// An accepted placement and its figure.
struct Ranked {
  Placement placement;
  exact::Q figure;
};

/// The total order of the report: larger figure first, ties by the candidate indices (lexicographic).
bool ranks_before(const Ranked& a, const Ranked& b);

/// The best `k` placements seen, best first.
class TopK {
 public:
  explicit TopK(std::size_t k = 0) : k_(k) {}
  void offer(Ranked r);
  void merge(const TopK& other);
  const std::vector<Ranked>& items() const { return items_; }

 private:
  std::size_t k_;
  std::vector<Ranked> items_;
};

struct DesignStatistics {
  std::array<long, kPlacementStatusCount> by_status{};
  long lps = 0;
  long evaluated() const;
  void add(const DesignStatistics& o);
};

/// The outcome of some chunks: their top K and statistics.
struct ChunkResult {
  TopK top;
  DesignStatistics statistics;
  void merge(const ChunkResult& o) {
    top.merge(o.top);
    statistics.add(o.statistics);
  }
};

/// Placements [chunk * size, (chunk + 1) * size) of `total`, evaluated in order; `between` runs after each
/// placement (a distributed root serves requests there) and stops the chunk early by returning false (then
/// the result is incomplete and must not be recorded). `cones` (one per problem) shares insertion cones across
/// placements and chunks.
ChunkResult run_chunk(const DesignProblem& problem, const CandidateSymmetry& symmetry, long chunk, long size,
                      long total, std::size_t k, const std::function<bool()>& between, bool* complete,
                      InsertionCones<exact::Q>* cones = nullptr);

/// Text form of a chunk result (exact figures as strings), for the messages between ranks.
std::string chunk_result_text(const ChunkResult& r);
/// The chunk result of chunk_result_text's text (internal: figures of any length, no input limits).
ChunkResult parse_chunk_result(const std::string& text, std::size_t k);

/// A figure as exact::to_string writes it ("-7/20", "3"), of any length; false unless text is exactly that form.
/// Internal figures are read back here, never by the input parser and its digit limit.
bool figure_from_text(std::string_view text, exact::Q& out);

}  // namespace contactcert::solvers
