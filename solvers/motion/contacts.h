// The contacts of a pose, found from geometry (gap exactly 0), the exact overlap test of convex shapes, and the
// first contact that closes during a step of a constant twist (first_root.h), written once over T (Q or double).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/rigid_motion.h"
#include "solvers/motion/motion_scene.h"

namespace contactcert::solvers::motion {

using geometry::Pose;
using geometry::Vec2;

/// q rounded to the nearest double (GMP's get_d truncates: 1/10 would become 0.09999999999999999).
double nearest_double(const Q& q);

/// An exact scene number in the run's number type: itself for Q, its nearest double for the float run.
template <class T>
T from_q(const Q& q) {
  if constexpr (std::is_same_v<T, Q>)
    return q;
  else
    return nearest_double(q);
}

/// The scene's shapes in T: the body's vertices in its own frame (the world frame at time 0), obstacles and
/// friction coefficients.
template <class T>
struct SceneGeometry {
  std::vector<Vec2<T>> body;
  Vec2<T> com, gravity;
  std::vector<std::vector<Vec2<T>>> obstacles;
  std::vector<T> obstacle_mu, finger_mu;
  std::vector<std::string> obstacle_names, finger_names;
};

/// The scene in T (Q: as read; double: each number rounded).
template <class T>
SceneGeometry<T> scene_geometry(const MotionScene& scene);

/// Which features touch: a body vertex on an obstacle edge, an obstacle vertex on a body edge, a finger tip on a
/// body edge (each strictly inside the edge's segment).
enum class ContactKind { kBodyVertex, kObstacleVertex, kFinger };

/// One contact at a pose: its features, the world point and the inward normal of the body (non-unit: the
/// obstacle edge's outward normal, or the body edge's inward one), and mu.
template <class T>
struct Contact {
  ContactKind kind = ContactKind::kBodyVertex;
  int body = -1;         ///< body vertex (kBodyVertex) or body edge
  int other = -1;        ///< obstacle or finger
  int other_index = -1;  ///< obstacle edge (kBodyVertex) or obstacle vertex (kObstacleVertex)
  Vec2<T> point, normal;
  T mu;
  /// "body vertex 1 on floor edge 2", "floor vertex 0 on body edge 3", "finger pusher on body edge 3": also the
  /// identity of a contact from step to step.
  std::string name;
};

/// The contacts at a pose; `unsupported` names a vertex-on-vertex contact (its normal is not determined), else empty.
template <class T>
struct ContactSet {
  std::vector<Contact<T>> contacts;
  std::string unsupported;
};

/// The contacts of the body at `pose` with the obstacles and the finger tips `tips`.
template <class T>
ContactSet<T> find_contacts(const SceneGeometry<T>& g, const Pose<T>& pose, const std::vector<Vec2<T>>& tips);

/// Whether two shapes overlap (their interiors meet; a finger tip strictly inside the body): names the pair, else
/// empty. Convex polygons are disjoint iff an edge of one has the other on its closed outer side.
template <class T>
std::string overlap(const SceneGeometry<T>& g, const Pose<T>& pose, const std::vector<Vec2<T>>& tips);

/// A contact that closes during a step: the time from the step's start and whether it is exact (else a rational
/// time just before the irrational one, the gap still > 0).
template <class T>
struct ClosingContact {
  T tau;
  bool exact = true;
  std::string name;
};

/// The first contact, not touching at the start, that closes in (0, H] while the body moves by the twist
/// (v, omega) (geometry::twist_step) and every finger i with free_velocity[i] moves by it (nullopt: the finger is
/// carried with the body or holds still). Candidates: each body vertex against each obstacle edge, each obstacle
/// vertex against each body edge, each moving finger tip against each body edge, whose gap (times 1 + u^2) is a
/// polynomial of degree <= 3 in the time, with the point on the edge's segment at the root.
template <class T>
std::optional<ClosingContact<T>> first_closing(const SceneGeometry<T>& g, const Pose<T>& pose,
                                               const std::vector<Vec2<T>>& tips, const Vec2<T>& v, const T& omega,
                                               const std::vector<std::optional<Vec2<T>>>& free_velocity, const T& H);

#define CONTACTCERT_MOTION_CONTACTS_EXTERN(T)                                                                   \
  extern template SceneGeometry<T> scene_geometry<T>(const MotionScene&);                                       \
  extern template ContactSet<T> find_contacts<T>(const SceneGeometry<T>&, const Pose<T>&,                       \
                                                 const std::vector<Vec2<T>>&);                                  \
  extern template std::string overlap<T>(const SceneGeometry<T>&, const Pose<T>&, const std::vector<Vec2<T>>&); \
  extern template std::optional<ClosingContact<T>> first_closing<T>(                                            \
      const SceneGeometry<T>&, const Pose<T>&, const std::vector<Vec2<T>>&, const Vec2<T>&, const T&,           \
      const std::vector<std::optional<Vec2<T>>>&, const T&);
CONTACTCERT_MOTION_CONTACTS_EXTERN(Q)
CONTACTCERT_MOTION_CONTACTS_EXTERN(double)
#undef CONTACTCERT_MOTION_CONTACTS_EXTERN

}  // namespace contactcert::solvers::motion
