// What a scene file holds, read once: one movable workpiece (docs/formats.md section 3; for `ucp`, a problem file of
// section 2) or several bodies (an assembly, section 3a: a `planar` or `quasistatic_scene` file with `bodies`). The
// commands that take either - `stability`, `modes` and `ucp` - dispatch on the kind read here, so each question
// on an assembly is the query that `contactcert assembly` runs (queries/assembly_query.h, assembly_modes_query.h).
#pragma once

#include <string>
#include <variant>

#include "queries/assembly_query.h"
#include "queries/scene_input.h"
#include "queries/spatial_modes_query.h"
#include "queries/ucp_query.h"

namespace contactcert::queries {

/// Whether the JSON text is an assembly (it has `bodies`); a text that is not JSON is not one (its reader says why).
bool is_assembly_text(const std::string& text, const std::string& name);

/// Whether the JSON text is a spatial scene ("kind": "spatial", docs/formats.md section 3b).
bool is_spatial_text(const std::string& text, const std::string& name);

using SceneOrAssembly = std::variant<SceneInput, AssemblyInput, SpatialInput>;
/// The scene, assembly or spatial scene in the file `path` (read once), as load_scene, load_assembly or
/// parse_spatial. An assembly or a spatial scene is read exactly: a snap tolerance is refused (InputError naming
/// `snap_field`).
SceneOrAssembly load_scene_or_assembly(const std::string& path, const std::string& snap_tolerance = "",
                                       const std::string& snap_field = "--snap");

using UcpOrAssembly = std::variant<UcpInput, AssemblyInput>;
/// The problem or assembly (a quasistatic_scene with bodies) in the file `path` (read once), as load_ucp or
/// load_assembly; reading the file counts as the problem's parse.
UcpOrAssembly load_ucp_or_assembly(const std::string& path);

}  // namespace contactcert::queries
