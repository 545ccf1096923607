#include "queries/stability_svg.h"

#include <array>
#include <cstdio>
#include <set>
#include <sstream>
#include <vector>

#include "queries/html_report.h"

namespace contactcert::queries {
namespace {

using exact::Q;
using exact::Vec;
using solvers::StabilityVerdict;

using Point = std::array<Q, 2>;  ///< (u, v) on a face, each in [-1, 1]
using Polygon = std::vector<Point>;

/// One face of the cube net: (a, b, c) = M g with c > 0 on the face and (u, v) = (a / c, b / c) in [-1, 1]^2.
/// M is a signed permutation chosen so that the net is continuous across every edge it shows.
struct Face {
  const char* name;
  int column, row;
  int M[3][3];
};

// Middle row, left to right, turns about the f_y axis: -f_x, +tau, +f_x, -tau; the middle column goes up to +f_y.
constexpr Face kFaces[6] = {
    {"torque > 0", 1, 1, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},   {"f_x > 0", 2, 1, {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}},
    {"torque < 0", 3, 1, {{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}}}, {"f_x < 0", 0, 1, {{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}}},
    {"f_y > 0", 1, 0, {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}},     {"f_y < 0", 1, 2, {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}},
};

/// g = M^T (u, v, 1), the wrench direction of a face point.
Vec<Q> wrench_at(const Face& f, const Point& p) {
  Vec<Q> g(3);
  for (int k = 0; k < 3; ++k) g(k) = Q(f.M[0][k]) * p[0] + Q(f.M[1][k]) * p[1] + Q(f.M[2][k]);
  return g;
}

/// The line of plane n on face f: (M n) . (u, v, 1) = 0.
std::array<Q, 3> face_line(const Face& f, const Vec<Q>& n) {
  std::array<Q, 3> L;
  for (int r = 0; r < 3; ++r) L[r] = Q(f.M[r][0]) * n(0) + Q(f.M[r][1]) * n(1) + Q(f.M[r][2]) * n(2);
  return L;
}

Q value(const std::array<Q, 3>& L, const Point& p) { return L[0] * p[0] + L[1] * p[1] + L[2]; }

Q area2(const Polygon& P) {
  Q a = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Point &p = P[i], &q = P[(i + 1) % P.size()];
    a += p[0] * q[1] - p[1] * q[0];
  }
  return a;
}

/// Cuts a convex polygon by a line into its parts with value <= 0 and >= 0 (exact; a part of zero area is
/// dropped).
void cut(const Polygon& P, const std::array<Q, 3>& L, std::vector<Polygon>& out) {
  Polygon neg, pos;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Point &p = P[i], &q = P[(i + 1) % P.size()];
    const Q sp = value(L, p), sq = value(L, q);
    if (sgn(sp) <= 0) neg.push_back(p);
    if (sgn(sp) >= 0) pos.push_back(p);
    if (sgn(sp) * sgn(sq) < 0) {
      const Q t = sp / (sp - sq);
      const Point x{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])};
      neg.push_back(x);
      pos.push_back(x);
    }
  }
  for (Polygon* part : {&neg, &pos})
    if (part->size() >= 3 && sgn(area2(*part)) != 0) out.push_back(std::move(*part));
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

constexpr double kSide = 150, kPad = 12, kTop = 28;

/// Picture coordinates of face point p (u right, v up).
std::pair<double, double> at(const Face& f, const Point& p) {
  return {kPad + kSide * (f.column + (p[0].get_d() + 1) / 2), kTop + kSide * (f.row + (1 - p[1].get_d()) / 2)};
}

std::string xy(const Face& f, const Point& p) {
  const auto [x, y] = at(f, p);
  return num(x) + "," + num(y);
}

bool on_border(const Point& p, const Point& q) {
  for (int k = 0; k < 2; ++k)
    for (int s : {-1, 1})
      if (p[k] == Q(s) && q[k] == Q(s)) return true;
  return false;
}

}  // namespace

const char* verdict_colour(StabilityVerdict v) {
  switch (v) {
    case StabilityVerdict::kStronglyStable:
      return "#1b7837";
    case StabilityVerdict::kWeaklyStable:
      return "#f1c232";
    case StabilityVerdict::kUnstable:
      return "#e8a8a8";
  }
  return "#000";
}

std::string stability_sphere_svg(const solvers::StableRegion<Q>& region, const std::optional<Vec<Q>>& mark) {
  const double width = 2 * kPad + 4 * kSide, height = kTop + 3 * kSide + kPad;
  std::ostringstream fills, bounds, frame;
  std::set<std::string> dots;
  for (const Face& f : kFaces) {
    std::vector<Polygon> cells{{{Q(-1), Q(-1)}, {Q(1), Q(-1)}, {Q(1), Q(1)}, {Q(-1), Q(1)}}};
    std::vector<std::array<Q, 3>> lines;
    for (Eigen::Index r = 0; r < region.planes.rows(); ++r) {
      const auto L = face_line(f, region.planes.row(r).transpose());
      if (sgn(L[0]) == 0 && sgn(L[1]) == 0) continue;  // the plane misses this face's interior
      lines.push_back(L);
      std::vector<Polygon> next;
      for (const auto& P : cells) cut(P, L, next);
      cells = std::move(next);
    }
    auto on_line = [&](const Point& p, const Point& q) {
      for (const auto& L : lines)
        if (sgn(value(L, p)) == 0 && sgn(value(L, q)) == 0) return true;
      return false;
    };
    for (const auto& P : cells) {
      Point c{Q(0), Q(0)};
      for (const auto& p : P) c = {c[0] + p[0], c[1] + p[1]};
      c = {c[0] / Q(long(P.size())), c[1] / Q(long(P.size()))};
      const StabilityVerdict label = region.label(wrench_at(f, c));
      fills << "<polygon points=\"";
      for (const auto& p : P) fills << xy(f, p) << " ";
      fills << "\" fill=\"" << verdict_colour(label) << "\" stroke=\"" << verdict_colour(label)
            << "\" stroke-width=\"0.6\"/>\n";
      // Lower-dimensional cells (sectors on an edge, rays at a vertex) with a label of their own.
      for (std::size_t i = 0; i < P.size(); ++i) {
        const Point &p = P[i], &q = P[(i + 1) % P.size()];
        if (on_border(p, q) || !on_line(p, q)) continue;
        const StabilityVerdict e = region.label(wrench_at(f, {(p[0] + q[0]) / 2, (p[1] + q[1]) / 2}));
        if (e != label)
          bounds << "<line x1=\"" << num(at(f, p).first) << "\" y1=\"" << num(at(f, p).second) << "\" x2=\""
                 << num(at(f, q).first) << "\" y2=\"" << num(at(f, q).second) << "\" stroke=\"" << verdict_colour(e)
                 << "\" stroke-width=\"2.5\" stroke-linecap=\"round\"/>\n";
        const StabilityVerdict v = region.label(wrench_at(f, p));
        if (v != label && v != e)
          dots.insert("<circle cx=\"" + num(at(f, p).first) + "\" cy=\"" + num(at(f, p).second) +
                      "\" r=\"2.6\" fill=\"" + verdict_colour(v) + "\" stroke=\"#333\" stroke-width=\"0.5\"/>\n");
      }
    }
    const auto [x0, y0] = at(f, {Q(-1), Q(1)});
    frame << "<rect x=\"" << num(x0) << "\" y=\"" << num(y0) << "\" width=\"" << kSide << "\" height=\"" << kSide
          << "\" fill=\"none\" stroke=\"#333\" stroke-width=\"0.8\"/>\n"
          << "<text x=\"" << num(x0 + 4) << "\" y=\"" << num(y0 + 13) << "\" font-size=\"11\" "
          << "paint-order=\"stroke\" stroke=\"white\" stroke-width=\"3\">" << html_escape(f.name) << "</text>\n";
  }
  if (mark) {
    const Vec<Q>& g = *mark;
    for (const Face& f : kFaces) {
      Q a = 0, b = 0, c = 0;
      for (int k = 0; k < 3; ++k) a += Q(f.M[0][k]) * g(k), b += Q(f.M[1][k]) * g(k), c += Q(f.M[2][k]) * g(k);
      if (sgn(c) <= 0 || abs(a) > c || abs(b) > c) continue;
      const auto [x, y] = at(f, {a / c, b / c});
      frame << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y) << "\" r=\"5\" fill=\"none\" stroke=\"black\" "
            << "stroke-width=\"1.5\"/><path d=\"M" << num(x - 8) << "," << num(y) << " h16 M" << num(x) << ","
            << num(y - 8) << " v16\" stroke=\"black\"/>\n<text x=\"" << num(x + 7) << "\" y=\"" << num(y - 7)
            << "\" font-size=\"12\" paint-order=\"stroke\" stroke=\"white\" stroke-width=\"3\">g</text>\n";
      break;  // a direction on a cube edge is drawn once
    }
  }
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
    << "\" viewBox=\"0 0 " << num(width) << " " << num(height)
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << fills.str() << bounds.str();
  for (const auto& d : dots) s << d;
  s << frame.str();
  // Title, axes and legend in the empty corners of the net.
  s << "<text x=\"" << kPad << "\" y=\"18\" font-size=\"13\">Wrench directions g = (f_x, f_y, torque), "
    << "exact cells (" << region.cells.size() << ") of " << region.planes.rows() << " planes</text>\n";
  const double lx = kPad + 2 * kSide + 10, ly = kTop + 16;
  const std::pair<StabilityVerdict, const char*> legend[] = {{StabilityVerdict::kStronglyStable, "strongly stable"},
                                                             {StabilityVerdict::kWeaklyStable, "weakly stable only"},
                                                             {StabilityVerdict::kUnstable, "unstable"}};
  for (int i = 0; i < 3; ++i)
    s << "<rect x=\"" << num(lx) << "\" y=\"" << num(ly + 20 * i - 10) << "\" width=\"14\" height=\"12\" fill=\""
      << verdict_colour(legend[i].first) << "\" stroke=\"#333\" stroke-width=\"0.5\"/><text x=\"" << num(lx + 20)
      << "\" y=\"" << num(ly + 20 * i) << "\">" << legend[i].second << "</text>\n";
  s << "<text x=\"" << num(lx) << "\" y=\"" << num(ly + 62) << "\" font-size=\"11\">thick line / dot: a sector / ray "
    << "whose label differs</text>\n<text x=\"" << num(lx) << "\" y=\"" << num(ly + 76)
    << "\" font-size=\"11\">from the region it bounds" << (mark ? "; g: the queried wrench" : "") << "</text>\n";
  const char* notes[] = {
      "The unfolded cube max(|f_x|, |f_y|, |torque|) = 1:", "each face is a gnomonic view, so the planes are",
      "straight lines and every cell is drawn exactly.",    "On the face torque &gt; 0, f_x points right and f_y",
      "up; its centre is g = (0, 0, 1). Folded (faces",     "seen from outside), the net is the sphere of",
      "directions; a cube edge appears on both faces."};
  for (int i = 0; i < 7; ++i)
    s << "<text x=\"" << num(kPad + 2 * kSide + 10) << "\" y=\"" << num(kTop + 2 * kSide + 18 + 15 * i)
      << "\" font-size=\"11\">" << notes[i] << "</text>\n";
  s << "</svg>\n";
  return s.str();
}

}  // namespace contactcert::queries
