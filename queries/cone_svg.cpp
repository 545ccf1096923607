#include "queries/cone_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "queries/html_report.h"
#include "solvers/wrench_cone/line_of_force.h"

namespace contactcert::queries {
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

P2 unit(P2 v) {
  const double l = std::hypot(v.x, v.y);
  return l > 0 ? P2{v.x / l, v.y / l} : P2{0, 0};
}

/// An axis-aligned box in picture coordinates.
struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(double x, double y) {
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  }
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

constexpr double kFont = 12, kCharWidth = 7.2;  // sans-serif 12 px: a generous width per character

/// The drawing in picture coordinates (y down), its bounding box and the boxes of the labels placed so far.
class Canvas {
 public:
  Canvas(double xmin, double ymax, double scale) : xmin_(xmin), ymax_(ymax), scale_(scale) {}
  P2 px(P2 p) const { return {(p.x - xmin_) * scale_, (ymax_ - p.y) * scale_}; }
  double scale() const { return scale_; }
  std::ostringstream& out() { return s_; }
  void cover(P2 q, double r = 0) {
    box_.add(q.x - r, q.y - r);
    box_.add(q.x + r, q.y + r);
  }
  const Box& box() const { return box_; }
  /// A label near picture point `at`: the first of the candidate offsets whose box overlaps no label placed so
  /// far (else the first), so labels never overlap where there is room; the box is added to the drawing's.
  void label(P2 at, const std::string& text, const std::string& colour, const std::vector<P2>& offsets) {
    const double w = kCharWidth * static_cast<double>(text.size()), h = kFont;
    Box chosen;
    bool found = false;
    for (const P2& o : offsets) {
      Box b;
      b.add(at.x + o.x, at.y + o.y - h);
      b.add(at.x + o.x + w, at.y + o.y + 2);
      if (std::none_of(labels_.begin(), labels_.end(), [&](const Box& l) { return l.overlaps(b); })) {
        chosen = b;
        found = true;
        break;
      }
    }
    if (!found) {
      chosen.add(at.x + offsets[0].x, at.y + offsets[0].y - h);
      chosen.add(at.x + offsets[0].x + w, at.y + offsets[0].y + 2);
    }
    labels_.push_back(chosen);
    box_.add(chosen.x0, chosen.y0);
    box_.add(chosen.x1, chosen.y1);
    s_ << "<text x=\"" << num(chosen.x0) << "\" y=\"" << num(chosen.y1 - 2) << "\" fill=\"" << colour
       << "\" paint-order=\"stroke\" stroke=\"white\" stroke-width=\"3\">" << html_escape(text) << "</text>\n";
  }

 private:
  double xmin_, ymax_, scale_;
  Box box_;
  std::vector<Box> labels_;
  std::ostringstream s_;
};

/// Candidate label offsets around a point, nearest first.
std::vector<P2> around(double d) {
  return {{d, -d},
          {d, d + kFont},
          {-d - 3 * kCharWidth, -d},
          {-d - 3 * kCharWidth, d + kFont},
          {d, 2 * kFont},
          {d, -2 * kFont},
          {-d - 3 * kCharWidth, 2 * kFont},
          {2 * d, -3 * kFont},
          {2 * d, 3 * kFont},
          {-4 * kCharWidth, -3 * kFont}};
}

const char* kForce = "#c0392b";
const char* kCone = "#2471a3";

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
  Canvas cv(xmin, ymax, 320.0 / size);
  auto& s = cv.out();
  auto X = [&](P2 p) { return num(cv.px(p).x); };
  auto Y = [&](P2 p) { return num(cv.px(p).y); };
  // Workpiece and centre of mass.
  if (const auto* d = std::get_if<geometry::DiskShape>(&scene.workpiece.shape)) {
    const P2 c = approx(d->center);
    const double r = d->radius.get_d();
    s << "<circle cx=\"" << X(c) << "\" cy=\"" << Y(c) << "\" r=\"" << num(r * cv.scale())
      << "\" fill=\"#dddddd\" stroke=\"black\"/>\n";
    cv.cover(cv.px(c), r * cv.scale());
  } else {
    s << "<polygon points=\"";
    for (const auto& v : std::get<geometry::PolygonShape>(scene.workpiece.shape).vertices) {
      s << X(approx(v)) << "," << Y(approx(v)) << " ";
      cv.cover(cv.px(approx(v)));
    }
    s << "\" fill=\"#dddddd\" stroke=\"black\"/>\n";
  }
  for (const auto& m : marks) {
    if (m.points.size() == 1) {
      const P2 q{m.points[0].first, m.points[0].second};
      s << "<circle cx=\"" << X(q) << "\" cy=\"" << Y(q) << "\" r=\"4\" fill=\"" << m.style.colour << "\"/>\n";
      continue;
    }
    s << "<polyline fill=\"none\" stroke=\"" << m.style.colour
      << "\" stroke-width=\"5\" stroke-linecap=\"round\" points=\"";
    for (const auto& [x, y] : m.points) s << X({x, y}) << "," << Y({x, y}) << " ";
    s << "\"/>\n";
  }
  const P2 c = cv.px(com);
  s << "<path d=\"M" << num(c.x - 5) << "," << num(c.y) << " h10 M" << num(c.x) << "," << num(c.y - 5)
    << " v10\" stroke=\"black\"/>\n";
  // Fixels and their friction cones (edges n +- mu_s t through the contact point).
  const double cone_len = 0.22 * size;
  bool any_touching = false, any_gap = false;
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const auto& f = scene.fixels[i];
    const P2 p = approx(f.frame.point), n = unit(approx(f.frame.normal)), t{-n.y, n.x};
    const double mu = f.mu_s.get_d();
    if (f.frame.touching()) {
      for (double sgn_t : {-1.0, 1.0}) {
        const P2 e = unit({n.x + sgn_t * mu * t.x, n.y + sgn_t * mu * t.y});
        const P2 a{p.x - cone_len * e.x, p.y - cone_len * e.y}, b{p.x + cone_len * e.x, p.y + cone_len * e.y};
        s << "<line x1=\"" << X(a) << "\" y1=\"" << Y(a) << "\" x2=\"" << X(b) << "\" y2=\"" << Y(b) << "\" stroke=\""
          << kCone << "\" stroke-dasharray=\"4 3\"/>\n";
        cv.cover(cv.px(a));
        cv.cover(cv.px(b));
      }
    }
    (f.frame.touching() ? any_touching : any_gap) = true;
    const P2 q = cv.px(fixel_at[i]);
    s << "<circle cx=\"" << num(q.x) << "\" cy=\"" << num(q.y) << "\" r=\"4\" stroke=\"black\" fill=\""
      << (f.frame.touching() ? "black" : "white") << "\"/>\n";
    cv.cover(q, 5);
    // Label on the side away from the workpiece (opposite to the inward normal) where there is room.
    const P2 out{-n.x * 12, n.y * 12};
    cv.label(q, std::to_string(i), "black",
             {{out.x - 3, out.y + 4}, {out.x + 6, out.y + 12}, {out.x - 12, out.y - 4}, {6, 14}, {-14, 14}, {6, -6}});
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
  bool any_force = false, any_moment = false;
  for (const auto& [g, label] : gens) {
    const solvers::LineOfForce l = solvers::line_of_force(g, scene.workpiece.com);
    if (l.kind == solvers::LineOfForce::Kind::kForce) {
      any_force = true;
      const P2 a = approx(l.through), d = unit(approx(l.direction));
      // The arrow's tip moves on past a fixel's dot it would end on (the dot would hide the arrowhead).
      double ahead = half;
      for (const P2& f : fixel_at)
        if (std::hypot(a.x + ahead * d.x - f.x, a.y + ahead * d.y - f.y) * cv.scale() < 14) ahead += 0.15 * size;
      const P2 from = cv.px({a.x - half * d.x, a.y - half * d.y}), to = cv.px({a.x + ahead * d.x, a.y + ahead * d.y});
      s << "<line x1=\"" << num(from.x) << "\" y1=\"" << num(from.y) << "\" x2=\"" << num(to.x) << "\" y2=\""
        << num(to.y) << "\" stroke=\"" << kForce << "\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\"/>\n";
      cv.cover(from);
      cv.cover(to);
      // Candidates at the tip first, then along the line back toward the tail.
      std::vector<P2> offsets = around(6);
      for (double f : {0.8, 0.6, 0.4})
        for (const P2& o : {P2{6, -6}, P2{-6 - 3 * kCharWidth, -6}, P2{6, 16}})
          offsets.push_back({(from.x - to.x) * (1 - f) + o.x, (from.y - to.y) * (1 - f) + o.y});
      cv.label(to, label, kForce, offsets);
    } else if (l.kind == solvers::LineOfForce::Kind::kPureMoment) {
      any_moment = true;
      // An arc of 270 degrees about the com, counter-clockwise for a positive torque.
      const double r = (0.12 + 0.05 * moments++) * size;
      const bool ccw = sgn(l.torque) > 0;
      const P2 start{com.x + r, com.y}, end{com.x, com.y + (ccw ? -r : r)};
      s << "<path d=\"M" << X(start) << "," << Y(start) << " A" << num(r * cv.scale()) << "," << num(r * cv.scale())
        << " 0 1 " << (ccw ? 0 : 1) << " " << X(end) << "," << Y(end) << "\" fill=\"none\" stroke=\"" << kForce
        << "\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\"/>\n";
      cv.cover(cv.px(com), r * cv.scale());
      cv.label(cv.px(start), label, kForce, around(4));
    }
  }
  // Title above, legend below the drawing; the canvas fits them all with a small margin.
  struct Entry {
    std::string svg, text;
  };
  std::vector<Entry> legend;
  if (any_force)
    legend.push_back({"<line x1=\"0\" y1=\"-4\" x2=\"22\" y2=\"-4\" stroke=\"" + std::string(kForce) +
                          "\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\"/>",
                      "generator g_k of the cone as a directed line of force"});
  if (any_moment)
    legend.push_back({"<path d=\"M2,0 A7,7 0 1 0 14,-6\" fill=\"none\" stroke=\"" + std::string(kForce) +
                          "\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\"/>",
                      "pure moment about the centre of mass"});
  if (any_touching)
    legend.push_back({"<line x1=\"0\" y1=\"-4\" x2=\"22\" y2=\"-4\" stroke=\"" + std::string(kCone) +
                          "\" stroke-dasharray=\"4 3\"/>",
                      "friction cone edges n +- mu_s t at a contact"});
  if (any_touching)
    legend.push_back(
        {"<circle cx=\"11\" cy=\"-4\" r=\"4\" fill=\"black\" stroke=\"black\"/>", "fixel touching (gap 0)"});
  if (any_gap)
    legend.push_back({"<circle cx=\"11\" cy=\"-4\" r=\"4\" fill=\"white\" stroke=\"black\"/>", "fixel not touching"});
  legend.push_back({"<path d=\"M6,-4 h10 M11,-9 v10\" stroke=\"black\"/>", "centre of mass; fixels numbered from 0"});
  std::vector<std::string> explained;
  for (const auto& mark : marks) {
    if (mark.style.meaning.empty() ||
        std::find(explained.begin(), explained.end(), mark.style.meaning) != explained.end())
      continue;
    explained.push_back(mark.style.meaning);
    legend.push_back({"<line x1=\"2\" y1=\"-4\" x2=\"20\" y2=\"-4\" stroke=\"" + mark.style.colour +
                          "\" stroke-width=\"5\" stroke-linecap=\"round\"/>",
                      mark.style.meaning});
  }
  const double m = 8, title_h = 20, line_h = 16;
  double legend_w = 0;
  for (const auto& e : legend) legend_w = std::max(legend_w, 30 + 6.3 * static_cast<double>(e.text.size()));
  const double title_w = 7.0 * static_cast<double>(title.size());
  const Box& b = cv.box();
  const double width = std::max({b.x1 - b.x0, legend_w, title_w}) + 2 * m;
  const double legend_top = title_h + (b.y1 - b.y0) + 2 * m;
  const double height = legend_top + line_h * static_cast<double>(legend.size()) + m;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
      << "\" viewBox=\"0 0 " << num(width) << " " << num(height) << "\" font-family=\"sans-serif\" font-size=\""
      << kFont << "\">\n";
  svg << "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" "
         "orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\""
      << kForce << "\"/></marker></defs>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << m << "\" y=\"" << title_h - 4 << "\" font-size=\"13\">" << html_escape(title) << "</text>\n";
  svg << "<g transform=\"translate(" << num(m + (width - 2 * m - (b.x1 - b.x0)) / 2 - b.x0) << ","
      << num(title_h + m - b.y0) << ")\">\n"
      << s.str() << "</g>\n";
  for (std::size_t k = 0; k < legend.size(); ++k)
    svg << "<g transform=\"translate(" << m << "," << num(legend_top + line_h * static_cast<double>(k) + 4) << ")\">"
        << legend[k].svg << "<text x=\"30\" y=\"0\" font-size=\"11\">" << html_escape(legend[k].text)
        << "</text></g>\n";
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace contactcert::queries
