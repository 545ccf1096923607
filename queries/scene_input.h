// A planar scene as a query reads it (docs/formats.md section 3): the file's name (for messages), its text (a
// certificate embeds it) and the parsed scene; read from a file or a text, optionally snapped on purpose (--snap
// TOL, geometry/snap.h), with the snaps made so that a front end can report them.
#pragma once

#include <string>
#include <vector>

#include "geometry/planar_scene.h"
#include "geometry/snap.h"

namespace contactcert::queries {

struct SceneInput {
  std::string name;  ///< the file's name, or the name a text was given under
  std::string text;  ///< the scene's text as read (after snapping)
  geometry::PlanarScene scene;
  std::vector<geometry::Snap> snaps;  ///< what snapping moved (empty without a tolerance)
};

/// A snap tolerance: the exact number > 0 in `text` (e.g. "1e-9"); InputError naming `file` and `field` otherwise.
exact::Q parse_snap_tolerance(const std::string& text, const std::string& file, const std::string& field);

/// The scene in `text` named `name`; with `snap_tolerance` (a number > 0 as text, "" = none) snapped first.
/// InputError naming the file and field for a bad scene, naming `snap_field` for a bad tolerance.
SceneInput parse_scene(const std::string& text, const std::string& name, const std::string& snap_tolerance = "",
                       const std::string& snap_field = "--snap");
/// The scene in the file `path` (read once: a pipe cannot be read again), as parse_scene.
SceneInput load_scene(const std::string& path, const std::string& snap_tolerance = "",
                      const std::string& snap_field = "--snap");

}  // namespace contactcert::queries
