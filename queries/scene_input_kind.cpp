#include "queries/scene_input_kind.h"

#include <chrono>

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "geometry/assembly.h"
#include "geometry/spatial_scene.h"
#include "solvers/ucp/phases.h"

namespace contactcert::queries {

bool is_assembly_text(const std::string& text, const std::string& name) {
  // Only a text that names the key is parsed here: a problem of thousands of contacts is not parsed twice.
  if (text.find("bodies") == std::string::npos) return false;
  try {
    return geometry::is_assembly(exact::JsonInput::parse(text, name));
  } catch (const exact::InputError&) {
    return false;  // not JSON: the scene's or problem's reader reports it
  }
}

bool is_spatial_text(const std::string& text, const std::string& name) {
  if (text.find("spatial") == std::string::npos) return false;
  try {
    return geometry::is_spatial_scene(exact::JsonInput::parse(text, name));
  } catch (const exact::InputError&) {
    return false;
  }
}

SceneOrAssembly load_scene_or_assembly(const std::string& path, const std::string& snap_tolerance,
                                       const std::string& snap_field) {
  std::string text = exact::JsonInput::read_text(path);
  const bool spatial = is_spatial_text(text, path);
  if (!spatial && !is_assembly_text(text, path)) return parse_scene(text, path, snap_tolerance, snap_field);
  if (!snap_tolerance.empty())
    throw exact::InputError(snap_field == "--snap" ? "command line" : path, snap_field,
                            spatial ? "a spatial scene is read exactly; snapping reads one planar workpiece only"
                                    : "an assembly (a file with bodies) is read exactly; snapping reads one "
                                      "workpiece only");
  if (spatial) return parse_spatial(text, path);
  return parse_assembly(text, path);
}

UcpOrAssembly load_ucp_or_assembly(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  double read = 0;  // CPU seconds, as the phases count them
  std::string text;
  {
    const solvers::ucp::PhaseTimer t(read);
    text = exact::JsonInput::read_text(path);
    if (is_assembly_text(text, path)) return parse_assembly(text, path);
  }
  UcpInput in = parse_ucp(text, path);
  in.setup.parse += read;
  in.seconds = seconds_since(start);
  return in;
}

}  // namespace contactcert::queries
