#include "queries/design_svg.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace contactcert::queries {
namespace {

struct Bounds {
  double x0, y0, x1, y1;
};

Bounds bounds(const geometry::Shape& shape) {
  if (const auto* d = std::get_if<geometry::DiskShape>(&shape)) {
    const double cx = d->center.x.get_d(), cy = d->center.y.get_d(), r = d->radius.get_d();
    return {cx - r, cy - r, cx + r, cy + r};
  }
  Bounds b{1e300, 1e300, -1e300, -1e300};
  for (const auto& v : std::get<geometry::PolygonShape>(shape).vertices) {
    b.x0 = std::min(b.x0, v.x.get_d()), b.x1 = std::max(b.x1, v.x.get_d());
    b.y0 = std::min(b.y0, v.y.get_d()), b.y1 = std::max(b.y1, v.y.get_d());
  }
  return b;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

}  // namespace

std::string design_svg(const solvers::DesignProblem& problem, const std::vector<solvers::Ranked>& best,
                       const std::vector<std::string>& captions, const std::string& title) {
  constexpr double kPanel = 260, kCaption = 34, kTop = 30, kLegend = 52;
  const int columns = static_cast<int>(std::min<std::size_t>(3, std::max<std::size_t>(1, best.size())));
  const int rows = static_cast<int>((std::max<std::size_t>(1, best.size()) + columns - 1) / columns);
  // Wide enough for the title (sans-serif 14 px: at most ~7.8 px a character) and the legend.
  const double width = std::max({columns * kPanel, 16 + 7.8 * static_cast<double>(title.size()), 430.0});
  const double legend_top = kTop + rows * (kPanel + kCaption);
  const Bounds b = bounds(problem.workpiece.shape);
  const double extent = std::max(b.x1 - b.x0, b.y1 - b.y0);
  const double scale = (kPanel - 60) / (extent > 0 ? extent : 1);
  const double fixel_r = 7;
  std::ostringstream s;
  s.precision(5);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << legend_top + kLegend
    << "\" font-family=\"sans-serif\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"8\" y=\"20\" font-size=\"14\">" << escape(title) << "</text>\n";
  for (std::size_t p = 0; p < std::max<std::size_t>(1, best.size()); ++p) {
    const double ox = static_cast<double>(p % columns) * kPanel,
                 oy = kTop + static_cast<double>(p / columns) * (kPanel + kCaption);
    // Centred in the panel.
    const double mx = 30 + (extent - (b.x1 - b.x0)) * scale / 2, my = 30 + (extent - (b.y1 - b.y0)) * scale / 2;
    auto X = [&](const exact::Q& x) { return ox + mx + (x.get_d() - b.x0) * scale; };
    auto Y = [&](const exact::Q& y) { return oy + kPanel - my - (y.get_d() - b.y0) * scale; };
    s << "<g>\n";
    if (const auto* d = std::get_if<geometry::DiskShape>(&problem.workpiece.shape))
      s << "<circle cx=\"" << X(d->center.x) << "\" cy=\"" << Y(d->center.y) << "\" r=\"" << d->radius.get_d() * scale
        << "\" fill=\"#dde6f0\" stroke=\"#234\" stroke-width=\"1.5\"/>\n";
    else {
      s << "<polygon fill=\"#dde6f0\" stroke=\"#234\" stroke-width=\"1.5\" points=\"";
      for (const auto& v : std::get<geometry::PolygonShape>(problem.workpiece.shape).vertices)
        s << X(v.x) << "," << Y(v.y) << " ";
      s << "\"/>\n";
    }
    s << "<circle cx=\"" << X(problem.workpiece.com.x) << "\" cy=\"" << Y(problem.workpiece.com.y)
      << "\" r=\"2.5\" fill=\"#234\"/>\n";
    for (const auto& c : problem.candidates)
      s << "<circle cx=\"" << X(c.point.x) << "\" cy=\"" << Y(c.point.y) << "\" r=\"2.2\" fill=\"#777\"/>\n";
    if (p < best.size()) {
      int label = 0;  // fixels numbered from 0, as in the placement's scene file
      for (int i : best[p].placement) {
        const auto& c = problem.candidates[static_cast<std::size_t>(i)];
        const double nx = c.normal.x.get_d(), ny = c.normal.y.get_d(), nn = std::hypot(nx, ny);
        // The fixel disc sits outside the workpiece, touching it at the candidate point.
        const double px = X(c.point.x), py = Y(c.point.y), ux = nx / nn, uy = -ny / nn;
        s << "<circle cx=\"" << px - ux * fixel_r << "\" cy=\"" << py - uy * fixel_r << "\" r=\"" << fixel_r
          << "\" fill=\"#c0392b\"/>\n"
          << "<line x1=\"" << px << "\" y1=\"" << py << "\" x2=\"" << px + ux * 22 << "\" y2=\"" << py + uy * 22
          << "\" stroke=\"#c0392b\" stroke-width=\"1.5\"/>\n"
          << "<text x=\"" << px - ux * 2.6 * fixel_r - 4 << "\" y=\"" << py - uy * 2.6 * fixel_r + 4
          << "\" font-size=\"11\" fill=\"#c0392b\">" << label++ << "</text>\n";
      }
      s << "<text x=\"" << ox + 8 << "\" y=\"" << oy + kPanel + 4 << "\" font-size=\"10\">#" << p + 1 << ": "
        << escape(p < captions.size() ? captions[p] : "") << "</text>\n";
    } else {
      s << "<text x=\"" << ox + 8 << "\" y=\"" << oy + kPanel + 4
        << "\" font-size=\"11\">no placement meets the requirements</text>\n";
    }
    s << "</g>\n";
  }
  // Legend.
  const double ly = legend_top + 4;
  s << "<g font-size=\"11\">\n"
    << "<circle cx=\"15\" cy=\"" << ly + 4 << "\" r=\"6\" fill=\"#c0392b\"/><line x1=\"21\" y1=\"" << ly + 4
    << "\" x2=\"36\" y2=\"" << ly + 4 << "\" stroke=\"#c0392b\" stroke-width=\"1.5\"/><text x=\"44\" y=\"" << ly + 8
    << "\">fixel (numbered from 0) and its inward normal at the contact</text>\n"
    << "<circle cx=\"15\" cy=\"" << ly + 20 << "\" r=\"2.2\" fill=\"#777\"/><text x=\"44\" y=\"" << ly + 24
    << "\">candidate point</text>\n"
    << "<circle cx=\"15\" cy=\"" << ly + 36 << "\" r=\"2.5\" fill=\"#234\"/><text x=\"44\" y=\"" << ly + 40
    << "\">centre of mass</text>\n</g>\n";
  s << "</svg>\n";
  return s.str();
}

}  // namespace contactcert::queries
