// Helpers shared by the Balkcom-Trinkle solver tests: bundled scenes with a chosen friction, and wrenches.
#pragma once

#include <random>
#include <string>

#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "runtime/scenes.h"

namespace contactcert::solvers::testing {

/// scenes/<name> with mu_s = mu_k = mu at every fixel (runtime/scenes.h).
inline geometry::PlanarScene scene_with_mu(const std::string& name, const char* mu) {
  auto s = geometry::load_planar_scene((contactcert::runtime::bundled_scenes_dir() + "/") + name);
  for (auto& f : s.fixels) f.mu_s = f.mu_k = exact::parse_rational(mu);
  return s;
}

/// The wrench (fx, fy, tz) in Q.
inline exact::Vec<exact::Q> wrench(long fx, long fy, long tz) {
  exact::Vec<exact::Q> g(3);
  g << fx, fy, tz;
  return g;
}

/// A wrench with components drawn from d: tz first, then fy, then fx. The draws are sequenced here because the
/// evaluation order of function arguments is unspecified (gcc evaluates them right to left, clang left to right),
/// so `wrench(d(rng), d(rng), d(rng))` would build other wrenches under the sanitizer build's clang.
inline exact::Vec<exact::Q> random_wrench(std::uniform_int_distribution<int>& d, std::mt19937_64& rng) {
  const long tz = d(rng);
  const long fy = d(rng);
  const long fx = d(rng);
  return wrench(fx, fy, tz);
}

}  // namespace contactcert::solvers::testing
