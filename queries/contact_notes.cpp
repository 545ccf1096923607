#include "queries/contact_notes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace contactcert::queries {

std::string tiny_gap_notes(const geometry::PlanarScene& scene, const std::string& indent) {
  // size^2 = the squared largest distance from the com to the workpiece (a disk: (|c - com| + r)^2 >= r^2).
  exact::Q size2 = 0;
  if (const auto* d = std::get_if<geometry::DiskShape>(&scene.workpiece.shape)) {
    size2 = d->radius * d->radius;
  } else {
    for (const auto& v : std::get<geometry::PolygonShape>(scene.workpiece.shape).vertices)
      size2 = std::max(size2, geometry::norm2(v - scene.workpiece.com));
  }
  const exact::Q limit = size2 / exact::Q(exact::Z("1" + std::string(60, '0')));
  std::string out;
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const exact::Q& g2 = scene.fixels[i].frame.gap_squared;
    if (sgn(g2) <= 0 || g2 >= limit) continue;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g", std::sqrt(g2.get_d()));
    out += indent + "note: fixel " + std::to_string(i) + " is " + buf +
           " from the workpiece, so it does not touch (only a gap of exactly 0 touches)\n";
  }
  return out;
}

}  // namespace contactcert::queries
