#include "cli/snap_option.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>

namespace contactcert::cli {

void add_snap_option(CLI::App& sub, std::string& snap) {
  sub.add_option("--snap", snap,
                 "Read float input on purpose: put fixel points exactly on the boundary and numbers on the simplest "
                 "rational within TOL (e.g. 1e-9); every snap is reported on stderr");
}

namespace {

void report_snaps(const queries::SceneInput& in) {
  for (const geometry::Snap& x : in.snaps)
    std::cerr << "snapped " << x.field << ": " << x.original << " -> " << x.snapped << " (moved ~"
              << std::sqrt(x.distance_squared.get_d()) << ")\n";
}

}  // namespace

queries::SceneInput read_scene(const std::string& file, const std::string& snap) {
  queries::SceneInput in = queries::load_scene(file, snap);
  report_snaps(in);
  return in;
}

queries::SceneOrAssembly read_scene_or_assembly(const std::string& file, const std::string& snap) {
  queries::SceneOrAssembly in = queries::load_scene_or_assembly(file, snap);
  if (const auto* scene = std::get_if<queries::SceneInput>(&in)) report_snaps(*scene);
  return in;
}

}  // namespace contactcert::cli
