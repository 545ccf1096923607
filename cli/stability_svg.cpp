#include "cli/stability_svg.h"

#include <cmath>
#include <sstream>

namespace contactcert::cli {

const char* verdict_colour(solvers::StabilityVerdict v) {
  switch (v) {
    case solvers::StabilityVerdict::kStronglyStable: return "#1b7837";
    case solvers::StabilityVerdict::kWeaklyStable: return "#f1c232";
    case solvers::StabilityVerdict::kUnstable: return "#e8a8a8";
  }
  return "#000";
}

std::string stability_sphere_svg(const solvers::StableRegion<exact::Q>& region, int res) {
  // Float copies of the exact cones, for colouring only.
  solvers::StableRegion<double> f;
  auto to_d = [](const geometry::FaceCone<exact::Q>& c) {
    return geometry::FaceCone<double>::from_rows(3, exact::to_double(c.inequalities), exact::to_double(c.equalities),
                                                 exact::to_double(c.strict));
  };
  f.weak = to_d(region.weak);
  for (const auto& c : region.cones) f.cones.push_back(to_d(c));

  const double R = 150, pad = 30, cell = 2 * R / res;
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 4 * R + 3 * pad << "\" height=\"" << 2 * R + 2 * pad + 20
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  for (int side = 0; side < 2; ++side) {
    const double cx = pad + R + side * (2 * R + pad), cy = pad + R, tz_sign = side == 0 ? 1 : -1;
    for (int i = 0; i < res; ++i)
      for (int j = 0; j < res; ++j) {
        const double x = -1 + (i + 0.5) * 2.0 / res, y = 1 - (j + 0.5) * 2.0 / res, r2 = x * x + y * y;
        if (r2 > 1) continue;
        exact::Vec<double> g(3);
        g << x, y, tz_sign * std::sqrt(1 - r2);
        s << "<rect x=\"" << cx - R + i * cell << "\" y=\"" << cy - R + j * cell << "\" width=\"" << cell + 0.3
          << "\" height=\"" << cell + 0.3 << "\" fill=\"" << verdict_colour(f.label(g)) << "\"/>";
      }
    s << "\n<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << R << "\" fill=\"none\" stroke=\"#333\"/>"
      << "<text x=\"" << cx - R << "\" y=\"" << cy + R + 18 << "\">" << (side == 0 ? "torque &gt; 0" : "torque &lt; 0")
      << " (horizontal: f_x, vertical: f_y)</text>\n";
  }
  s << "<text x=\"" << pad << "\" y=\"18\"><tspan fill=\"" << verdict_colour(solvers::StabilityVerdict::kStronglyStable)
    << "\">strongly stable</tspan>, <tspan fill=\"#b8860b\">weakly stable</tspan>, <tspan fill=\"#c0392b\">unstable"
    << "</tspan> wrench directions</text></svg>\n";
  return s.str();
}

}  // namespace contactcert::cli
