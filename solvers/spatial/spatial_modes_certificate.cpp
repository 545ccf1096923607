#include "solvers/spatial/spatial_modes_certificate.h"

#include <nlohmann/json.hpp>

#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "solvers/spatial/spatial_certificate_lines.h"

namespace contactcert::solvers::spatial {

std::string spatial_modes_certificate(const std::string& scene_text, const SpatialModeTree& tree) {
  const exact::JsonInput in = exact::JsonInput::parse(scene_text, "scene");
  std::string out = "{\n \"kind\": \"spatial_modes\",\n \"scene\": " + nlohmann::json(scene_text).dump() +
                    ",\n \"problem_sha256\": \"" + in.canonical_sha256() + "\"";
  const RowNames names(spatial_model(geometry::read_spatial_scene(in)));
  VectorLines vectors;
  const std::vector<std::string> dead = dead_lines(tree, names, vectors);
  std::vector<std::string> modes;
  for (std::size_t i = 0; i < tree.modes.size(); ++i) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (Eigen::Index d = 0; d < 6; ++d) a.push_back(exact::to_string(tree.accelerations[i](d)));
    modes.push_back(nlohmann::ordered_json{{"mode", tree.modes[i]}, {"acceleration", a}}.dump());
  }
  put_lines(out, "vectors", vectors.lines());
  put_lines(out, "dead", dead);
  put_lines(out, "modes", modes);
  return out + "\n}\n";
}

}  // namespace contactcert::solvers::spatial
