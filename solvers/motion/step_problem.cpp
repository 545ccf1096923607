#include "solvers/motion/step_problem.h"

#include <nlohmann/json.hpp>

#include "exact/rational_text.h"

namespace contactcert::solvers::motion {
namespace {

std::string text(const Q& x) { return exact::to_string(x); }
std::string text(double x) { return exact::to_string(Q(x)); }

template <class T>
nlohmann::ordered_json pair(const Vec2<T>& p) {
  return nlohmann::ordered_json::array({text(p.x), text(p.y)});
}

/// The frame as the step scene writes it.
geometry::FrameResult frame_as_written(const geometry::Shape&, const geometry::FrameInput& given) {
  return {geometry::FrameStatus::kOk, {given.point, given.normal, Q(0)}, ""};
}

}  // namespace

template <class T>
nlohmann::ordered_json step_scene(const SceneGeometry<T>& g, const Pose<T>& pose,
                                  const std::vector<Contact<T>>& contacts,
                                  const std::vector<FingerCommand<T>>& commands) {
  nlohmann::ordered_json vertices = nlohmann::ordered_json::array();
  for (const Vec2<T>& p : g.body) vertices.push_back(pair(pose.apply(p)));
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const Contact<T>& c : contacts) {
    nlohmann::ordered_json j{
        {"name", c.name}, {"point", pair(c.point)}, {"normal", pair(c.normal)}, {"mu", text(c.mu)}};
    if (c.kind == ContactKind::kFinger) {
      const FingerCommand<T>& cmd = commands[static_cast<std::size_t>(c.other)];
      j["finger"] = {{"axes", "world"}, {cmd.force ? "force" : "velocity", pair(cmd.value)}};
    }
    list.push_back(j);
  }
  return {{"kind", "quasistatic_scene"},
          {"workpiece", {{"shape", {{"type", "polygon"}, {"vertices", vertices}}}, {"com", pair(pose.apply(g.com))}}},
          {"gravity", pair(g.gravity)},
          {"contacts", list}};
}

ucp::UcpProblem step_problem(const nlohmann::ordered_json& scene, const std::string& name) {
  const exact::JsonInput in = exact::JsonInput::parse(exact::json_text(scene), name);
  return ucp::read_ucp_problem(in, nullptr, frame_as_written);
}

template nlohmann::ordered_json step_scene<Q>(const SceneGeometry<Q>&, const Pose<Q>&, const std::vector<Contact<Q>>&,
                                              const std::vector<FingerCommand<Q>>&);
template nlohmann::ordered_json step_scene<double>(const SceneGeometry<double>&, const Pose<double>&,
                                                   const std::vector<Contact<double>>&,
                                                   const std::vector<FingerCommand<double>>&);

}  // namespace contactcert::solvers::motion
