#include "solvers/design/distribute.h"

namespace contactcert::solvers {
namespace {

class SerialDistributor : public Distributor {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  bool run(const std::vector<long>& todo, const ChunkWork& work, const ChunkRecord& record,
           const std::function<bool()>& keep_going) override {
    for (long chunk : todo) {
      if (!keep_going()) return false;
      const std::optional<std::string> result = work(chunk, keep_going);
      if (!result) return false;
      record(chunk, *result);
    }
    return true;
  }
  void agree(const std::string&) override {}
  void abort_all(const std::string&, int) override {}
};

}  // namespace

std::unique_ptr<Distributor> serial_distributor() { return std::make_unique<SerialDistributor>(); }

#ifndef CONTACTCERT_HAVE_MPI
std::unique_ptr<Distributor> make_distributor() { return serial_distributor(); }
#endif

}  // namespace contactcert::solvers
