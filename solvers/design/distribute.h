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
#include <vector>

namespace contactcert::solvers {

/// Computes one chunk; `between` is called between placements and returning false aborts it (nullopt).
using ChunkWork = std::function<std::optional<std::string>(long chunk, const std::function<bool()>& between)>;
/// Root only: a finished chunk's result text.
using ChunkRecord = std::function<void(long chunk, const std::string& result)>;

class Distributor {
 public:
  virtual ~Distributor() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  bool is_root() const { return rank() == 0; }
  /// Every rank must call this with the text that identifies its problem (candidates, options): a rank whose text
  /// differs from the root's (e.g. another scene file at the same path on its node) ends the run with exit 2.
  virtual void agree(const std::string& problem) = 0;
  /// Runs the chunks of `todo` (read on the root only) until all are recorded or `keep_going` (root, polled
  /// between placements) returns false. Returns true on every rank when every chunk was recorded.
  virtual bool run(const std::vector<long>& todo, const ChunkWork& work, const ChunkRecord& record,
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
