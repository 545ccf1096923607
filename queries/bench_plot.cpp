// The plots of `contactcert bench`: time against error on log scales, per instance and per family (the
// precision ladder), with strips for errors of exactly 0 and of 1 or more.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "queries/bench_aggregate.h"
#include "queries/html_report.h"

namespace contactcert::queries {

namespace {

using namespace bench_report;

/// One point of a plot: time (s), error against exact, and the shape of its marker (marker_svg).
struct PlotPoint {
  double seconds = 0, error = 0;
  int marker = 0;
};
struct PlotSeries {
  std::string name;
  std::vector<PlotPoint> points;
  bool connect = false;  ///< a line through the points, in order
};

/// Where a plot draws. x: time, log scale. y, top to bottom: a strip for errors >= 1 (a wrong or undecided answer
/// counts as 1), the log scale of errors in (0, 1), and a strip for errors of exactly 0. Each strip has a row per
/// series; in a row, a point that would cover an earlier one (closer than a dot) moves to another of three lanes,
/// and the row ends with its count of points, so coincident answers stay visible and countable.
struct PlotFrame {
  static constexpr double W = 680, left = 86, right = 130, top = 24, row = 14, pad = 4, gap = 14, log_height = 300;
  static constexpr double y_floor = -18;  ///< log10 of the smallest error on the log scale
  std::size_t rows = 1;                   ///< rows per strip: one per series
  double x0 = 0, x1 = 1;                  ///< log10 of the time range
  double strip() const { return rows * row + 2 * pad; }
  double log_top() const { return top + strip() + gap; }
  double zero_top() const { return log_top() + log_height + gap; }
  double height() const { return zero_top() + strip() + 46; }
  double X(double t) const { return left + (std::max(std::log10(t), x0) - x0) / (x1 - x0) * (W - left - right); }
  /// The centre line of a point of series k with error e (before its lane offset).
  double Y(double e, std::size_t k) const {
    if (e >= 1) return top + pad + (k + 0.5) * row;
    if (e <= 0) return zero_top() + pad + (k + 0.5) * row;
    return log_top() + (-std::max(std::log10(e), y_floor)) / -y_floor * log_height;
  }
};

/// The axes, grid lines, strip labels and axis titles.
void draw_axes(std::ostringstream& s, const PlotFrame& f, const std::string& x_label) {
  const double H = f.height(), plot_right = f.W - f.right;
  for (double d = f.x0; d <= f.x1; ++d)
    s << "<line x1=\"" << f.X(std::pow(10, d)) << "\" y1=\"" << f.top << "\" x2=\"" << f.X(std::pow(10, d))
      << "\" y2=\"" << f.zero_top() + f.strip() << "\" stroke=\"#ddd\"/><text x=\"" << f.X(std::pow(10, d)) << "\" y=\""
      << f.zero_top() + f.strip() + 15 << "\" text-anchor=\"middle\">1e" << d << "</text>\n";
  for (double d = -3; d >= f.y_floor; d -= 3)  // 1 and above are the top strip
    s << "<line x1=\"" << f.left << "\" y1=\"" << f.Y(std::pow(10, d), 0) << "\" x2=\"" << plot_right << "\" y2=\""
      << f.Y(std::pow(10, d), 0) << "\" stroke=\"#ddd\"/><text x=\"" << f.left - 5 << "\" y=\""
      << f.Y(std::pow(10, d), 0) + 4 << "\" text-anchor=\"end\">1e" << int(d) << "</text>\n";
  const std::pair<double, const char*> strips[] = {{f.top, "&#8805; 1 or wrong"}, {f.zero_top(), "exactly 0"}};
  for (const auto& [y, name] : strips)
    s << "<rect x=\"" << f.left << "\" y=\"" << y << "\" width=\"" << plot_right - f.left << "\" height=\"" << f.strip()
      << "\" fill=\"#f4f4f4\" stroke=\"#ccc\"/><text x=\"" << f.left - 5 << "\" y=\"" << y + f.strip() / 2 + 4
      << "\" text-anchor=\"end\">" << name << "</text>\n";
  s << "<text x=\"" << plot_right + 6 << "\" y=\"" << f.top - 6 << "\" font-size=\"11\">count</text>\n";
  s << "<text x=\"" << (f.left + plot_right) / 2 << "\" y=\"" << H - 12 << "\" text-anchor=\"middle\">"
    << html_escape(x_label) << "</text>\n<text transform=\"translate(14," << (f.log_top() + f.log_height / 2)
    << ") rotate(-90)\" text-anchor=\"middle\">error against exact</text>\n";
}

/// The positions of a series' points: in a strip, each point takes the first of three lanes (offsets 0, -4, +4)
/// whose last point is at least a dot's width to its left, in order of x (deterministic).
std::vector<std::pair<double, double>> place(const PlotFrame& f, const PlotSeries& ser, std::size_t k) {
  std::vector<std::pair<double, double>> at(ser.points.size());
  std::vector<std::size_t> order(ser.points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return f.X(ser.points[a].seconds) < f.X(ser.points[b].seconds);
  });
  constexpr double lanes[] = {0, -4, 4}, dot = 5;
  double last[2][3];  // per strip (wrong, zero) and lane: the x of its last point
  for (auto& l : last) std::fill(std::begin(l), std::end(l), -1e9);
  for (std::size_t i : order) {
    const PlotPoint& p = ser.points[i];
    const double x = f.X(p.seconds), e = p.error;
    double y = f.Y(e, k);
    if (e >= 1 || e <= 0) {
      double* lane = last[e >= 1 ? 0 : 1];
      std::size_t j = 0;
      while (j < 3 && x - lane[j] < dot) ++j;
      if (j == 3) j = static_cast<std::size_t>(std::min_element(lane, lane + 3) - lane);
      lane[j] = x;
      y += lanes[j];
    }
    at[i] = {x, y};
  }
  return at;
}

/// A marker of shape `shape` (0 circle, 1 square, 2 diamond, 3 triangle up, 4 triangle down, 5 plus, 6 cross,
/// 7 bar; then again) centred at (x, y).
std::string marker_svg(int shape, double x, double y, const char* colour, double opacity) {
  std::ostringstream s;
  const std::string paint = std::string("fill=\"") + colour + "\" fill-opacity=\"" + std::to_string(opacity) + "\"";
  const std::string line = std::string("fill=\"none\" stroke=\"") + colour + "\" stroke-width=\"1.6\"";
  const double r = 3.2;
  switch (shape % 8) {
    case 0:
      s << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"" << r << "\" " << paint << "/>";
      break;
    case 1:
      s << "<rect x=\"" << x - r << "\" y=\"" << y - r << "\" width=\"" << 2 * r << "\" height=\"" << 2 * r << "\" "
        << paint << "/>";
      break;
    case 2:
      s << "<path d=\"M" << x << " " << y - 1.3 * r << "L" << x + 1.3 * r << " " << y << "L" << x << " " << y + 1.3 * r
        << "L" << x - 1.3 * r << " " << y << "Z\" " << paint << "/>";
      break;
    case 3:
    case 4: {
      const double d = shape % 8 == 3 ? 1 : -1;
      s << "<path d=\"M" << x << " " << y - d * 1.3 * r << "L" << x + 1.2 * r << " " << y + d * r << "L" << x - 1.2 * r
        << " " << y + d * r << "Z\" " << paint << "/>";
      break;
    }
    case 5:
      s << "<path d=\"M" << x - r << " " << y << "H" << x + r << "M" << x << " " << y - r << "V" << y + r << "\" "
        << line << "/>";
      break;
    case 6:
      s << "<path d=\"M" << x - r << " " << y - r << "L" << x + r << " " << y + r << "M" << x - r << " " << y + r << "L"
        << x + r << " " << y - r << "\" " << line << "/>";
      break;
    default:
      s << "<rect x=\"" << x - 1.5 * r << "\" y=\"" << y - 0.6 * r << "\" width=\"" << 3 * r << "\" height=\""
        << 1.2 * r << "\" " << paint << "/>";
  }
  return s.str();
}

/// Time (x) against error (y), one colour per series (PlotFrame); `markers` names the marker shapes the points
/// use (a legend below the series'), or is empty when every point is a circle.
std::string svg_plot(const std::vector<PlotSeries>& series, const std::vector<std::string>& markers,
                     const std::string& x_label) {
  const char* colours[] = {"#d73027", "#4575b4", "#1a9850", "#984ea3", "#ff7f00", "#a65628", "#f781bf", "#666666"};
  PlotFrame f;
  f.rows = std::max<std::size_t>(1, series.size());
  double tmin = std::numeric_limits<double>::infinity(), tmax = -tmin;
  for (const auto& ser : series)
    for (const auto& p : ser.points)
      if (p.seconds > 0) tmin = std::min(tmin, p.seconds), tmax = std::max(tmax, p.seconds);
  if (!(tmin < tmax)) tmin = 1e-6, tmax = 1;
  f.x0 = std::floor(std::log10(tmin));
  f.x1 = std::ceil(std::log10(tmax));
  const double H = f.height();
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << f.W << "\" height=\"" << H << "\" viewBox=\"0 0 " << f.W
    << " " << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  draw_axes(s, f, x_label);
  for (std::size_t k = 0; k < series.size(); ++k) {
    const char* c = colours[k % 8];
    const PlotSeries& ser = series[k];
    const auto at = place(f, ser, k);
    if (ser.connect && at.size() > 1) {
      s << "<polyline fill=\"none\" stroke=\"" << c << "\" stroke-opacity=\"0.5\" points=\"";
      for (const auto& [x, y] : at) s << x << "," << y << " ";
      s << "\"/>\n";
    }
    long wrong = 0, zero = 0;
    for (std::size_t i = 0; i < at.size(); ++i) {
      const PlotPoint& p = ser.points[i];
      wrong += p.error >= 1;
      zero += p.error <= 0;
      s << marker_svg(p.marker, at[i].first, at[i].second, c, 0.6) << "\n";
    }
    // The count of each strip row, right of the plot.
    for (const auto& [n, e] : {std::pair{wrong, 1.0}, std::pair{zero, 0.0}})
      s << "<text x=\"" << f.W - f.right + 6 << "\" y=\"" << f.Y(e, k) + 4 << "\" font-size=\"11\" fill=\"" << c
        << "\">" << n << "</text>\n";
    s << "<circle cx=\"" << f.W - f.right + 15 << "\" cy=\"" << f.log_top() + 10 + 18 * k << "\" r=\"4\" fill=\"" << c
      << "\"/><text x=\"" << f.W - f.right + 24 << "\" y=\"" << f.log_top() + 14 + 18 * k << "\">"
      << html_escape(ser.name) << "</text>\n";
  }
  for (std::size_t m = 0; m < markers.size(); ++m) {
    const double y = f.log_top() + 18 * (series.size() + 1.5 + m);
    s << marker_svg(static_cast<int>(m), f.W - f.right + 15, y - 4, "#555", 0.9) << "<text x=\"" << f.W - f.right + 24
      << "\" y=\"" << y << "\">" << html_escape(markers[m]) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace

std::string bench_svg(const BenchRun& run) {
  std::vector<PlotSeries> series;
  for (std::size_t k = 0; k < run.rungs.size(); ++k) {
    PlotSeries ser{run.rungs[k].name, {}, false};
    for (const auto& r : run.instances)
      ser.points.push_back({r.rungs[k].median_seconds, bench::worst_error(r.rungs[k].errors), 0});
    series.push_back(std::move(ser));
  }
  return svg_plot(series, {}, "time per instance (s, median of repeats)");
}

std::string ladder_svg(const BenchRun& run) {
  std::vector<PlotSeries> series;
  for (bench::Family f : families_in(run)) {
    PlotSeries ser{bench::family_name(f), {}, true};
    for (std::size_t k = 0; k < run.rungs.size(); ++k) {
      const LadderCell c = ladder_cell(run, f, k);
      // A wrong or undecided answer anywhere in the family puts its rung on the "1 (wrong)" line.
      const double e = c.wrong + c.undecided > 0 ? 1.0 : (std::isnan(c.worst) ? 0.0 : c.worst);
      ser.points.push_back({c.median_seconds, e, static_cast<int>(k)});
    }
    series.push_back(std::move(ser));
  }
  std::vector<std::string> rungs;
  for (const auto& r : run.rungs) rungs.push_back(r.name);
  return svg_plot(series, rungs, "median time per instance of the family (s)");
}

}  // namespace contactcert::queries
