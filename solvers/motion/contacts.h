// The contacts of a pose, found from geometry (gap exactly 0), the exact overlap test of convex shapes, and the
// first contact that closes during a step of a constant twist (first_root.h), written once over T (Q or double).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "exact/interval_number.h"
#include "exact/nearest_double.h"
#include "geometry/rigid_motion.h"
#include "solvers/motion/motion_scene.h"

namespace contactcert::solvers::motion {

using geometry::Pose;
using geometry::Vec2;

/// An exact scene number in the run's number type: itself for Q, its nearest double for the float run.
template <class T>
T from_q(const Q& q) {
  if constexpr (std::is_same_v<T, Q>)
    return q;
  else
    return exact::nearest_double(q);
}

/// The scene's shapes in T: each body's vertices in its own frame (the world frame at time 0), com, weight, name and
/// edge friction; obstacles and friction coefficients.
template <class T>
struct SceneGeometry {
  std::vector<std::vector<Vec2<T>>> bodies;
  std::vector<Vec2<T>> coms, weights;
  std::vector<T> body_mu;
  std::vector<std::vector<Vec2<T>>> obstacles;
  /// On the exact paths the interval enclosures of the obstacles' vertices (exact/interval_number.h), from which most
  /// sign tests are taken without rationals; empty for double.
  std::vector<std::vector<Vec2<exact::Interval>>> obstacles_enclosed;
  std::vector<T> obstacle_mu, finger_mu;
  std::vector<std::string> body_names, obstacle_names, finger_names;
};

/// The pose of every body (world = R body + t), in the scene's order.
template <class T>
using Poses = std::vector<Pose<T>>;

/// A body's planar velocity: v of the body point at the world origin, and omega (ucp's q_dot block).
template <class T>
struct Twist {
  Vec2<T> v{T(0), T(0)};
  T omega = T(0);
};

/// The scene in T (Q: as read; double: each number rounded).
template <class T>
SceneGeometry<T> scene_geometry(const MotionScene& scene);

/// Which features touch: a body vertex on an obstacle edge, an obstacle vertex on a body edge, a finger tip on a
/// body edge, a body vertex on another body's edge (each strictly inside the edge's segment).
enum class ContactKind { kBodyVertex, kObstacleVertex, kFinger, kBodyBody };

/// One contact at a pose: its features, the world point and the inward normal of the body `which` (non-unit: the
/// obstacle's or other body's edge's outward normal, or the body edge's inward one), and mu. The force c_n n + c_t t
/// acts on `which`, its opposite on the other party.
template <class T>
struct Contact {
  ContactKind kind = ContactKind::kBodyVertex;
  int body = -1;         ///< body vertex (kBodyVertex, kBodyBody) or body edge
  int other = -1;        ///< obstacle, finger or the other body (kBodyBody)
  int other_index = -1;  ///< obstacle edge (kBodyVertex), obstacle vertex (kObstacleVertex), other body's edge
  int which = 0;         ///< the body (index into SceneGeometry::bodies)
  Vec2<T> point, normal;
  T mu;
  /// "body vertex 1 on floor edge 2", "floor vertex 0 on body edge 3", "finger pusher on body edge 3", "box 2
  /// vertex 0 on box 1 edge 1" (a body's name for "body" with several): also the identity of a contact from step to
  /// step.
  std::string name;
};

/// The contacts at a pose; `unsupported` names a vertex-on-vertex contact (its normal is not determined), else empty.
template <class T>
struct ContactSet {
  std::vector<Contact<T>> contacts;
  std::string unsupported;
};

/// Each body's vertices in the world at its pose (geometry::apply_all) and on the exact paths their enclosures, made
/// once per pose and shared by the contact search, the closing times and the overlap test.
template <class T>
struct WorldBodies {
  std::vector<std::vector<Vec2<T>>> vertices;
  std::vector<std::vector<Vec2<exact::Interval>>> enclosed;  ///< empty for double
};

/// An exact point's enclosure (exact::enclose of each coordinate: the filters' cheap interval).
Vec2<exact::Interval> enclose(const Vec2<Q>& p);

template <class T>
WorldBodies<T> world_bodies(const SceneGeometry<T>& g, const Poses<T>& poses);

/// The contacts of the bodies (vertices `world`) with the obstacles, each other and the finger tips `tips`: per body
/// its obstacle contacts, then its contacts with the later bodies (its vertices on their edges, theirs on its), then
/// the fingers'.
template <class T>
ContactSet<T> find_contacts(const SceneGeometry<T>& g, const WorldBodies<T>& world, const std::vector<Vec2<T>>& tips);

/// Whether two shapes overlap (their interiors meet; a finger tip strictly inside a body): names the pair, else
/// empty. Convex polygons are disjoint iff an edge of one has the other on its closed outer side.
template <class T>
std::string overlap(const SceneGeometry<T>& g, const WorldBodies<T>& world, const std::vector<Vec2<T>>& tips);
/// The same at `poses`.
template <class T>
std::string overlap(const SceneGeometry<T>& g, const Poses<T>& poses, const std::vector<Vec2<T>>& tips);

/// A contact that closes during a step: the time from the step's start and whether it is exact (else a rational
/// time just before the irrational one, the gap still > 0).
template <class T>
struct ClosingContact {
  T tau;
  bool exact = true;
  std::string name;
};

/// The first contact, not touching at the start, that closes in (0, H] while each body b moves by its twist
/// twists[b] (geometry::twist_step) and every finger i with free_velocity[i] moves by it (nullopt: the finger is
/// carried with a body or holds still), the bodies' vertices at the start being `world`. Candidates: each body vertex
/// against each obstacle edge, each obstacle vertex against each body edge, each moving finger tip against each body
/// edge, whose gap (times 1 + u^2) is a polynomial of degree <= 3 in the time, and each vertex of a body against each
/// edge of another, whose gap (times the positive (1 + u_a^2)(1 + u_b^2)^2) is one of degree <= 6; with the point on
/// the edge's segment at the root.
template <class T>
std::optional<ClosingContact<T>> first_closing(const SceneGeometry<T>& g, const WorldBodies<T>& world,
                                               const std::vector<Vec2<T>>& tips, const std::vector<Twist<T>>& twists,
                                               const std::vector<std::optional<Vec2<T>>>& free_velocity, const T& H);

#define CONTACTCERT_MOTION_CONTACTS_EXTERN(T)                                                                          \
  extern template SceneGeometry<T> scene_geometry<T>(const MotionScene&);                                              \
  extern template WorldBodies<T> world_bodies<T>(const SceneGeometry<T>&, const Poses<T>&);                            \
  extern template ContactSet<T> find_contacts<T>(const SceneGeometry<T>&, const WorldBodies<T>&,                       \
                                                 const std::vector<Vec2<T>>&);                                         \
  extern template std::string overlap<T>(const SceneGeometry<T>&, const WorldBodies<T>&, const std::vector<Vec2<T>>&); \
  extern template std::string overlap<T>(const SceneGeometry<T>&, const Poses<T>&, const std::vector<Vec2<T>>&);       \
  extern template std::optional<ClosingContact<T>> first_closing<T>(                                                   \
      const SceneGeometry<T>&, const WorldBodies<T>&, const std::vector<Vec2<T>>&, const std::vector<Twist<T>>&,       \
      const std::vector<std::optional<Vec2<T>>>&, const T&);
CONTACTCERT_MOTION_CONTACTS_EXTERN(Q)
CONTACTCERT_MOTION_CONTACTS_EXTERN(double)
#undef CONTACTCERT_MOTION_CONTACTS_EXTERN

}  // namespace contactcert::solvers::motion
