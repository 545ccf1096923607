// Distribution of design chunks over processes: serially, or on MPI ranks with dynamic load balancing (the
// cost of one placement varies by orders of magnitude, so a static split leaves ranks idle). The root hands
// out chunk indices one at a time as ranks ask for work, and works on chunks itself between requests when
// there are few ranks; only the root records results. MPI stays behind this interface (distribute_mpi.cpp,
// built only when MPI is found, as a module loaded under mpirun); a serial build and a run without mpirun use
// distribute_serial.cpp's path.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace contactcert::solvers {

/// Computes one chunk; `between` is called between placements and returning false aborts it (nullopt).
using ChunkWork = std::function<std::optional<std::string>(long chunk, const std::function<bool()>& between)>;
/// Root only: a finished chunk's result text.
using ChunkRecord = std::function<void(long chunk, const std::string& result)>;
/// Root only: the next chunk to hand out, or nullopt when none is left (chunks are produced as they are handed
/// out, so no list of every chunk is ever built).
using ChunkSource = std::function<std::optional<long>()>;

class Distributor {
 public:
  virtual ~Distributor() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  bool is_root() const { return rank() == 0; }
  /// Every rank must call this with the text that identifies its problem (candidates, options): a rank whose text
  /// differs from the root's (e.g. another scene file at the same path on its node) ends the run with exit 2.
  virtual void agree(const std::string& problem) = 0;
  /// Every rank must call this: the root's `text` on every rank (how the root tells the others of a decision
  /// only it can make, such as refusing a checkpoint, so that no rank waits for work that never comes).
  virtual std::string from_root(const std::string& text) = 0;
  /// Runs the chunks of `next` (called on the root only) until all are recorded or `keep_going` (root, polled
  /// between placements) returns false. Returns true on every rank when every chunk was recorded.
  virtual bool run(const ChunkSource& next, const ChunkWork& work, const ChunkRecord& record,
                   const std::function<bool()>& keep_going) = 0;
  /// An error on one rank that the others cannot learn of: MPI prints `message` and ends every rank with `code`
  /// (MPI_Abort; waiting ranks would otherwise hang); serial returns and the caller reports the error.
  virtual void abort_all(const std::string& message, int code) = 0;
};

/// The serial distributor.
std::unique_ptr<Distributor> serial_distributor();

/// MPI when the program was built with MPI and started by mpirun (an MPI launcher's environment), else serial.
/// Initialises MPI on construction and finalises it on destruction.
std::unique_ptr<Distributor> make_distributor();

}  // namespace contactcert::solvers
