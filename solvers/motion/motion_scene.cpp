#include "solvers/motion/motion_scene.h"

#include "geometry/scene_json.h"

namespace contactcert::solvers::motion {
namespace {

using exact::JsonInput;
using geometry::read_point;

/// Fails unless the vertices form a convex counter-clockwise polygon (simple, no collinear vertex).
void expect_convex(const std::vector<Point2>& v, const JsonInput& node) {
  const geometry::PolygonCheck check = geometry::check_polygon(v);
  if (check.defect != geometry::PolygonDefect::kNone) node.fail(check.message());
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    if (sgn(geometry::cross(v[(i + 1) % n] - v[i], v[(i + 2) % n] - v[(i + 1) % n])) <= 0)
      node.fail("a convex polygon (vertex " + std::to_string((i + 1) % n) +
                " is reflex; split a non-convex shape into convex obstacles)");
}

Q read_mu(const JsonInput& node) {
  const Q mu = node.rational();
  if (sgn(mu) < 0) node.fail("a friction coefficient >= 0");
  return mu;
}

std::vector<ScheduleSegment> read_schedule(const JsonInput& node) {
  std::vector<ScheduleSegment> out;
  const std::vector<JsonInput> pieces = node.elements();
  if (pieces.empty()) node.fail("at least one schedule segment");
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const JsonInput& p = pieces[i];
    p.expect_keys({"duration", "velocity", "force"});
    ScheduleSegment s;
    if (const auto d = p.find("duration")) {
      s.duration = d->rational();
      if (sgn(*s.duration) <= 0) d->fail("a duration > 0");
    } else if (i + 1 < pieces.size()) {
      p.fail("a \"duration\" (only the last segment may last for ever)");
    }
    const auto v = p.find("velocity"), f = p.find("force");
    if (bool(v) == bool(f)) p.fail("exactly one of \"velocity\" or \"force\" (world axes)");
    s.force = bool(f);
    s.value = read_point(v ? *v : *f);
    out.push_back(s);
  }
  return out;
}

}  // namespace

bool is_motion_scene(const JsonInput& root) { return root.is_object() && bool(root.find("motion")); }

ScheduleAt schedule_at(const Finger& f, const Q& t) {
  Q start(0);
  for (const ScheduleSegment& s : f.schedule) {
    if (!s.duration) return {&s, std::nullopt};
    const Q end = start + *s.duration;
    if (t < end) return {&s, end};
    start = end;
  }
  // Past the last segment's end: it stays in force (a schedule whose last segment has a duration holds it).
  return {&f.schedule.back(), std::nullopt};
}

/// A convex polygonal body: its shape and com (default: the centroid) as a workpiece.
geometry::Workpiece read_convex_body(const JsonInput& node, const JsonInput& shape_node) {
  geometry::Workpiece w;
  w.shape = geometry::read_shape(shape_node);
  const auto* poly = std::get_if<geometry::PolygonShape>(&w.shape);
  if (!poly) shape_node.fail("a polygon (motion is for polygonal bodies)");
  expect_convex(poly->vertices, shape_node.at("vertices"));
  const auto com = node.find("com");
  w.com = com ? read_point(*com) : geometry::centroid(w.shape);
  w.inertia_per_mass = geometry::inertia_per_mass(w.shape, w.com);
  return w;
}

MotionScene read_motion_scene(const JsonInput& root) {
  root.expect_keys({"kind", "name", "description", "source", "note", "workpiece", "bodies", "gravity", "obstacles",
                    "fingers", "motion"});
  if (root.at("kind").string() != "quasistatic_scene") root.at("kind").fail("\"quasistatic_scene\"");
  MotionScene s;
  s.file = root.file();
  const Point2 gravity = root.find("gravity") ? read_point(root.at("gravity")) : Point2{Q(0), Q(0)};
  if (bool(root.find("workpiece")) == bool(root.find("bodies")))
    root.fail("exactly one of \"workpiece\" (one body) or \"bodies\" (several)");
  if (const auto w = root.find("workpiece")) {
    s.bodies.push_back({"body", geometry::read_workpiece(*w), gravity, Q(0)});
    const auto* poly = std::get_if<geometry::PolygonShape>(&s.bodies[0].workpiece.shape);
    if (!poly) w->at("shape").fail("a polygon (motion is for polygonal workpieces)");
    expect_convex(poly->vertices, w->at("shape").at("vertices"));
  } else {
    const std::vector<JsonInput> bodies = root.at("bodies").elements();
    if (bodies.empty()) root.at("bodies").fail("at least one body");
    for (std::size_t k = 0; k < bodies.size(); ++k) {
      const JsonInput& b = bodies[k];
      b.expect_keys({"name", "shape", "com", "weight", "mu"});
      MovingBody body{"body " + std::to_string(k), read_convex_body(b, b.at("shape")), gravity, Q(0)};
      if (const auto n = b.find("name")) body.name = n->string();
      if (const auto w = b.find("weight")) body.weight = read_point(*w);
      if (const auto m = b.find("mu")) body.mu = read_mu(*m);
      for (const MovingBody& other : s.bodies)
        if (other.name == body.name) b.at("name").fail("a name no other body has");
      s.bodies.push_back(body);
    }
  }
  if (const auto obs = root.find("obstacles")) {
    for (const JsonInput& o : obs->elements()) {
      o.expect_keys({"name", "vertices", "mu"});
      Obstacle ob;
      if (const auto n = o.find("name")) ob.name = n->string();
      for (const JsonInput& v : o.at("vertices").elements()) ob.vertices.push_back(read_point(v));
      expect_convex(ob.vertices, o.at("vertices"));
      ob.mu = read_mu(o.at("mu"));
      s.obstacles.push_back(ob);
    }
  }
  if (const auto fs = root.find("fingers")) {
    for (const JsonInput& f : fs->elements()) {
      f.expect_keys({"name", "tip", "mu", "schedule"});
      Finger fi;
      if (const auto n = f.find("name")) fi.name = n->string();
      fi.tip = read_point(f.at("tip"));
      fi.mu = read_mu(f.at("mu"));
      fi.schedule = read_schedule(f.at("schedule"));
      s.fingers.push_back(fi);
    }
  }
  const JsonInput m = root.at("motion");
  m.expect_keys({"dt", "steps"});
  s.dt = m.at("dt").rational();
  if (sgn(s.dt) <= 0) m.at("dt").fail("a step size > 0");
  s.steps = m.at("steps").integer(1, 1000000);
  if (s.obstacles.empty() && s.fingers.empty()) root.fail("at least one of \"obstacles\" or \"fingers\"");
  return s;
}

}  // namespace contactcert::solvers::motion
