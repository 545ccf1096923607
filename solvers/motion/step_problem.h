// The quasistatic problem of one step: the body at its pose with the contacts found there, built as the scene
// builder builds a `"kind": "quasistatic_scene"` file (docs/formats.md section 2), so each step's problem and
// certificate are those `contactcert ucp` and `check` read. Several bodies: the step's assembly
// (geometry/assembly.h) built directly, its problem by solvers/assembly (the one `contactcert assembly --ucp`
// solves), and the assembly written as its scene file for the certificate, whose checker re-derives the problem.
#pragma once

#include <string>
#include <vector>

#include "geometry/assembly.h"
#include "solvers/motion/contacts.h"
#include "solvers/ucp/problem.h"

namespace contactcert::solvers::motion {

/// A finger's command during a step, world axes: a velocity, or a force.
template <class T>
struct FingerCommand {
  bool force = false;
  Vec2<T> value;
};

/// The step's problem of one body: the workpiece's com at `pose`, its weight, and per contact its point, normal and mu;
/// a finger contact carries its command in world axes. Built as the scene builder builds a `quasistatic_scene` file
/// (ucp::quasistatic_of_contacts), each contact's frame taken as written: the contacts are found exactly on the exact
/// paths (a point strictly inside an edge, the normal the edge's perpendicular, the shapes apart at every recorded
/// pose), so geometry::frame_of would only confirm them; the float path's rounded points lie near, not on, the
/// boundary. A double is taken as the rational it is. Throws exact::InputError (naming `name`) if it is refused.
template <class T>
ucp::UcpProblem step_problem(const SceneGeometry<T>& g, const Pose<T>& pose, const std::vector<Contact<T>>& contacts,
                             const std::vector<FingerCommand<T>>& commands, const std::string& name);

/// The step's assembly of several bodies: each body at its pose (world vertices, com, its weight as the load), the
/// obstacles in contact (in the order of their first contact: the assembly's reader refuses overlapping obstacles,
/// so obstacles that overlap and both touch a body make a certificate `check` refuses), each touching finger (world
/// axes, its command; in the order of its contact), and per contact its parties (`from` the obstacle, other body or
/// finger, `to` the body `which`), point, normal and mu. A double is taken as the rational it is.
template <class T>
geometry::Assembly step_assembly(const SceneGeometry<T>& g, const Poses<T>& poses,
                                 const std::vector<Contact<T>>& contacts,
                                 const std::vector<FingerCommand<T>>& commands);

/// The problem of a step assembly (solvers/assembly/assembly_ucp.h); the float path's rounded points lie near, not
/// on, the boundaries, and nothing re-checks them here.
ucp::UcpProblem assembly_step_problem(const geometry::Assembly& a);

/// The assembly as a `"kind": "quasistatic_scene"` file with `bodies` (docs/formats.md section 3a; each body's
/// `load` given): the text a certificate embeds, from which `check` re-derives the problem and verifies every
/// contact frame.
nlohmann::ordered_json assembly_scene_json(const geometry::Assembly& a);

#define CONTACTCERT_MOTION_STEP_EXTERN(T)                                                                              \
  extern template geometry::Assembly step_assembly<T>(                                                                 \
      const SceneGeometry<T>&, const Poses<T>&, const std::vector<Contact<T>>&, const std::vector<FingerCommand<T>>&); \
  extern template ucp::UcpProblem step_problem<T>(const SceneGeometry<T>&, const Pose<T>&,                             \
                                                  const std::vector<Contact<T>>&,                                      \
                                                  const std::vector<FingerCommand<T>>&, const std::string&);
CONTACTCERT_MOTION_STEP_EXTERN(Q)
CONTACTCERT_MOTION_STEP_EXTERN(double)
#undef CONTACTCERT_MOTION_STEP_EXTERN

}  // namespace contactcert::solvers::motion
