#include "queries/scene_input.h"

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"

namespace contactcert::queries {

exact::Q parse_snap_tolerance(const std::string& text, const std::string& file, const std::string& field) {
  exact::Q tol;
  if (!exact::parse_rational_into(text, tol) || sgn(tol) <= 0)
    throw exact::InputError(file, field, "a tolerance > 0 such as 1e-9, got " + exact::quoted_excerpt(text));
  return tol;
}

SceneInput parse_scene(const std::string& text, const std::string& name, const std::string& snap_tolerance,
                       const std::string& snap_field) {
  SceneInput in{name, text, {}, {}};
  if (!snap_tolerance.empty()) {
    const exact::Q tol =
        parse_snap_tolerance(snap_tolerance, snap_field == "--snap" ? "command line" : name, snap_field);
    geometry::SnappedScene s = geometry::snap_planar_scene(text, name, tol);
    in.text = std::move(s.text);
    in.snaps = std::move(s.snaps);
  }
  in.scene = geometry::read_planar_scene(exact::JsonInput::parse(in.text, name));
  return in;
}

SceneInput load_scene(const std::string& path, const std::string& snap_tolerance, const std::string& snap_field) {
  return parse_scene(exact::JsonInput::read_text(path), path, snap_tolerance, snap_field);
}

}  // namespace contactcert::queries
