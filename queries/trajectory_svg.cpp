#include "queries/trajectory_svg.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "exact/rational_text.h"
#include "queries/html_report.h"
#include "queries/simulate_query.h"

namespace contactcert::queries {
namespace {

namespace motion = solvers::motion;
using exact::Q;
using P = geometry::Vec2<double>;

constexpr std::size_t kMaxFrames = 400;
constexpr double kWidth = 640, kMargin = 20, kCaption = 44;

P view(const geometry::Vec2<Q>& p) { return {p.x.get_d(), p.y.get_d()}; }
P view(const P& p) { return p; }
geometry::Pose<double> view(const geometry::Pose<Q>& p) { return geometry::to_double(p); }
geometry::Pose<double> view(const geometry::Pose<double>& p) { return p; }
std::string text_of(const Q& x) { return exact::to_string(x); }
std::string text_of(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

struct FrameContact {
  P point, force;
  char mode;
};

/// What one frame shows, in doubles.
struct Frame {
  std::vector<std::vector<P>> bodies, float_bodies;
  std::vector<P> tips;
  std::vector<FrameContact> contacts;
  std::string caption;
};

/// Every body's outline at its pose.
template <class T>
std::vector<std::vector<P>> bodies_at(const motion::MotionScene& scene, const motion::Poses<T>& poses) {
  std::vector<std::vector<P>> out;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const geometry::Pose<double> pose = view(poses[b]);
    out.emplace_back();
    for (const geometry::Point2& v : std::get<geometry::PolygonShape>(scene.bodies[b].workpiece.shape).vertices)
      out.back().push_back(pose.apply(view(geometry::Vec2<Q>{v.x, v.y})));
  }
  return out;
}

/// The frames of a run: before each step (its pose, the tips then, its contacts and forces), then the final pose.
template <class T>
std::vector<Frame> frames_of(const motion::MotionScene& scene, const motion::Trajectory<T>& run) {
  std::vector<Frame> out;
  std::vector<P> tips;
  for (const motion::Finger& f : scene.fingers) tips.push_back(view(geometry::Vec2<Q>{f.tip.x, f.tip.y}));
  for (const motion::StepRecord<T>& s : run.steps) {
    Frame f{bodies_at(scene, s.poses), {}, tips, {}, ""};
    std::string modes;
    for (const motion::ContactRecord<T>& c : s.contacts) {
      f.contacts.push_back({view(c.point), view(c.force()), c.mode});
      modes += c.mode;
    }
    f.caption = "step " + std::to_string(s.index) + ", t = " + text_of(s.time) + ", h = " + text_of(s.h) + ": " +
                solvers::ucp::status_name(s.verdict) +
                (s.uniqueness ? std::string(", ") + motion::uniqueness_name(s.uniqueness->status) : "") + ", modes " +
                modes + (s.made.empty() ? "" : ", made " + std::to_string(s.made.size())) +
                (s.broken.empty() ? "" : ", broken " + std::to_string(s.broken.size()));
    out.push_back(f);
    tips.clear();
    for (const auto& t : s.tips_after) tips.push_back(view(t));
  }
  Frame last{bodies_at(scene, run.final_poses), {}, tips, {}, ""};
  last.caption = "end, t = " + text_of(run.final_time) + ": " + motion::run_status_name(run.status);
  out.push_back(last);
  return out;
}

/// world -> picture coordinates (y up -> y down).
struct Canvas {
  double x0, y1, scale;
  P at(const P& p) const { return {kMargin + (p.x - x0) * scale, kMargin + (y1 - p.y) * scale}; }
};

std::string points(const Canvas& c, const std::vector<P>& poly) {
  std::ostringstream s;
  s.precision(6);
  for (const P& p : poly) s << c.at(p).x << "," << c.at(p).y << " ";
  return s.str();
}

const char* mode_colour(char mode) {
  switch (mode) {
    case 's':
      return "white";
    case 'r':
      return "black";
    case '+':
    case '-':
      return "darkorange";
    default:
      return "purple";
  }
}

/// One frame's group: visible from frame k's start to the next frame's (SMIL, discrete), frame 0 without animation.
void draw_frame(std::ostringstream& s, const Canvas& c, const Frame& f, std::size_t k, std::size_t n, double seconds,
                double force_scale, double height) {
  s << "<g visibility=\"" << (k == 0 ? "visible" : "hidden") << "\">\n";
  s << "<animate attributeName=\"visibility\" calcMode=\"discrete\" dur=\"" << seconds * double(n)
    << "s\" repeatCount=\"indefinite\" values=\"hidden;visible;hidden\" keyTimes=\"0;" << double(k) / double(n) << ";"
    << double(k + 1) / double(n) << "\"/>\n";
  for (const std::vector<P>& body : f.float_bodies)
    s << "<polygon points=\"" << points(c, body) << "\" fill=\"none\" stroke=\"crimson\" stroke-dasharray=\"4 3\"/>\n";
  for (const std::vector<P>& body : f.bodies)
    s << "<polygon points=\"" << points(c, body) << "\" fill=\"lightsteelblue\" stroke=\"navy\"/>\n";
  for (const P& t : f.tips)
    s << "<circle cx=\"" << c.at(t).x << "\" cy=\"" << c.at(t).y << "\" r=\"7\" fill=\"none\" stroke=\"red\" "
      << "stroke-width=\"2\"/>\n";
  for (const FrameContact& x : f.contacts) {
    const P a = c.at(x.point), b = c.at({x.point.x + force_scale * x.force.x, x.point.y + force_scale * x.force.y});
    if (std::hypot(b.x - a.x, b.y - a.y) > 1)
      s << "<line x1=\"" << a.x << "\" y1=\"" << a.y << "\" x2=\"" << b.x << "\" y2=\"" << b.y
        << "\" stroke=\"seagreen\" stroke-width=\"2\" marker-end=\"url(#arrow)\"/>\n";
    s << "<circle cx=\"" << a.x << "\" cy=\"" << a.y << "\" r=\"4\" fill=\"" << mode_colour(x.mode)
      << "\" stroke=\"black\"/>\n";
  }
  s << "<text x=\"" << kMargin << "\" y=\"" << height - 10 << "\" font-size=\"13\">" << html_escape(f.caption)
    << "</text>\n</g>\n";
}

}  // namespace

std::string trajectory_svg(const SimulateAnswer& a) {
  std::vector<Frame> all = a.exact_run ? frames_of(a.scene, *a.exact_run) : frames_of(a.scene, *a.float_run);
  if (a.compared) {
    const std::vector<Frame> fl = frames_of(a.scene, *a.float_run);
    for (std::size_t k = 0; k < all.size() && k < fl.size(); ++k) all[k].float_bodies = fl[k].bodies;
  }
  // At most kMaxFrames frames: every k-th, and the last.
  const std::size_t stride = (all.size() + kMaxFrames - 1) / kMaxFrames;
  std::vector<Frame> frames;
  for (std::size_t k = 0; k < all.size(); k += stride) frames.push_back(all[k]);
  if ((all.size() - 1) % stride != 0) frames.push_back(all.back());
  // The view: every body vertex and tip of every frame, with a margin of half the bodies' extent.
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300, force = 0;
  for (const Frame& f : frames) {
    std::vector<const std::vector<P>*> all_points{&f.tips};
    for (const std::vector<P>& body : f.bodies) all_points.push_back(&body);
    for (const std::vector<P>* ps : all_points)
      for (const P& p : *ps)
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    for (const FrameContact& x : f.contacts) force = std::max(force, std::hypot(x.force.x, x.force.y));
  }
  const double pad = 0.5 * std::max({x1 - x0, y1 - y0, 1e-9});
  x0 -= pad, y0 -= pad, x1 += pad, y1 += pad;
  const Canvas c{x0, y1, (kWidth - 2 * kMargin) / (x1 - x0)};
  const double height = 2 * kMargin + (y1 - y0) * c.scale + kCaption;
  const double force_scale = force > 0 ? 0.3 * pad * 2 / force : 0;  // the largest force: 0.3 of the body's size
  const double frame_seconds = std::clamp(10.0 / double(frames.size()), 0.05, 0.5);

  std::ostringstream s;
  s.precision(6);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << height
    << "\" font-family=\"sans-serif\">\n<title>" << html_escape(a.file) << "</title>\n"
    << "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"6\" markerHeight=\"6\" "
       "orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"seagreen\"/></marker>\n"
    << "<clipPath id=\"view\"><rect x=\"" << kMargin << "\" y=\"" << kMargin << "\" width=\"" << kWidth - 2 * kMargin
    << "\" height=\"" << (y1 - y0) * c.scale << "\"/></clipPath></defs>\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<g clip-path=\"url(#view)\">\n";
  for (const motion::Obstacle& o : a.scene.obstacles) {
    std::vector<P> poly;
    for (const geometry::Point2& v : o.vertices) poly.push_back(view(geometry::Vec2<Q>{v.x, v.y}));
    s << "<polygon points=\"" << points(c, poly) << "\" fill=\"silver\" stroke=\"dimgray\"><title>"
      << html_escape(o.name) << "</title></polygon>\n";
  }
  s << "</g>\n";
  // The path: at most about 20 outlines, evenly spaced, and the last.
  const std::size_t every = std::max<std::size_t>(1, frames.size() / 20);
  for (std::size_t k = 0; k < frames.size(); ++k)
    if (k % every == 0 || k + 1 == frames.size())
      for (const std::vector<P>& body : frames[k].bodies)
        s << "<polygon points=\"" << points(c, body)
          << "\" fill=\"none\" stroke=\"steelblue\" stroke-opacity=\"0.3\"/>\n";
  for (std::size_t k = 0; k < frames.size(); ++k)
    draw_frame(s, c, frames[k], k, frames.size(), frame_seconds, force_scale, height);
  s << "<text x=\"" << kMargin << "\" y=\"" << height - 28 << "\" font-size=\"13\">"
    << html_escape(a.file + ": " + motion::run_status_name(run_status(a)) +
                   (run_reason(a).empty() ? "" : " (" + run_reason(a) + ")"))
    << "</text>\n</svg>\n";
  return s.str();
}

}  // namespace contactcert::queries
