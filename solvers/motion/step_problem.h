// The quasistatic problem of one step: the body at its pose with the contacts found there, written as a
// `"kind": "quasistatic_scene"` file (docs/formats.md section 2) and built by the existing scene builder, so each
// step's problem and certificate are those `contactcert ucp` and `check` read.
#pragma once

#include <string>
#include <vector>

#include "solvers/motion/contacts.h"
#include "solvers/ucp/problem.h"

namespace contactcert::solvers::motion {

/// A finger's command during a step, world axes: a velocity, or a force.
template <class T>
struct FingerCommand {
  bool force = false;
  Vec2<T> value;
};

/// The step's scene: the workpiece at `pose` (world vertices and com), gravity, and per contact its point, normal
/// and mu; a finger contact carries its command ("axes": "world"). Numbers are exact strings (a double is written
/// as the rational it is).
template <class T>
nlohmann::ordered_json step_scene(const SceneGeometry<T>& g, const Pose<T>& pose,
                                  const std::vector<Contact<T>>& contacts,
                                  const std::vector<FingerCommand<T>>& commands);

/// The problem of a step scene, each contact's frame taken as written: the contacts are found exactly on the exact
/// paths (a point strictly inside an edge, the normal the edge's perpendicular, the shapes apart at every recorded
/// pose), so geometry::frame_of would only confirm them (about a tenth of a turning step); the float path's
/// rounded points lie near, not on, the boundary. Throws exact::InputError if the scene is refused.
ucp::UcpProblem step_problem(const nlohmann::ordered_json& scene, const std::string& name);

extern template nlohmann::ordered_json step_scene<Q>(const SceneGeometry<Q>&, const Pose<Q>&,
                                                     const std::vector<Contact<Q>>&,
                                                     const std::vector<FingerCommand<Q>>&);
extern template nlohmann::ordered_json step_scene<double>(const SceneGeometry<double>&, const Pose<double>&,
                                                          const std::vector<Contact<double>>&,
                                                          const std::vector<FingerCommand<double>>&);

}  // namespace contactcert::solvers::motion
