// Checkpoints of a design run: which chunks are done and the merged result of those chunks (top K and
// statistics), so a run killed at any moment resumes and ends with the same result. Written atomically
// (a temporary file beside it, then rename), so a kill leaves the previous or the new checkpoint, never half.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "solvers/design/ranking.h"

namespace contactcert::solvers {

struct DesignCheckpoint {
  std::string problem_key;  ///< what was searched (scene, candidates, options): a resume must match it
  long chunk_size = 0;
  long chunks = 0;
  std::vector<bool> done;  ///< per chunk
  ChunkResult result;      ///< merged over the done chunks
};

/// Writes the checkpoint; InputError naming the file if it cannot be written.
void write_checkpoint(const std::string& path, const DesignCheckpoint& c);

/// The checkpoint at `path`, or nullopt when there is no such file. InputError when it is not a checkpoint
/// of this problem (another key, chunk size or chunk count) or is malformed.
std::optional<DesignCheckpoint> read_checkpoint(const std::string& path, const std::string& problem_key,
                                                long chunk_size, long chunks, std::size_t k);

}  // namespace contactcert::solvers
