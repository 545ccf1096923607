#include "solvers/spatial/spatial_stability_certificate.h"

#include <nlohmann/json.hpp>

#include "solvers/spatial/spatial_certificate_lines.h"
#include "solvers/stability/sparse_motzkin.h"
#include "solvers/stability/stability_certificate.h"

namespace contactcert::solvers::spatial {

using json = nlohmann::ordered_json;

std::string spatial_stability_certificate(const geometry::SpatialScene& scene, const std::string& scene_text,
                                          const Vec<Q>& g, const SpatialStability& r) {
  json head = stability_certificate_head("spatial_stability", r.verdict, scene_text, g);
  head["resting"] = r.has_resting ? json{{"weights", exact_strings(r.resting_weights)}}
                                  : json{{"motzkin", sparse_motzkin_json(r.resting_motzkin)}};
  if (r.has_moving)
    head["moving"] = {{"mode", r.moving.mode},
                      {"weights", exact_strings(r.moving.weights)},
                      {"acceleration", exact_strings(r.moving.acceleration)}};
  std::string out = "{";
  for (auto it = head.begin(); it != head.end(); ++it)
    out += std::string(it == head.begin() ? "\n " : ",\n ") + json(it.key()).dump() + ": " + it.value().dump();
  // The proofs, one line each: dead prefixes grouped by their parent (a node of the tree, its dead children's
  // letters and vectors), then the moving modes.
  const RowNames names(spatial_model(scene));
  VectorLines vectors;
  const std::vector<std::string> dead = dead_lines(r.tree, names, vectors);
  std::vector<std::string> modes;
  for (const SpatialModeProof& p : r.proofs)
    modes.push_back(json{{"mode", p.mode}, {"vector", vectors.index(names.line(p.mode, p.motzkin, true))}}.dump());
  put_lines(out, "vectors", vectors.lines());
  put_lines(out, "dead", dead);
  put_lines(out, "modes", modes);
  return out + "\n}\n";
}

}  // namespace contactcert::solvers::spatial
