#include "solvers/design/distribute.h"

#ifdef CONTACTCERT_HAVE_MPI
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#endif

namespace contactcert::solvers {
namespace {

class SerialDistributor : public Distributor {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  bool run(const ChunkSource& next, const ChunkWork& work, const ChunkRecord& record,
           const std::function<bool()>& keep_going) override {
    for (;;) {
      const std::optional<long> chunk = next();
      if (!chunk) return true;
      if (!keep_going()) return false;
      const std::optional<std::string> result = work(*chunk, keep_going);
      if (!result) return false;
      record(*chunk, *result);
    }
  }
  void agree(const std::string&) override {}
  std::string from_root(const std::string& text) override { return text; }
  void abort_all(const std::string&, int) override {}
};

}  // namespace

std::unique_ptr<Distributor> serial_distributor() { return std::make_unique<SerialDistributor>(); }

#ifdef CONTACTCERT_HAVE_MPI
namespace {

bool launched_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

/// The MPI distributor of the module beside the executable (build tree), else of the one installed under the
/// executable's prefix (PREFIX/bin/contactcert, PREFIX/LIBDIR/contactcert/libcontactcert_mpi.so). MPI's libraries are
/// loaded only here: linked into the program they cost every command ~10 ms of start-up. RTLD_GLOBAL: MPI's own plugins
/// resolve their symbols against the MPI library.
std::unique_ptr<Distributor> mpi_distributor() {
  std::vector<std::string> places;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    places.push_back((exe.parent_path() / "libcontactcert_mpi.so").string());
    places.push_back((exe.parent_path().parent_path() / CONTACTCERT_MPI_MODULE).string());
  }
  std::string why;
  for (const std::string& path : places) {
    if (void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL)) {
      using Make = Distributor* (*)();
      if (auto make = reinterpret_cast<Make>(dlsym(module, "contactcert_mpi_distributor")))
        return std::unique_ptr<Distributor>(make());
    }
    why += std::string(why.empty() ? "" : "; ") + dlerror();
  }
  throw std::runtime_error("cannot load the MPI distribution (" + why + ")");
}

}  // namespace

std::unique_ptr<Distributor> make_distributor() {
  return launched_by_mpirun() ? mpi_distributor() : serial_distributor();
}
#else
std::unique_ptr<Distributor> make_distributor() { return serial_distributor(); }
#endif

}  // namespace contactcert::solvers
