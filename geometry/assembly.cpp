#include "geometry/assembly.h"

#include "exact/rational_text.h"
#include "geometry/contact_frame.h"
#include "geometry/point_text.h"
#include "geometry/scene_json.h"
#include "geometry/shape_overlap.h"

namespace contactcert::geometry {
namespace {

using exact::JsonInput;

/// A body: com defaults to the centroid, mass to the area (density 1; a disk's area is irrational, so a disk
/// needs its mass), inertia to uniform density, load to its weight m gravity at the com.
Body read_body(const JsonInput& node, const Point2& gravity) {
  node.expect_keys({"name", "shape", "com", "mass", "inertia", "load"});
  Body b;
  b.shape = read_shape(node.at("shape"));
  const auto com = node.find("com");
  b.com = com ? read_point(*com) : centroid(b.shape);
  if (const auto m = node.find("mass")) {
    b.mass = read_positive(*m);
  } else if (const auto* poly = std::get_if<PolygonShape>(&b.shape)) {
    b.mass = shoelace_area2(poly->vertices) / 2;
  } else {
    node.fail("a \"mass\" (a disk's area is irrational, so it has no exact default)");
  }
  const auto inertia = node.find("inertia");
  b.inertia = inertia ? read_positive(*inertia) : b.mass * inertia_per_mass(b.shape, b.com);
  if (const auto load = node.find("load")) {
    const exact::Vec<Q> w = load->rational_vector(3);
    b.load_fx = w(0), b.load_fy = w(1), b.load_torque = w(2);
  } else {
    b.load_fx = b.mass * gravity.x, b.load_fy = b.mass * gravity.y, b.load_torque = 0;
  }
  return b;
}

Finger read_finger(const JsonInput& f) {
  f.expect_keys({"name", "position", "axes", "velocity", "force"});
  Finger out;
  out.position = read_point(f.at("position"));
  if (const auto axes = f.find("axes")) {
    const std::string a = axes->string();
    if (a != "frame" && a != "world") axes->fail("\"frame\" (joints along n and t) or \"world\" (along x and y)");
    out.world_axes = a == "world";
  }
  const auto v = f.find("velocity"), force = f.find("force");
  if (bool(v) == bool(force)) f.fail("exactly one of \"velocity\" or \"force\"");
  out.force_controlled = bool(force);
  out.given = read_point(v ? *v : *force);
  return out;
}

Party read_party(const JsonInput& node, const Assembly& a) {
  node.expect_keys({"body", "obstacle", "fixel", "finger"});
  struct Option {
    const char* key;
    Party::Kind kind;
    std::size_t count;
  };
  const Option options[] = {{"body", Party::Kind::kBody, a.bodies.size()},
                            {"obstacle", Party::Kind::kObstacle, a.obstacles.size()},
                            {"fixel", Party::Kind::kFixel, a.fixels.size()},
                            {"finger", Party::Kind::kFinger, a.fingers.size()}};
  std::optional<Party> out;
  for (const Option& o : options) {
    const auto i = node.find(o.key);
    if (!i) continue;
    if (out) node.fail("exactly one of \"body\", \"obstacle\", \"fixel\" or \"finger\"");
    if (o.count == 0) i->fail(std::string("an index, but the scene has no ") + o.key);
    out = Party{o.kind, static_cast<std::size_t>(i->integer(0, static_cast<long>(o.count) - 1))};
  }
  if (!out) node.fail("one of {\"body\": i}, {\"obstacle\": i}, {\"fixel\": i} or {\"finger\": i}");
  return *out;
}

const Shape* shape_of(const Assembly& a, const Party& p) {
  if (p.kind == Party::Kind::kBody) return &a.bodies[p.index].shape;
  if (p.kind == Party::Kind::kObstacle) return &a.obstacles[p.index];
  return nullptr;
}

Point2 position_of(const Assembly& a, const Party& p) {
  return p.kind == Party::Kind::kFixel ? a.fixels[p.index] : a.fingers[p.index].position;
}

/// The normal at boundary point p of shape s pointing into it, if the boundary determines it (not at a vertex).
std::optional<Point2> inward_normal(const Shape& s, const Point2& p) {
  const FrameResult f = frame_from_position(s, p);
  if (f.status != FrameStatus::kOk) return std::nullopt;
  return f.frame.normal;
}

/// The frame of a contact given by a `position` on both boundaries: the normal of whichever boundary determines it
/// (into `to`, or out of `from`); both must agree where both do.
void frame_from_positions(const Assembly& a, AssemblyContact& c, const JsonInput& node) {
  const Shape* from = shape_of(a, c.from);
  const Shape* to = shape_of(a, c.to);
  std::optional<Point2> n_to = to ? inward_normal(*to, c.point) : std::nullopt;
  std::optional<Point2> n_from = from ? inward_normal(*from, c.point) : std::nullopt;
  if (n_from) n_from = Q(-1) * *n_from;
  if (n_to && n_from && (sgn(Q(cross(*n_to, *n_from))) != 0 || sgn(Q(dot(*n_to, *n_from))) <= 0))
    node.fail("a point where the two boundaries have a common normal; at " + point_text(c.point) + " they have " +
              point_text(*n_to) + " and " + point_text(*n_from));
  if (!n_to && !n_from)
    node.fail("an explicit \"normal\": at " + point_text(c.point) +
              " neither boundary determines the normal (vertices)");
  c.normal = n_to ? *n_to : *n_from;
}

/// Checks that c.point lies on both parties' boundaries (a point party: is that point) and that c.normal points
/// into `to` and out of `from` there.
void check_contact(const Assembly& a, const AssemblyContact& c, const JsonInput& node) {
  const Party* sides[] = {&c.from, &c.to};
  for (const Party* side : sides) {
    const bool is_to = side == &c.to;
    if (const Shape* s = shape_of(a, *side)) {
      const FrameResult f = frame_from_contact(*s, c.point, is_to ? c.normal : Q(-1) * c.normal, Q(0));
      if (f.status == FrameStatus::kClosestNotUnique)
        node.fail(std::string("a point on the boundary of `") + (is_to ? "to" : "from") + "`: " + f.message);
      if (f.status != FrameStatus::kOk)
        node.fail(std::string("a common normal pointing from `from` into `to`; at `") + (is_to ? "to" : "from") +
                  "`: " + f.message + (is_to ? "" : " (negated: the normal points out of `from`)"));
    } else if (!(position_of(a, *side) == c.point)) {
      node.fail("the point " + point_text(position_of(a, *side)) + " of the point party, not " + point_text(c.point));
    }
  }
}

AssemblyContact read_contact(const JsonInput& node, const Assembly& a, const std::optional<Q>& mu_s,
                             const std::optional<Q>& mu_k) {
  node.expect_keys({"name", "from", "to", "point", "normal", "position", "mu", "mu_s", "mu_k"});
  AssemblyContact c;
  c.from = read_party(node.at("from"), a);
  c.to = read_party(node.at("to"), a);
  if (!c.from.movable() && !c.to.movable()) node.fail("a contact with at least one movable body");
  if (c.from.kind == c.to.kind && c.from.index == c.to.index) node.fail("two different parties");
  const bool point_from = !shape_of(a, c.from), point_to = !shape_of(a, c.to);
  if (point_from && point_to) node.fail("at most one point party (fixel or finger)");
  const auto point = node.find("point"), normal = node.find("normal"), position = node.find("position");
  if (position && (point || normal)) node.fail("either \"position\" or \"point\" and \"normal\", not both");
  if (bool(point) != bool(normal)) node.fail("both \"point\" and \"normal\"");
  if (point) {
    c.point = read_point(*point);
    c.normal = read_point(*normal);
    if (sgn(norm2(c.normal)) == 0) normal->fail("a non-zero normal");
  } else if (position) {
    c.point = read_point(*position);
    for (const Party* side : {&c.from, &c.to})
      if (const Shape* s = shape_of(a, *side); s && locate_in_shape(*s, c.point) != ShapeLocation::kBoundary)
        position->fail("a point on the boundary of both parties, not " + point_text(c.point));
    frame_from_positions(a, c, node);
  } else if (point_from || point_to) {  // the frame from the point party's position (docs/formats.md section 3)
    const Party& body = point_from ? c.to : c.from;
    const FrameResult f = frame_from_position(*shape_of(a, body), position_of(a, point_from ? c.from : c.to));
    if (f.status != FrameStatus::kOk) node.fail(f.message);
    if (!f.frame.touching()) node.fail("a fixel or finger on the body's boundary (a contact touches)");
    c.point = f.frame.point;
    c.normal = point_from ? f.frame.normal : Q(-1) * f.frame.normal;
  } else {
    node.fail("\"point\" and \"normal\", or a \"position\" on both boundaries");
  }
  check_contact(a, c, node);
  const auto mu = node.find("mu"), s = node.find("mu_s"), k = node.find("mu_k");
  if (mu && (s || k)) node.fail("either \"mu\" or \"mu_s\"/\"mu_k\"");
  if (mu) {
    c.mu_s = c.mu_k = read_nonnegative(*mu);
  } else if (s || mu_s) {
    c.mu_s = s ? read_nonnegative(*s) : *mu_s;
    c.mu_k = k ? read_nonnegative(*k) : (mu_k ? *mu_k : c.mu_s);
  } else {
    node.fail("a friction coefficient \"mu_s\" (or \"mu\"), here or at the top level");
  }
  return c;
}

/// Bodies and obstacles must not overlap; fixels and fingers must not lie inside them.
void check_overlaps(const JsonInput& root, const Assembly& a) {
  std::vector<std::pair<const Shape*, std::string>> shapes;
  for (std::size_t i = 0; i < a.bodies.size(); ++i)
    shapes.push_back({&a.bodies[i].shape, "bodies[" + std::to_string(i) + "]"});
  for (std::size_t i = 0; i < a.obstacles.size(); ++i)
    shapes.push_back({&a.obstacles[i], "obstacles[" + std::to_string(i) + "]"});
  for (std::size_t j = 0; j < shapes.size(); ++j) {
    for (std::size_t i = 0; i < j; ++i)
      if (interiors_overlap(*shapes[i].first, *shapes[j].first))
        root.at(j < a.bodies.size() ? "bodies" : "obstacles")
            .at(j < a.bodies.size() ? j : j - a.bodies.size())
            .fail("a shape that does not overlap " + shapes[i].second + " (their interiors intersect)");
  }
  const auto points = [&](const char* key, const std::vector<Point2>& ps) {
    for (std::size_t k = 0; k < ps.size(); ++k)
      for (const auto& [s, name] : shapes)
        if (locate_in_shape(*s, ps[k]) == ShapeLocation::kInside)
          root.at(key).at(k).fail("a point outside " + name + ", not inside it");
  };
  points("fixels", a.fixels);
  std::vector<Point2> finger_points;
  for (const Finger& f : a.fingers) finger_points.push_back(f.position);
  points("fingers", finger_points);
}

}  // namespace

bool is_assembly(const JsonInput& root) { return root.is_object() && root.find("bodies").has_value(); }

Assembly read_assembly(const JsonInput& root) {
  const std::string kind = root.at("kind").string();
  if (kind != "planar" && kind != "quasistatic_scene")
    root.at("kind").fail("\"planar\" or \"quasistatic_scene\" (an assembly)");
  root.expect_keys({"kind", "name", "description", "source", "note", "bodies", "obstacles", "fixels", "fingers",
                    "gravity", "contacts", "mu_s", "mu_k"});
  Assembly a;
  const Point2 gravity = root.find("gravity") ? read_point(root.at("gravity")) : Point2{Q(0), Q(-1)};
  const JsonInput bodies = root.at("bodies");
  for (const JsonInput& b : bodies.elements()) a.bodies.push_back(read_body(b, gravity));
  if (a.bodies.empty()) bodies.fail("at least one body");
  if (const auto obs = root.find("obstacles"))
    for (const JsonInput& o : obs->elements()) {
      o.expect_keys({"name", "shape"});
      a.obstacles.push_back(read_shape(o.at("shape")));
    }
  if (const auto fx = root.find("fixels"))
    for (const JsonInput& f : fx->elements()) {
      f.expect_keys({"name", "position"});
      a.fixels.push_back(read_point(f.at("position")));
    }
  if (const auto fg = root.find("fingers")) {
    if (kind != "quasistatic_scene")
      fg->fail("no fingers in a \"planar\" assembly (they belong to a quasistatic_scene)");
    for (const JsonInput& f : fg->elements()) a.fingers.push_back(read_finger(f));
  }
  check_overlaps(root, a);
  const auto mu_s = root.find("mu_s"), mu_k = root.find("mu_k");
  const std::optional<Q> s = mu_s ? std::optional<Q>(read_nonnegative(*mu_s)) : std::nullopt;
  const std::optional<Q> k = mu_k ? std::optional<Q>(read_nonnegative(*mu_k)) : std::nullopt;
  const JsonInput contacts = root.at("contacts");
  for (const JsonInput& c : contacts.elements()) a.contacts.push_back(read_contact(c, a, s, k));
  if (a.contacts.empty()) contacts.fail("at least one contact");
  return a;
}

}  // namespace contactcert::geometry
