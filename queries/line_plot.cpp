#include "queries/line_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "queries/html_report.h"

namespace contactcert::queries {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string tick(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// A round step (1, 2 or 5 times a power of ten) giving about 5 ticks up to `top`.
double step_for(double top) {
  const double raw = top / 5, p = std::pow(10, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

}  // namespace

std::string line_plot_svg(const std::vector<LineSeries>& series, const std::string& title, const std::string& x_label,
                          const std::string& y_label) {
  constexpr double W = 460, H = 300, left = 60, right = 20, top = 30, bottom = 80;
  const char* colours[] = {"#1b7837", "#2471a3", "#c0392b", "#984ea3"};
  double xmax = 0, ymax = 0;
  for (const auto& s : series)
    for (const auto& [x, y] : s.points) xmax = std::max(xmax, x), ymax = std::max(ymax, y);
  if (!(xmax > 0)) xmax = 1;
  if (!(ymax > 0)) ymax = 1;
  const double xs = step_for(xmax), ys = step_for(ymax);
  xmax = std::ceil(xmax / xs) * xs;
  ymax = std::ceil(ymax / ys) * ys;
  const auto X = [&](double x) { return left + x / xmax * (W - left - right); };
  const auto Y = [&](double y) { return H - bottom - y / ymax * (H - top - bottom); };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
    << " " << H << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" "
    << "fill=\"white\"/>\n<text x=\"" << left << "\" y=\"18\" font-size=\"13\">" << html_escape(title) << "</text>\n";
  for (double x = 0; x <= xmax + xs / 2; x += xs)
    s << "<line x1=\"" << num(X(x)) << "\" y1=\"" << num(Y(0)) << "\" x2=\"" << num(X(x)) << "\" y2=\"" << num(Y(ymax))
      << "\" stroke=\"#e4e4e4\"/><text x=\"" << num(X(x)) << "\" y=\"" << num(Y(0) + 15) << "\" text-anchor=\"middle\">"
      << tick(x) << "</text>\n";
  for (double y = 0; y <= ymax + ys / 2; y += ys)
    s << "<line x1=\"" << num(X(0)) << "\" y1=\"" << num(Y(y)) << "\" x2=\"" << num(X(xmax)) << "\" y2=\"" << num(Y(y))
      << "\" stroke=\"#e4e4e4\"/><text x=\"" << num(X(0) - 6) << "\" y=\"" << num(Y(y) + 4) << "\" text-anchor=\"end\">"
      << tick(y) << "</text>\n";
  s << "<path d=\"M" << num(X(0)) << "," << num(Y(ymax)) << " V" << num(Y(0)) << " H" << num(X(xmax))
    << "\" fill=\"none\" stroke=\"#333\"/>\n<text x=\"" << num((X(0) + X(xmax)) / 2) << "\" y=\"" << num(Y(0) + 32)
    << "\" text-anchor=\"middle\" font-size=\"12\">" << html_escape(x_label)
    << "</text>\n<text transform=\"translate(16," << num((Y(0) + Y(ymax)) / 2)
    << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">" << html_escape(y_label) << "</text>\n";
  for (std::size_t k = 0; k < series.size(); ++k) {
    const char* c = colours[k % 4];
    s << "<polyline fill=\"none\" stroke=\"" << c << "\" stroke-width=\"2\" points=\"";
    for (const auto& [x, y] : series[k].points) s << num(X(x)) << "," << num(Y(y)) << " ";
    s << "\"/>\n";
    for (const auto& [x, y] : series[k].points)
      s << "<circle cx=\"" << num(X(x)) << "\" cy=\"" << num(Y(y)) << "\" r=\"3.5\" fill=\"" << c << "\"/>\n";
    const double ly = H - bottom + 50 + 14 * static_cast<double>(k);
    s << "<line x1=\"" << left << "\" y1=\"" << num(ly - 4) << "\" x2=\"" << left + 22 << "\" y2=\"" << num(ly - 4)
      << "\" stroke=\"" << c << "\" stroke-width=\"2\"/><text x=\"" << left + 28 << "\" y=\"" << num(ly) << "\">"
      << html_escape(series[k].name) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace contactcert::queries
