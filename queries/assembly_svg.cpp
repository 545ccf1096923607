#include "queries/assembly_svg.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <variant>

#include "queries/html_report.h"
#include "solvers/assembly/assembly_stability.h"

namespace contactcert::queries {
namespace {

using geometry::Point2;

struct XY {
  double x, y;
};

XY to_xy(const Point2& p) { return {p.x.get_d(), p.y.get_d()}; }

std::string fixed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

/// World to picture coordinates (y up to y down) over the world window [x0, x1] x [y0, y1].
struct View {
  double x0, y1, scale;
  XY at(XY p) const { return {(p.x - x0) * scale, (y1 - p.y) * scale + kTop}; }
  static constexpr double kTop = 30;  ///< room for the title
};

/// The window: the bodies, the point parties and the contact points, with a margin (obstacles may be far larger,
/// the picture clips them).
std::array<double, 4> window(const geometry::Assembly& a) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  const auto add = [&](XY p, double r = 0) {
    x0 = std::min(x0, p.x - r), y0 = std::min(y0, p.y - r), x1 = std::max(x1, p.x + r), y1 = std::max(y1, p.y + r);
  };
  for (const geometry::Body& b : a.bodies) {
    if (const auto* poly = std::get_if<geometry::PolygonShape>(&b.shape))
      for (const Point2& v : poly->vertices) add(to_xy(v));
    else if (const auto* disk = std::get_if<geometry::DiskShape>(&b.shape))
      add(to_xy(disk->center), disk->radius.get_d());
  }
  for (const Point2& f : a.fixels) add(to_xy(f));
  for (const geometry::Finger& f : a.fingers) add(to_xy(f.position));
  for (const geometry::AssemblyContact& c : a.contacts) add(to_xy(c.point));
  const double m = 0.15 * std::max({x1 - x0, y1 - y0, 1e-9});
  return {x0 - m, y0 - m, x1 + m, y1 + m};
}

/// One shape as an SVG element with the given style.
std::string shape_svg(const geometry::Shape& s, const View& v, const std::string& style) {
  if (const auto* disk = std::get_if<geometry::DiskShape>(&s)) {
    const XY c = v.at(to_xy(disk->center));
    return "<circle cx=\"" + fixed(c.x) + "\" cy=\"" + fixed(c.y) + "\" r=\"" + fixed(disk->radius.get_d() * v.scale) +
           "\" " + style + "/>\n";
  }
  std::string points;
  for (const Point2& p : std::get<geometry::PolygonShape>(s).vertices) {
    const XY q = v.at(to_xy(p));
    if (!points.empty()) points += ' ';
    points += fixed(q.x);
    points += ',';
    points += fixed(q.y);
  }
  return "<polygon points=\"" + points + "\" " + style + "/>\n";
}

/// An arrow of `length` px from picture point p along the world direction d.
std::string arrow(XY p, XY d, double length, const char* colour, const char* marker) {
  const double l = std::hypot(d.x, d.y);
  if (l == 0) return {};
  const XY q{p.x + length * d.x / l, p.y - length * d.y / l};
  return "<line x1=\"" + fixed(p.x) + "\" y1=\"" + fixed(p.y) + "\" x2=\"" + fixed(q.x) + "\" y2=\"" + fixed(q.y) +
         "\" stroke=\"" + colour + "\" stroke-width=\"2\" marker-end=\"url(#" + marker + ")\"/>\n";
}

std::string text_at(XY p, const std::string& text, const char* colour) {
  return "<text x=\"" + fixed(p.x) + "\" y=\"" + fixed(p.y) + "\" fill=\"" + colour +
         "\" paint-order=\"stroke\" stroke=\"white\" stroke-width=\"3\">" + html_escape(text) + "</text>\n";
}

const char* const kBodyFill[] = {"#aed6f1", "#f9e79f", "#abebc6", "#f5cba7", "#d7bde2", "#a3e4d7"};
const char* const kNormal = "#2471a3";
const char* const kForce = "#c0392b";

}  // namespace

std::string assembly_svg(const geometry::Assembly& a, const std::vector<AssemblyContactForce>& forces,
                         const std::string& title) {
  const auto [x0, y0, x1, y1] = window(a);
  const double scale = 560 / std::max(x1 - x0, y1 - y0);
  const View v{x0, y1, scale};
  const double width = (x1 - x0) * scale, height = (y1 - y0) * scale + View::kTop + 24;
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fixed(width) + "\" height=\"" + fixed(height) +
                  "\" viewBox=\"0 0 " + fixed(width) + " " + fixed(height) +
                  "\" font-family=\"sans-serif\" font-size=\"12\">\n"
                  "<defs>\n";
  for (const auto& [id, colour] : {std::pair{"assembly-normal", kNormal}, std::pair{"assembly-force", kForce}})
    s += std::string("<marker id=\"") + id +
         "\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"6\" markerHeight=\"6\" orient=\"auto\">"
         "<path d=\"M0,0 L10,5 L0,10 z\" fill=\"" +
         colour + "\"/></marker>\n";
  // The drawing is a nested svg over the window, which clips it (no id, so that pictures share a page): an
  // obstacle such as a long ground stays out of the title and legend.
  const std::string window_height = fixed((y1 - y0) * scale), top = fixed(View::kTop);
  s += "</defs>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" + text_at({8, 18}, title, "black") +
       "<svg x=\"0\" y=\"" + top + "\" width=\"" + fixed(width) + "\" height=\"" + window_height + "\" viewBox=\"0 " +
       top + " " + fixed(width) + " " + window_height + "\">\n";
  for (const geometry::Shape& o : a.obstacles) s += shape_svg(o, v, "fill=\"#d5d8dc\" stroke=\"#566573\"");
  for (std::size_t b = 0; b < a.bodies.size(); ++b) {
    const geometry::Body& body = a.bodies[b];
    s += shape_svg(
        body.shape, v,
        std::string("fill=\"") + kBodyFill[b % std::size(kBodyFill)] + "\" fill-opacity=\"0.8\" stroke=\"black\"");
    const XY c = v.at(to_xy(body.com));
    s += "<circle cx=\"" + fixed(c.x) + "\" cy=\"" + fixed(c.y) + "\" r=\"3\" fill=\"black\"/>\n" +
         text_at({c.x + 5, c.y - 5}, std::string("body ") + std::to_string(b), "black");
  }
  for (const Point2& f : a.fixels) {
    const XY p = v.at(to_xy(f));
    s += "<circle cx=\"" + fixed(p.x) + "\" cy=\"" + fixed(p.y) + "\" r=\"5\" fill=\"#566573\"/>\n";
  }
  for (const geometry::Finger& f : a.fingers) {
    const XY p = v.at(to_xy(f.position));
    s += "<circle cx=\"" + fixed(p.x) + "\" cy=\"" + fixed(p.y) + "\" r=\"5\" fill=\"#7d3c98\"/>\n";
  }
  for (std::size_t i = 0; i < a.contacts.size(); ++i) {
    const XY p = v.at(to_xy(a.contacts[i].point));
    s += arrow(p, to_xy(a.contacts[i].normal), 24, kNormal, "assembly-normal") + "<circle cx=\"" + fixed(p.x) +
         "\" cy=\"" + fixed(p.y) + "\" r=\"3\" fill=\"" + kNormal + "\"/>\n";
  }
  double largest = 0;
  for (const AssemblyContactForce& f : forces)
    largest = std::max(largest, std::hypot(f.force.x.get_d(), f.force.y.get_d()));
  for (const AssemblyContactForce& f : forces) {
    const XY d = to_xy(f.force);
    const XY p = v.at(to_xy(f.point));
    s += arrow(p, d, 70 * std::hypot(d.x, d.y) / largest, kForce, "assembly-force") +
         text_at({p.x + 4, p.y + 14}, std::string("c") + std::to_string(f.contact), kForce);
  }
  s += "</svg>\n" + text_at({8, height - 8},
                            "blue: contact normals (from `from` into `to`)" +
                                std::string(forces.empty() ? "" : "; red: contact forces on `to` (to scale)"),
                            "black");
  return s + "</svg>\n";
}

std::string to_svg(const AssemblyInput& in, const AssemblyStabilityAnswer& answer) {
  const solvers::assembly::AssemblyStabilityResult& r = answer.result;
  std::string title = answer.decided() ? solvers::assembly::verdict_name(r.verdict) : "unknown";
  title += r.has_moving    ? ": a moving witness, mode " + r.moving.mode
           : r.has_resting ? ": resting contact forces"
                           : ": no resting contact forces";
  return assembly_svg(in.assembly, r.has_moving ? answer.moving : answer.resting, title);
}

std::string to_svg(const AssemblyInput& in, const AssemblyUcpAnswer& answer) {
  std::string title = "quasistatic problem: ";
  title += solvers::ucp::status_name(answer.report.status);
  if (!answer.forces.empty()) title += ", contact forces of the solution";
  return assembly_svg(in.assembly, answer.forces, title);
}

}  // namespace contactcert::queries
