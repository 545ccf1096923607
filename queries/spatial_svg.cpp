#include "queries/spatial_svg.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "queries/html_report.h"

namespace contactcert::queries {
namespace {

using P3 = std::array<double, 3>;

P3 to_p3(const geometry::Vec3& v) { return {v[0].get_d(), v[1].get_d(), v[2].get_d()}; }
P3 plus(const P3& a, const P3& b, double t = 1) { return {a[0] + t * b[0], a[1] + t * b[1], a[2] + t * b[2]}; }
double norm(const P3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

std::string fixed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

struct XY {
  double x, y;
};

// The isometric projection seen from (1, 1, 1): u = (x - y) cos 30, w = z - (x + y) sin 30 (up); picture
// coordinates (u - u0) scale + margin, (w1 - w) scale + top.
struct View {
  double u0 = 0, w1 = 0, scale = 1;
  static constexpr double kMargin = 40, kTop = 40;
  static XY project(const P3& p) { return {(p[0] - p[1]) * std::sqrt(3.0) / 2, p[2] - (p[0] + p[1]) / 2}; }
  XY at(const P3& p) const {
    const XY q = project(p);
    return {(q.x - u0) * scale + kMargin, (w1 - q.y) * scale + kTop};
  }
};

std::string line(XY a, XY b, const std::string& style) {
  return "<line x1=\"" + fixed(a.x) + "\" y1=\"" + fixed(a.y) + "\" x2=\"" + fixed(b.x) + "\" y2=\"" + fixed(b.y) +
         "\" " + style + "/>\n";
}

std::string polygon(const std::vector<XY>& corners, const std::string& style) {
  std::string points;
  for (const XY& p : corners) points += std::string(points.empty() ? "" : " ") + fixed(p.x) + "," + fixed(p.y);
  return "<polygon points=\"" + points + "\" " + style + "/>\n";
}

std::string text_at(XY p, const std::string& text, const char* colour) {
  return "<text x=\"" + fixed(p.x) + "\" y=\"" + fixed(p.y) + "\" fill=\"" + colour +
         "\" paint-order=\"stroke\" stroke=\"white\" stroke-width=\"3\">" + html_escape(text) + "</text>\n";
}

const char* const kNormal = "#2471a3";
const char* const kPyramid = "#c0392b";

// Corner c of the box (bit 0: +x, bit 1: +y, bit 2: +z).
P3 corner(const P3& centre, const P3& half, int c) {
  P3 p;
  for (int d = 0; d < 3; ++d) p[d] = centre[d] + ((c >> d) & 1 ? half[d] : -half[d]);
  return p;
}

}  // namespace

std::string spatial_svg(const geometry::SpatialScene& scene, const std::string& title) {
  // The drawn length of a normal, in scene units: an eighth of the body's size (the largest distance between its
  // box's corners, com and contact points), at least 1/10.
  std::vector<P3> points{to_p3(scene.body.com)};
  P3 centre{}, half{};
  if (scene.body.box) {
    centre = to_p3(scene.body.box->center), half = to_p3(scene.body.box->half);
    for (int c = 0; c < 8; ++c) points.push_back(corner(centre, half, c));
  }
  for (const geometry::SpatialContact& c : scene.contacts) points.push_back(to_p3(c.point));
  double size = 0;
  for (const P3& p : points)
    for (const P3& q : points) size = std::max(size, norm(plus(p, q, -1)));
  const double reach = std::max(size / 8, 0.1);
  // Per contact: its pyramid's rays n + d_j scaled so that n has length `reach` (and the normal itself).
  std::vector<std::vector<P3>> tips;
  for (const geometry::SpatialContact& c : scene.contacts) {
    const P3 p = to_p3(c.point), n = to_p3(c.normal);
    const double s = reach / norm(n);
    std::vector<P3> t{plus(p, n, s)};
    for (std::size_t j = 0; j < c.edges.size(); ++j) t.push_back(plus(plus(p, n, s), to_p3(c.edge(j)), s));
    for (const P3& q : t) points.push_back(q);
    tips.push_back(std::move(t));
  }
  double u0 = 1e300, u1 = -1e300, w0 = 1e300, w1 = -1e300;
  for (const P3& p : points) {
    const XY q = View::project(p);
    u0 = std::min(u0, q.x), u1 = std::max(u1, q.x), w0 = std::min(w0, q.y), w1 = std::max(w1, q.y);
  }
  const View v{u0, w1, 520 / std::max({u1 - u0, w1 - w0, 1e-9})};
  const double width = std::max((u1 - u0) * v.scale + 2 * View::kMargin, 680.0),
               bar = (w1 - w0) * v.scale + View::kTop + 24, height = bar + v.scale / 2 + 48;
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fixed(width) + "\" height=\"" + fixed(height) +
                  "\" viewBox=\"0 0 " + fixed(width) + " " + fixed(height) +
                  "\" font-family=\"sans-serif\" font-size=\"12\">\n<defs>\n<marker id=\"spatial-normal\" "
                  "viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"6\" markerHeight=\"6\" orient=\"auto\">"
                  "<path d=\"M0,0 L10,5 L0,10 z\" fill=\"" +
                  std::string(kNormal) +
                  "\"/></marker>\n</defs>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" +
                  text_at({8, 18}, title, "black");
  if (scene.body.box) {
    // The faces -x, +x, -y, +y, -z, +z translucent (hidden ones first), the edges, dashed at the hidden corner 0.
    const int faces[6][4] = {{0, 2, 6, 4}, {0, 4, 5, 1}, {0, 1, 3, 2}, {1, 3, 7, 5}, {2, 6, 7, 3}, {4, 5, 7, 6}};
    for (const auto& f : faces) {
      std::vector<XY> q;
      for (int c : f) q.push_back(v.at(corner(centre, half, c)));
      s += polygon(q, "fill=\"#aed6f1\" fill-opacity=\"0.25\" stroke=\"none\"");
    }
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d)
        if (!((a >> d) & 1))
          s += line(v.at(corner(centre, half, a)), v.at(corner(centre, half, a | (1 << d))),
                    a == 0 ? "stroke=\"#566573\" stroke-dasharray=\"4 3\"" : "stroke=\"black\"");
  }
  const XY com = v.at(to_p3(scene.body.com));
  s += "<circle cx=\"" + fixed(com.x) + "\" cy=\"" + fixed(com.y) + "\" r=\"4\" fill=\"black\"/>\n" +
       text_at({com.x + 6, com.y - 6}, "com", "black");
  for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
    const XY p = v.at(to_p3(scene.contacts[i].point));
    const std::vector<P3>& t = tips[i];
    std::vector<XY> rim;
    for (std::size_t j = 1; j < t.size(); ++j) rim.push_back(v.at(t[j]));
    s += polygon(rim, std::string("fill=\"") + kPyramid + "\" fill-opacity=\"0.12\" stroke=\"" + kPyramid +
                          "\" stroke-width=\"0.8\"");
    for (const XY& q : rim) s += line(p, q, std::string("stroke=\"") + kPyramid + "\" stroke-width=\"0.8\"");
    s += line(p, v.at(t[0]),
              std::string("stroke=\"") + kNormal + "\" stroke-width=\"2\" marker-end=\"url(#spatial-normal)\"") +
         "<circle cx=\"" + fixed(p.x) + "\" cy=\"" + fixed(p.y) + "\" r=\"3\" fill=\"" + kNormal + "\"/>\n" +
         text_at({p.x + 4, p.y + 14}, std::to_string(i), kNormal);
  }
  // The scale: one scene unit along x; the legend.
  const XY unit_end{View::kMargin + v.scale * std::sqrt(3.0) / 2, bar + v.scale / 2};
  s += line({View::kMargin, bar}, unit_end, "stroke=\"black\" stroke-width=\"2\"") +
       text_at({unit_end.x + 6, unit_end.y + 4}, "1 unit along x", "black") +
       text_at({8, height - 26}, "contacts numbered, normals n blue, friction pyramids (rays n + d_j) red;", "black") +
       text_at({8, height - 10}, "x to the lower right, y to the lower left, z up; |n| drawn as " + fixed(reach),
               "black");
  return s + "</svg>\n";
}

}  // namespace contactcert::queries
