// Helpers shared by the Balkcom-Trinkle solver tests: bundled scenes with a chosen friction, and wrenches.
#pragma once

#include <string>

#include "exact/rational_text.h"
#include "geometry/scene_json.h"

namespace contactcert::solvers::testing {

/// scenes/<name> with mu_s = mu_k = mu at every fixel (needs CONTACTCERT_SCENES_DIR).
inline geometry::PlanarScene scene_with_mu(const std::string& name, const char* mu) {
  auto s = geometry::load_planar_scene(std::string(CONTACTCERT_SCENES_DIR "/") + name);
  for (auto& f : s.fixels) f.mu_s = f.mu_k = exact::parse_rational(mu);
  return s;
}

/// The wrench (fx, fy, tz) in Q.
inline exact::Vec<exact::Q> wrench(long fx, long fy, long tz) {
  exact::Vec<exact::Q> g(3);
  g << fx, fy, tz;
  return g;
}

}  // namespace contactcert::solvers::testing
