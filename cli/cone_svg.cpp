#include "cli/cone_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "cli/html_report.h"
#include "solvers/wrench_cone/line_of_force.h"

namespace contactcert::cli {
namespace {

struct P2 {
  double x, y;
};

P2 approx(const geometry::Point2& p) { return {p.x.get_d(), p.y.get_d()}; }

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

/// Maps scene coordinates (y up) to picture coordinates (y down).
struct View {
  double xmin, ymax, scale, margin;
  std::string x(double v) const { return num(margin + (v - xmin) * scale); }
  std::string y(double v) const { return num(margin + (ymax - v) * scale); }
};

P2 unit(P2 v) {
  const double l = std::hypot(v.x, v.y);
  return l > 0 ? P2{v.x / l, v.y / l} : P2{0, 0};
}

}  // namespace

std::string wrench_cone_svg(const geometry::PlanarScene& scene, const exact::Mat<exact::Q>& rays,
                            const exact::Mat<exact::Q>& lines, const std::string& title,
                            const std::vector<BoundaryMark>& marks) {
  // Fixel positions: given, or the contact point moved back along the normal by the gap.
  std::vector<P2> fixel_at;
  for (const auto& f : scene.fixels) {
    if (f.position) {
      fixel_at.push_back(approx(*f.position));
    } else {
      const P2 p = approx(f.frame.point), n = unit(approx(f.frame.normal));
      const double gap = std::sqrt(f.frame.gap_squared.get_d());
      fixel_at.push_back({p.x - gap * n.x, p.y - gap * n.y});
    }
  }
  std::vector<P2> pts = fixel_at;
  const P2 com = approx(scene.workpiece.com);
  if (const auto* d = std::get_if<geometry::DiskShape>(&scene.workpiece.shape)) {
    const P2 c = approx(d->center);
    const double r = d->radius.get_d();
    pts.push_back({c.x - r, c.y - r});
    pts.push_back({c.x + r, c.y + r});
  } else {
    for (const auto& v : std::get<geometry::PolygonShape>(scene.workpiece.shape).vertices) pts.push_back(approx(v));
  }
  double xmin = pts[0].x, xmax = pts[0].x, ymin = pts[0].y, ymax = pts[0].y;
  for (const P2& p : pts) {
    xmin = std::min(xmin, p.x);
    xmax = std::max(xmax, p.x);
    ymin = std::min(ymin, p.y);
    ymax = std::max(ymax, p.y);
  }
  const double size = std::max({xmax - xmin, ymax - ymin, 1e-9});
  xmin -= 0.35 * size;
  xmax += 0.35 * size;
  ymin -= 0.35 * size;
  ymax += 0.35 * size;
  const double extent = std::max(xmax - xmin, ymax - ymin);
  const View v{xmin, ymax, 480.0 / extent, 10};
  const double width = 20 + (xmax - xmin) * v.scale, height = 40 + (ymax - ymin) * v.scale;

  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
    << "\" viewBox=\"0 0 " << num(width) << " " << num(height) << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  s << "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" "
       "orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#c0392b\"/></marker></defs>\n";
  s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  // Workpiece and centre of mass.
  if (const auto* d = std::get_if<geometry::DiskShape>(&scene.workpiece.shape)) {
    const P2 c = approx(d->center);
    s << "<circle cx=\"" << v.x(c.x) << "\" cy=\"" << v.y(c.y) << "\" r=\"" << num(d->radius.get_d() * v.scale)
      << "\" fill=\"#dddddd\" stroke=\"black\"/>\n";
  } else {
    s << "<polygon points=\"";
    for (const auto& p : std::get<geometry::PolygonShape>(scene.workpiece.shape).vertices)
      s << v.x(p.x.get_d()) << "," << v.y(p.y.get_d()) << " ";
    s << "\" fill=\"#dddddd\" stroke=\"black\"/>\n";
  }
  for (const auto& m : marks) {
    if (m.points.size() == 1) {
      s << "<circle cx=\"" << v.x(m.points[0].first) << "\" cy=\"" << v.y(m.points[0].second) << "\" r=\"4\" fill=\""
        << m.colour << "\"/>\n";
      continue;
    }
    s << "<polyline fill=\"none\" stroke=\"" << m.colour << "\" stroke-width=\"5\" stroke-linecap=\"round\" points=\"";
    for (const auto& [x, y] : m.points) s << v.x(x) << "," << v.y(y) << " ";
    s << "\"/>\n";
  }
  s << "<path d=\"M" << num(std::stod(v.x(com.x)) - 5) << "," << v.y(com.y) << " h10 M" << v.x(com.x) << ","
    << num(std::stod(v.y(com.y)) - 5) << " v10\" stroke=\"black\"/>\n";
  // Fixels and their friction cones (edges n +- mu_s t through the contact point).
  const double cone_len = 0.25 * size;
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const auto& f = scene.fixels[i];
    const P2 p = approx(f.frame.point), n = unit(approx(f.frame.normal)), t{-n.y, n.x};
    const double mu = f.mu_s.get_d();
    if (f.frame.touching()) {
      for (double sgn_t : {-1.0, 1.0}) {
        const P2 e = unit({n.x + sgn_t * mu * t.x, n.y + sgn_t * mu * t.y});
        s << "<line x1=\"" << v.x(p.x - cone_len * e.x) << "\" y1=\"" << v.y(p.y - cone_len * e.y) << "\" x2=\""
          << v.x(p.x + cone_len * e.x) << "\" y2=\"" << v.y(p.y + cone_len * e.y)
          << "\" stroke=\"#2471a3\" stroke-dasharray=\"4 3\"/>\n";
      }
    }
    const P2 q = fixel_at[i];
    s << "<circle cx=\"" << v.x(q.x) << "\" cy=\"" << v.y(q.y) << "\" r=\"4\" stroke=\"black\" fill=\""
      << (f.frame.touching() ? "black" : "white") << "\"/>\n";
    s << "<text x=\"" << num(std::stod(v.x(q.x)) + 6) << "\" y=\"" << num(std::stod(v.y(q.y)) + 14) << "\">" << i
      << "</text>\n";
  }
  // Generators as directed lines of force.
  std::vector<std::pair<exact::Vec<exact::Q>, std::string>> gens;
  for (Eigen::Index r = 0; r < rays.rows(); ++r)
    gens.push_back({rays.row(r).transpose(), std::string("g") + std::to_string(r + 1)});
  for (Eigen::Index r = 0; r < lines.rows(); ++r) {
    gens.push_back({lines.row(r).transpose(), std::string("+l") + std::to_string(r + 1)});
    gens.push_back({exact::Vec<exact::Q>(-lines.row(r).transpose()), std::string("-l") + std::to_string(r + 1)});
  }
  const double half = 0.45 * size;
  int moments = 0;
  for (const auto& [g, label] : gens) {
    const solvers::LineOfForce l = solvers::line_of_force(g, scene.workpiece.com);
    if (l.kind == solvers::LineOfForce::Kind::kForce) {
      const P2 a = approx(l.through), d = unit(approx(l.direction));
      s << "<line x1=\"" << v.x(a.x - half * d.x) << "\" y1=\"" << v.y(a.y - half * d.y) << "\" x2=\""
        << v.x(a.x + half * d.x) << "\" y2=\"" << v.y(a.y + half * d.y)
        << "\" stroke=\"#c0392b\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\"/>\n";
      s << "<text x=\"" << v.x(a.x + half * d.x) << "\" y=\"" << num(std::stod(v.y(a.y + half * d.y)) - 6)
        << "\" fill=\"#c0392b\">" << label << "</text>\n";
    } else if (l.kind == solvers::LineOfForce::Kind::kPureMoment) {
      // An arc of 270 degrees about the com, counter-clockwise for a positive torque.
      const double r = (0.12 + 0.05 * moments++) * size;
      const bool ccw = sgn(l.torque) > 0;
      const P2 start{com.x + r, com.y}, end{com.x, com.y + (ccw ? -r : r)};
      s << "<path d=\"M" << v.x(start.x) << "," << v.y(start.y) << " A" << num(r * v.scale) << "," << num(r * v.scale)
        << " 0 1 " << (ccw ? 0 : 1) << " " << v.x(end.x) << "," << v.y(end.y)
        << "\" fill=\"none\" stroke=\"#c0392b\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\"/>\n";
      s << "<text x=\"" << v.x(start.x + 0.02 * size) << "\" y=\"" << v.y(start.y) << "\" fill=\"#c0392b\">" << label
        << "</text>\n";
    }
  }
  s << "<text x=\"10\" y=\"" << num(height - 10) << "\">" << html_escape(title) << "</text>\n";
  s << "</svg>\n";
  return s.str();
}

}  // namespace contactcert::cli
