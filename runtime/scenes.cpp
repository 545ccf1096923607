#include "runtime/scenes.h"

#include <filesystem>
#include <system_error>

namespace contactcert::runtime {

std::string bundled_scenes_dir() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (const char* rel : {"../share/contactcert/scenes", "scenes"}) {
      const fs::path p = (exe.parent_path() / rel).lexically_normal();
      if (fs::exists(p / "pang1994_dataset1.json", ec)) return p.string();
    }
  return CONTACTCERT_SCENES_DIR;
}

}  // namespace contactcert::runtime
