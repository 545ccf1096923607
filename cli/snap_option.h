// --snap TOL on the commands that read a planar scene: float input made exact on purpose (geometry/snap.h).
#pragma once

#include <string>

#include "queries/scene_input.h"
#include "queries/scene_input_kind.h"

namespace CLI {
class App;
}

namespace contactcert::cli {

/// Adds --snap TOL to a subcommand that reads a planar scene.
void add_snap_option(CLI::App& sub, std::string& snap);

/// The scene of `file` (queries::load_scene) with `snap` (a tolerance, "" = none), each snap reported on stderr
/// ("snapped FIELD: ORIGINAL -> SNAPPED (moved ~D)").
queries::SceneInput read_scene(const std::string& file, const std::string& snap);
/// The scene or assembly of `file` (queries::load_scene_or_assembly), a scene's snaps reported as read_scene does.
queries::SceneOrAssembly read_scene_or_assembly(const std::string& file, const std::string& snap);

}  // namespace contactcert::cli
