// The plots of `contactcert bench`: time against error on log scales, per instance and per family (the
// precision ladder).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "cli/bench_aggregate.h"
#include "cli/html_report.h"

namespace contactcert::cli {

namespace {

using namespace bench_report;

/// One point of a plot: time (s), error against exact, an optional label drawn beside it.
struct PlotPoint {
  double seconds = 0, error = 0;
  std::string label;
};
struct PlotSeries {
  std::string name;
  std::vector<PlotPoint> points;
  bool connect = false;  ///< a line through the points, in order
};

/// Time (x) against error (y), log scales, one colour per series; an error of exactly 0 sits on the bottom line.
std::string svg_plot(const std::vector<PlotSeries>& series, const std::string& x_label) {
  constexpr double W = 640, H = 420, left = 70, right = 130, top = 20, bottom = 50;
  constexpr double y_floor = -18;  // log10 of the error drawn for an exact 0
  const char* colours[] = {"#d73027", "#4575b4", "#1a9850", "#984ea3", "#ff7f00", "#a65628", "#f781bf", "#666666"};
  double tmin = std::numeric_limits<double>::infinity(), tmax = -tmin;
  for (const auto& ser : series)
    for (const auto& p : ser.points)
      if (p.seconds > 0) tmin = std::min(tmin, p.seconds), tmax = std::max(tmax, p.seconds);
  if (!(tmin < tmax)) tmin = 1e-6, tmax = 1;
  const double x0 = std::floor(std::log10(tmin)), x1 = std::ceil(std::log10(tmax));
  const auto X = [&](double t) { return left + (std::max(std::log10(t), x0) - x0) / (x1 - x0) * (W - left - right); };
  const auto Y = [&](double e) {
    const double l = e > 0 ? std::max(std::log10(e), y_floor + 1) : y_floor;
    return top + (0 - l) / (0 - y_floor) * (H - top - bottom);
  };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
    << " " << H
    << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (double d = x0; d <= x1; ++d)
    s << "<line x1=\"" << X(std::pow(10, d)) << "\" y1=\"" << top << "\" x2=\"" << X(std::pow(10, d)) << "\" y2=\""
      << H - bottom << "\" stroke=\"#ddd\"/><text x=\"" << X(std::pow(10, d)) << "\" y=\"" << H - bottom + 15
      << "\" text-anchor=\"middle\">1e" << d << "</text>\n";
  for (double d = 0; d >= y_floor; d -= 3) {
    const double y = d == y_floor ? Y(0) : Y(std::pow(10, d));
    s << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << W - right << "\" y2=\"" << y
      << "\" stroke=\"#ddd\"/><text x=\"" << left - 5 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">"
      << (d == y_floor ? std::string("0")
          : d == 0     ? std::string("1 (wrong)")
                       : "1e" + std::to_string(int(d)))
      << "</text>\n";
  }
  s << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 12 << "\" text-anchor=\"middle\">"
    << html_escape(x_label) << "</text>\n<text transform=\"translate(14," << (top + H - bottom) / 2
    << ") rotate(-90)\" text-anchor=\"middle\">error against exact</text>\n";
  for (std::size_t k = 0; k < series.size(); ++k) {
    const char* c = colours[k % 8];
    const PlotSeries& ser = series[k];
    if (ser.connect && ser.points.size() > 1) {
      s << "<polyline fill=\"none\" stroke=\"" << c << "\" stroke-opacity=\"0.5\" points=\"";
      for (const auto& p : ser.points) s << X(p.seconds) << "," << Y(p.error) << " ";
      s << "\"/>\n";
    }
    for (const auto& p : ser.points) {
      s << "<circle cx=\"" << X(p.seconds) << "\" cy=\"" << Y(p.error) << "\" r=\"3\" fill=\"" << c
        << "\" fill-opacity=\"0.55\"/>\n";
      if (!p.label.empty())
        s << "<text x=\"" << X(p.seconds) + 4 << "\" y=\"" << Y(p.error) - 4 << "\" font-size=\"10\" fill=\"" << c
          << "\" paint-order=\"stroke\" stroke=\"white\" stroke-width=\"3\">" << html_escape(p.label) << "</text>\n";
    }
    s << "<circle cx=\"" << W - right + 15 << "\" cy=\"" << top + 10 + 18 * k << "\" r=\"4\" fill=\"" << c
      << "\"/><text x=\"" << W - right + 24 << "\" y=\"" << top + 14 + 18 * k << "\">" << html_escape(ser.name)
      << "</text>\n";
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
      ser.points.push_back({r.rungs[k].median_seconds, bench::worst_error(r.rungs[k].errors), {}});
    series.push_back(std::move(ser));
  }
  return svg_plot(series, "time per instance (s, median of repeats)");
}

std::string ladder_svg(const BenchRun& run) {
  std::vector<PlotSeries> series;
  for (bench::Family f : families_in(run)) {
    PlotSeries ser{bench::family_name(f), {}, true};
    for (std::size_t k = 0; k < run.rungs.size(); ++k) {
      const LadderCell c = ladder_cell(run, f, k);
      // A wrong or undecided answer anywhere in the family puts its rung on the "1 (wrong)" line.
      const double e = c.wrong + c.undecided > 0 ? 1.0 : (std::isnan(c.worst) ? 0.0 : c.worst);
      ser.points.push_back({c.median_seconds, e, run.rungs[k].name});
    }
    series.push_back(std::move(ser));
  }
  return svg_plot(series, "median time per instance of the family (s)");
}

}  // namespace contactcert::cli
