// A small SVG line plot with linear axes (the friction sweep of Figure 11 in the demo report).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace contactcert::queries {

struct LineSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  ///< (x, y), drawn in order
};

/// A complete <svg> element: axes from 0 to a round number above the data, ticks, axis labels, a legend.
std::string line_plot_svg(const std::vector<LineSeries>& series, const std::string& title, const std::string& x_label,
                          const std::string& y_label);

}  // namespace contactcert::queries
