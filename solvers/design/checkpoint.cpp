#include "solvers/design/checkpoint.h"

#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"

namespace contactcert::solvers {
namespace {

using exact::JsonInput;

/// The checkpoint's content, whose canonical SHA-256 the file carries beside it.
nlohmann::ordered_json content_json(const DesignCheckpoint& c) {
  nlohmann::ordered_json done = nlohmann::ordered_json::array();
  for (const auto& [first, last] : c.done.ranges()) done.push_back({first, last});
  nlohmann::ordered_json top = nlohmann::ordered_json::array();
  for (const Ranked& x : c.result.top.items())
    top.push_back({{"placement", x.placement}, {"figure", exact::to_string(x.figure)}});
  nlohmann::ordered_json by = nlohmann::ordered_json::array();
  for (long n : c.result.statistics.by_status) by.push_back(n);
  return {{"chunk_size", c.chunk_size},
          {"chunks", c.chunks},
          {"done", done},
          {"result", {{"top", top}, {"by_status", by}, {"lps", c.result.statistics.lps}}}};
}

/// $.content.done: maximal ranges [first, last] of chunks, increasing, disjoint and not adjacent (as written).
ChunkSet read_done(const JsonInput& d, long chunks) {
  ChunkSet done;
  long previous = -2;
  for (const JsonInput& r : d.elements()) {
    if (!r.is_array() || r.size() != 2) r.fail("a chunk range [first, last]");
    const std::vector<JsonInput> ends = r.elements();
    const long first = ends[0].integer(0, chunks - 1), last = ends[1].integer(first, chunks - 1);
    if (first <= previous + 1) r.fail("chunk ranges in increasing order, disjoint and not adjacent (as written)");
    done.insert_range(first, last);
    previous = last;
  }
  return done;
}

/// $.content.result.by_status and lps: non-negative counts adding up to the placements of the done chunks.
DesignStatistics read_statistics(const JsonInput& r, long placements) {
  DesignStatistics s;
  const JsonInput by = r.at("by_status");
  if (!by.is_array() || by.size() != static_cast<std::size_t>(kPlacementStatusCount))
    by.fail(std::to_string(kPlacementStatusCount) + " counts, one per placement status");
  long sum = 0;
  const std::vector<JsonInput> counts = by.elements();
  for (int i = 0; i < kPlacementStatusCount; ++i) {
    const long n = counts[static_cast<std::size_t>(i)].integer(0, placements);
    if (n > placements - sum)
      by.fail("counts adding up to the " + std::to_string(placements) + " placements of the done chunks");
    sum += n;
    s.by_status[static_cast<std::size_t>(i)] = n;
  }
  if (sum != placements)
    by.fail("counts adding up to the " + std::to_string(placements) +
            " placements of the done chunks (they add up to " + std::to_string(sum) + ")");
  s.lps = r.at("lps").integer(0, LONG_MAX);
  return s;
}

/// One entry of $.content.result.top: `fixels` increasing candidate indices of a done chunk, and its figure.
Ranked read_ranked(const JsonInput& e, const DesignProblem& problem, const ChunkSet& done, long chunk_size) {
  if (!e.is_object()) e.fail("a ranked placement {\"placement\": [...], \"figure\": \"p/q\"}");
  e.expect_keys({"placement", "figure"});
  const JsonInput pl = e.at("placement");
  if (!pl.is_array() || pl.size() != static_cast<std::size_t>(problem.fixels))
    pl.fail(std::to_string(problem.fixels) + " candidate indices (--fixels)");
  const long n = static_cast<long>(problem.candidates.size());
  Ranked r;
  for (const JsonInput& i : pl.elements()) {
    const long c = i.integer(0, n - 1);
    if (!r.placement.empty() && c <= r.placement.back())
      i.fail("candidate indices in increasing order (distinct, sorted)");
    r.placement.push_back(static_cast<int>(c));
  }
  const long chunk = placement_index(r.placement, n) / chunk_size;
  if (!done.contains(chunk))
    pl.fail("a placement of a done chunk (this one is in chunk " + std::to_string(chunk) + ", not done)");
  const JsonInput figure = e.at("figure");
  if (!figure_from_text(figure.string(), r.figure)) figure.fail("an exact figure in lowest terms (\"p/q\")");
  return r;
}

/// $.content.result: the statistics, then the top list, each placement re-decided (its figure must be its own).
ChunkResult read_result(const JsonInput& r, const DesignProblem& problem, const CandidateSymmetry& symmetry,
                        const ChunkSet& done, long chunk_size, long total, std::size_t k) {
  if (!r.is_object()) r.fail("a design result {\"top\", \"by_status\", \"lps\"}");
  r.expect_keys({"top", "by_status", "lps"});
  ChunkResult out{TopK(k), read_statistics(r, placements_in(done, chunk_size, total))};
  const long accepted = out.statistics.by_status[static_cast<std::size_t>(PlacementStatus::kAccepted)];
  const std::size_t want = std::min(k, static_cast<std::size_t>(accepted));
  const JsonInput top = r.at("top");
  if (!top.is_array() || top.size() != want)
    top.fail("the best " + std::to_string(want) + " placements (--top, or every accepted one if fewer)");
  std::optional<Ranked> previous;
  for (const JsonInput& e : top.elements()) {
    Ranked x = read_ranked(e, problem, done, chunk_size);
    if (previous && !ranks_before(*previous, x)) e.fail("placements best first, each once");
    const Evaluation again = evaluate_placement(problem, symmetry, x.placement);
    if (again.status != PlacementStatus::kAccepted)
      e.at("placement")
          .fail(std::string("an accepted placement (re-decided, it is ") + placement_status_name(again.status) + ")");
    if (again.figure != x.figure) e.at("figure").fail("the placement's own figure (re-decided, it differs)");
    previous = x;
    out.top.offer(std::move(x));
  }
  return out;
}

}  // namespace

void ChunkSet::insert_range(long first, long last) {
  auto it = ranges_.upper_bound(first);
  if (it != ranges_.begin()) {
    const auto before = std::prev(it);
    if (before->second + 1 >= first) {
      first = before->first;
      last = std::max(last, before->second);
      it = ranges_.erase(before);
    }
  }
  while (it != ranges_.end() && it->first <= last + 1) {
    last = std::max(last, it->second);
    it = ranges_.erase(it);
  }
  ranges_[first] = last;
}

bool ChunkSet::contains(long chunk) const { return next_missing(chunk) != chunk; }

long ChunkSet::next_missing(long from) const {
  auto it = ranges_.upper_bound(from);
  if (it == ranges_.begin()) return from;
  --it;
  return it->second >= from ? it->second + 1 : from;
}

long placements_in(const ChunkSet& done, long size, long total) {
  long n = 0;
  for (const auto& [first, last] : done.ranges())
    n += std::min(total, (last + 1) * size) - first * size;  // chunks below chunk_count: no overflow
  return n;
}

void write_checkpoint(const std::string& path, const DesignCheckpoint& c) {
  const nlohmann::ordered_json content = content_json(c);
  const nlohmann::ordered_json j = {{"kind", "design_checkpoint"},
                                    {"problem", c.problem_key},
                                    {"content_digest", exact::canonical_sha256(content)},
                                    {"content", content}};
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << exact::json_text(j) << "\n";
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw exact::InputError(path, "", "a writable checkpoint file (--checkpoint)");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw exact::InputError(path, "", "a checkpoint path that can be replaced by rename (--checkpoint)");
  }
}

std::optional<DesignCheckpoint> read_checkpoint(const std::string& path, const std::string& problem_key,
                                                const DesignProblem& problem, const CandidateSymmetry& symmetry,
                                                long chunk_size, long total, std::size_t k) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) return std::nullopt;
  if (!std::filesystem::is_regular_file(status))
    throw exact::InputError(path, "", "a regular file as the checkpoint (--checkpoint; it is replaced by rename)");
  const JsonInput root = JsonInput::load(path);  // the input limits: 32 MiB, nesting depth
  if (!root.is_object()) root.fail("a design checkpoint (a JSON object)");
  root.expect_keys({"kind", "problem", "content_digest", "content"});
  if (root.at("kind").string() != "design_checkpoint") root.at("kind").fail("\"design_checkpoint\"");
  if (root.at("problem").string() != problem_key)
    root.at("problem").fail(
        "a checkpoint of this design (same scene, candidates and options); delete it to start over");
  const JsonInput content = root.at("content");
  if (!content.is_object()) content.fail("the checkpoint's content (a JSON object)");
  if (root.at("content_digest").string() != content.canonical_sha256())
    root.at("content_digest")
        .fail(
            "the SHA-256 of $.content (the checkpoint was edited or damaged after it was written); delete it to "
            "start over");
  content.expect_keys({"chunk_size", "chunks", "done", "result"});
  DesignCheckpoint c;
  c.problem_key = problem_key;
  c.chunk_size = chunk_size;
  c.chunks = chunk_count(total, chunk_size);
  if (content.at("chunk_size").integer(1, LONG_MAX) != chunk_size)
    content.at("chunk_size").fail("this run's --chunk-size " + std::to_string(chunk_size));
  if (content.at("chunks").integer(1, LONG_MAX) != c.chunks)
    content.at("chunks").fail("this design's " + std::to_string(c.chunks) + " chunks");
  const JsonInput done = content.at("done");
  if (!done.is_array()) done.fail("an array of chunk ranges [first, last]");
  c.done = read_done(done, c.chunks);
  c.result = read_result(content.at("result"), problem, symmetry, c.done, chunk_size, total, k);
  return c;
}

}  // namespace contactcert::solvers
