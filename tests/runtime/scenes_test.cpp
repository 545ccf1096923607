#include "runtime/scenes.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace contactcert::runtime {
namespace {

// A test program is neither installed nor beside a scenes/ folder: the source tree's scenes.
TEST(BundledScenes, FoundFromABuildTree) {
  const std::filesystem::path dir = bundled_scenes_dir();
  EXPECT_TRUE(std::filesystem::exists(dir / "pang1994_dataset1.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "bt2002_section7_disk.json"));
}

}  // namespace
}  // namespace contactcert::runtime
