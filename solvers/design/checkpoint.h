// Checkpoints of a design run: which chunks are done and the merged result of those chunks (top K and
// statistics), so a run killed at any moment resumes and ends with the same result. Written atomically
// (a temporary file beside it, then rename), so a kill leaves the previous or the new checkpoint, never half.
// A checkpoint is input like any other file: it carries the SHA-256 of its own content beside the problem's
// digest, and a resume checks every field against the problem (indices, counts, order) and re-decides every
// placement it lists before using it.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "solvers/design/ranking.h"
#include "solvers/design/symmetry.h"

namespace contactcert::solvers {

/// A set of chunk indices as disjoint maximal ranges [first, last]: memory grows with the ranges, not the chunks.
class ChunkSet {
 public:
  void insert(long chunk) { insert_range(chunk, chunk); }
  /// Adds the chunks first..last, merging ranges that touch.
  void insert_range(long first, long last);
  bool contains(long chunk) const;
  /// The least chunk >= from that is not in the set.
  long next_missing(long from) const;
  const std::map<long, long>& ranges() const { return ranges_; }

 private:
  std::map<long, long> ranges_;  ///< first -> last
};

/// Placements in the chunks of `done` (chunks of `size` placements out of `total`).
long placements_in(const ChunkSet& done, long size, long total);

struct DesignCheckpoint {
  std::string problem_key;  ///< digest of what was searched (scene, candidates, options): a resume must match it
  long chunk_size = 0;
  long chunks = 0;
  ChunkSet done;
  ChunkResult result;  ///< merged over the done chunks
};

/// Writes the checkpoint; InputError naming the file if it cannot be written.
void write_checkpoint(const std::string& path, const DesignCheckpoint& c);

/// The checkpoint at `path` of `problem` searched in chunks of `chunk_size` with the best `k` kept, or nullopt when
/// there is no such file. InputError naming the file and the field when it is not a regular file, is larger than
/// the input limit, is not a checkpoint of this problem (another key, chunk size or chunk count), its content
/// digest does not match (edited or damaged), or any entry is inconsistent: done ranges out of [0, chunks),
/// unsorted or overlapping; statistics that do not add up to the placements of the done chunks; a top placement
/// that is not `fixels` increasing candidate indices, lies in a chunk not done, is out of rank order, or whose
/// figure differs from its own re-decided one.
std::optional<DesignCheckpoint> read_checkpoint(const std::string& path, const std::string& problem_key,
                                                const DesignProblem& problem, const CandidateSymmetry& symmetry,
                                                long chunk_size, long total, std::size_t k);

}  // namespace contactcert::solvers
