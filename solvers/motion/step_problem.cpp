#include "solvers/motion/step_problem.h"

#include <nlohmann/json.hpp>

#include "exact/rational_text.h"
#include "solvers/assembly/assembly_ucp.h"
#include "solvers/ucp/scene_builder.h"

namespace contactcert::solvers::motion {
namespace {

std::string text(const Q& x) { return exact::to_string(x); }

Q rational(const Q& x) { return x; }
Q rational(double x) { return Q(x); }
template <class T>
geometry::Point2 point2(const Vec2<T>& p) {
  return {rational(p.x), rational(p.y)};
}
nlohmann::ordered_json pair(const geometry::Point2& p) { return nlohmann::ordered_json::array({text(p.x), text(p.y)}); }

nlohmann::ordered_json polygon(const geometry::Shape& s) {
  nlohmann::ordered_json v = nlohmann::ordered_json::array();
  for (const geometry::Point2& p : std::get<geometry::PolygonShape>(s).vertices) v.push_back(pair(p));
  return {{"type", "polygon"}, {"vertices", v}};
}

nlohmann::ordered_json party(const geometry::Party& p) {
  static const char* const kNames[] = {"body", "obstacle", "fixel", "finger"};
  return {{kNames[static_cast<int>(p.kind)], p.index}};
}

}  // namespace

template <class T>
ucp::UcpProblem step_problem(const SceneGeometry<T>& g, const Pose<T>& pose, const std::vector<Contact<T>>& contacts,
                             const std::vector<FingerCommand<T>>& commands, const std::string& name) {
  std::vector<ucp::SceneContact> list;
  for (const Contact<T>& c : contacts) {
    ucp::SceneContact s;
    s.r = point2(c.point), s.n = point2(c.normal), s.mu = rational(c.mu);
    if (c.kind == ContactKind::kFinger) {
      const FingerCommand<T>& cmd = commands[static_cast<std::size_t>(c.other)];
      s.finger = s.world_axes = true;
      s.force_controlled = cmd.force;
      s.given = point2(cmd.value);
    }
    list.push_back(s);
  }
  ucp::UcpProblem problem;
  problem.quasistatic = ucp::quasistatic_of_contacts(point2(pose.apply(g.coms[0])), point2(g.weights[0]), list, name);
  problem.set(ucp::build_ucp(*problem.quasistatic));
  return problem;
}

template <class T>
geometry::Assembly step_assembly(const SceneGeometry<T>& g, const Poses<T>& poses,
                                 const std::vector<Contact<T>>& contacts,
                                 const std::vector<FingerCommand<T>>& commands) {
  using geometry::Party;
  geometry::Assembly a;
  for (std::size_t b = 0; b < g.bodies.size(); ++b) {
    geometry::PolygonShape shape;
    for (const Vec2<T>& p : g.bodies[b]) shape.vertices.push_back(point2(poses[b].apply(p)));
    const geometry::Point2 w = point2(g.weights[b]);
    a.bodies.push_back({shape, point2(poses[b].apply(g.coms[b])), Q(1), Q(1), w.x, w.y, Q(0)});
  }
  std::vector<long> obstacle(g.obstacles.size(), -1);  // its index in the assembly, once a contact names it
  for (const Contact<T>& c : contacts) {
    Party from{Party::Kind::kBody, static_cast<std::size_t>(c.other)};
    if (c.kind == ContactKind::kBodyVertex || c.kind == ContactKind::kObstacleVertex) {
      long& index = obstacle[static_cast<std::size_t>(c.other)];
      if (index < 0) {
        index = static_cast<long>(a.obstacles.size());
        geometry::PolygonShape shape;
        for (const Vec2<T>& p : g.obstacles[static_cast<std::size_t>(c.other)]) shape.vertices.push_back(point2(p));
        a.obstacles.push_back(shape);
      }
      from = {Party::Kind::kObstacle, static_cast<std::size_t>(index)};
    }
    if (c.kind == ContactKind::kFinger) {
      const FingerCommand<T>& cmd = commands[static_cast<std::size_t>(c.other)];
      from = {Party::Kind::kFinger, a.fingers.size()};
      a.fingers.push_back({point2(c.point), true, cmd.force, point2(cmd.value)});
    }
    const Q mu = rational(c.mu);
    a.contacts.push_back(
        {from, {Party::Kind::kBody, static_cast<std::size_t>(c.which)}, point2(c.point), point2(c.normal), mu, mu});
  }
  return a;
}

ucp::UcpProblem assembly_step_problem(const geometry::Assembly& a) {
  ucp::UcpProblem problem;
  problem.quasistatic = assembly::assembly_quasistatic(a);
  problem.set(ucp::build_ucp(*problem.quasistatic));
  return problem;
}

nlohmann::ordered_json assembly_scene_json(const geometry::Assembly& a) {
  nlohmann::ordered_json bodies = nlohmann::ordered_json::array(), obstacles = nlohmann::ordered_json::array(),
                         fingers = nlohmann::ordered_json::array(), contacts = nlohmann::ordered_json::array();
  for (const geometry::Body& b : a.bodies)
    bodies.push_back(
        {{"shape", polygon(b.shape)},
         {"com", pair(b.com)},
         {"load", nlohmann::ordered_json::array({text(b.load_fx), text(b.load_fy), text(b.load_torque)})}});
  for (const geometry::Shape& o : a.obstacles) obstacles.push_back({{"shape", polygon(o)}});
  for (const geometry::Finger& f : a.fingers)
    fingers.push_back({{"position", pair(f.position)},
                       {"axes", f.world_axes ? "world" : "frame"},
                       {f.force_controlled ? "force" : "velocity", pair(f.given)}});
  for (const geometry::AssemblyContact& c : a.contacts)
    contacts.push_back({{"from", party(c.from)},
                        {"to", party(c.to)},
                        {"point", pair(c.point)},
                        {"normal", pair(c.normal)},
                        {"mu", text(c.mu_s)}});
  return {{"kind", "quasistatic_scene"},
          {"bodies", bodies},
          {"obstacles", obstacles},
          {"fingers", fingers},
          {"contacts", contacts}};
}

#define CONTACTCERT_MOTION_STEP_INST(T)                                                                               \
  template geometry::Assembly step_assembly<T>(const SceneGeometry<T>&, const Poses<T>&,                              \
                                               const std::vector<Contact<T>>&, const std::vector<FingerCommand<T>>&); \
  template ucp::UcpProblem step_problem<T>(const SceneGeometry<T>&, const Pose<T>&, const std::vector<Contact<T>>&,   \
                                           const std::vector<FingerCommand<T>>&, const std::string&);
CONTACTCERT_MOTION_STEP_INST(Q)
CONTACTCERT_MOTION_STEP_INST(double)
#undef CONTACTCERT_MOTION_STEP_INST

}  // namespace contactcert::solvers::motion
