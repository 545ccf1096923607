// `contactcert demo`: the main job on the bundled scenes.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>

#include "cli/command.h"

namespace contactcert::cli {
namespace {

struct DemoOptions {
  std::string scenes = CONTACTCERT_SCENES_DIR;
  std::string out = "contactcert-out";
};

int run_demo(const DemoOptions& opts) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(opts.scenes)) {
    std::cerr << "contactcert demo: scenes folder not found: " << opts.scenes << "\n";
    return 2;
  }
  std::cout << "contactcert demo: bundled scenes in " << opts.scenes << "\n";
  return 0;
}

}  // namespace

void register_demo(CLI::App& app, Action& action) {
  auto opts = std::make_shared<DemoOptions>();
  CLI::App* sub = app.add_subcommand("demo", "Reproduce both papers' worked examples on the bundled scenes");
  sub->add_option("--scenes", opts->scenes, "Folder of scene files")->capture_default_str();
  sub->add_option("--out", opts->out, "Folder for the report and pictures")->capture_default_str();
  sub->callback([opts, &action] { action = [opts] { return run_demo(*opts); }; });
}

}  // namespace contactcert::cli
