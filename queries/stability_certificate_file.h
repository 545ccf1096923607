// The `stability` certificate file (solvers/stability/stability_certificate.h) with its readable part: the
// witness's world forces under "resting"/"contacts" and "moving"/"contacts" (contacts_json, queries/contact_forces.h).
// The checker verifies the raw "forces"; `check` recomputes the contacts from them and compares.
#pragma once

#include <string>

#include "geometry/planar_scene.h"
#include "solvers/stability/strong_stability.h"

namespace contactcert::queries {

std::string stability_certificate_file(const std::string& scene_text, const geometry::PlanarScene& scene,
                                       const exact::Vec<exact::Q>& g, const solvers::StabilityResult<exact::Q>& r);

}  // namespace contactcert::queries
