// --snap TOL on the commands that read a planar scene: float input made exact on purpose (geometry/snap.h).
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace contactcert::cli {

/// Adds --snap TOL to a subcommand that reads a planar scene.
void add_snap_option(CLI::App& sub, std::string& snap);

/// The text of a planar scene file; with `snap` (a tolerance, "" = none) the text snapped by
/// geometry::snap_planar_scene, each snap reported on stderr ("snapped FIELD: ORIGINAL -> SNAPPED (moved ~D)").
std::string read_scene_text(const std::string& file, const std::string& snap);

}  // namespace contactcert::cli
