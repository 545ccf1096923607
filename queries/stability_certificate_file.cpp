#include "queries/stability_certificate_file.h"

#include "exact/json_input.h"
#include "queries/contact_forces.h"
#include "queries/json_out.h"
#include "solvers/stability/stability_certificate.h"

namespace contactcert::queries {

std::string stability_certificate_file(const std::string& scene_text, const geometry::PlanarScene& scene,
                                       const exact::Vec<exact::Q>& g, const solvers::StabilityResult<exact::Q>& r) {
  json j = solvers::stability_certificate_json(scene_text, g, r);
  if (r.has_resting) j["resting"]["contacts"] = contacts_json(scene, r.touching, r.resting_forces);
  if (r.has_moving) j["moving"]["contacts"] = contacts_json(scene, r.touching, r.moving.forces);
  return exact::json_text(j, 1) + "\n";
}

}  // namespace contactcert::queries
