// Sensorless insertion (wrench cone paper, sections 8-9): the wrenches G_goal that seat the workpiece
// against all fixels from any contact state, as the complement of the union of the wrench cones of the
// backward and self transitions: eq. (21) for two fixels, Table 5 for three.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geometry/face_cone.h"
#include "geometry/nnc_cone.h"
#include "solvers/stability/finger_push.h"
#include "solvers/wrench_cone/wrench_cone.h"

namespace contactcert::solvers {

/// One set of eq. (21) / Table 5: the contact state (touching[i]: contact achieved at fixel i) and the
/// augmented mode whose wrenches must be avoided in that state.
struct InsertionSet {
  std::vector<bool> state;
  ModeString mode;
  std::string state_text() const;  ///< e.g. "110"
};

/// eq. (21) for 2 fixels (su, ms in state 10; us, sm in state 01) and Table 5 for 3 fixels.
std::vector<InsertionSet> insertion_sets(std::size_t fixels);

template <class T>
struct Insertion {
  std::vector<InsertionSet> sets;
  std::vector<geometry::FaceCone<T>> cones;  ///< G of each set (empty-cone encoding when empty)
  std::vector<bool> redundant;  ///< contained in another set's cone (exactly checked); empty until find_redundant
  std::vector<std::optional<geometry::NncForm<T>>> forms;  ///< nnc_form of a non-empty cone, where already known
  bool in_goal(const Vec<T>& g) const;                     ///< g in G_goal: in no set's cone
};

/// Fills ins.redundant: a cone is redundant when it is empty or contained in another cone not already redundant
/// (the union, hence G_goal, stays the same without it).
template <class T>
void find_redundant(Insertion<T>& ins);

/// Whether insertion() runs the containment pass (Insertion::redundant) or leaves it to find_redundant (in_goal
/// reads every cone, so it needs none).
enum class Redundancy { kFound, kDeferred };

/// The scene in contact state `touching` (frames of the goal configuration; fixels not in contact get
/// a positive gap).
geometry::PlanarScene scene_in_state(const geometry::PlanarScene& goal, const std::vector<bool>& touching);

/// The cones of sets whose mode leaves a fixel unconstrained ('u': it takes no part in the cone), kept across
/// goal scenes of one workpiece, so that placements sharing the other fixels share them: keyed by the set, the
/// route and the frames and friction of the fixels that take part; at most `capacity` kept, all dropped when full.
/// A set's cone G and, when G is not the empty-cone encoding, its nnc_form (for the containment tests).
template <class T>
struct SetCone {
  geometry::FaceCone<T> cone;
  std::optional<geometry::NncForm<T>> form;
};

template <class T>
class InsertionCones {
 public:
  explicit InsertionCones(std::size_t capacity = 4096) : capacity_(capacity) {}
  /// G of `set`, number `index` of insertion_sets(goal.fixels.size()), in the goal scene `goal`.
  const SetCone<T>& cone(const geometry::PlanarScene& goal, std::size_t index, const InsertionSet& set, Route route);

 private:
  std::size_t capacity_;
  std::map<std::vector<Q>, SetCone<T>> cones_;
};

/// G_goal for a goal scene in which every fixel touches (2 or 3 fixels). Throws InputError otherwise. With
/// `cones`, the cones of sets that leave a fixel unconstrained come from there.
template <class T>
Insertion<T> insertion(const geometry::PlanarScene& goal, Route route = Route::kPaper,
                       InsertionCones<T>* cones = nullptr, Redundancy redundancy = Redundancy::kFound);

/// Frictionless finger pushes along the boundary that lie in G_goal (Figure 10).
template <class T>
BoundaryPieces<T, bool> insertion_pushes(const geometry::PlanarScene& goal, const Insertion<T>& ins);

#define CONTACTCERT_INSERTION_EXTERN(T)                                                                           \
  extern template struct Insertion<T>;                                                                            \
  extern template class InsertionCones<T>;                                                                        \
  extern template void find_redundant<T>(Insertion<T>&);                                                          \
  extern template Insertion<T> insertion<T>(const geometry::PlanarScene&, Route, InsertionCones<T>*, Redundancy); \
  extern template BoundaryPieces<T, bool> insertion_pushes<T>(const geometry::PlanarScene&, const Insertion<T>&);
CONTACTCERT_INSERTION_EXTERN(double)
CONTACTCERT_INSERTION_EXTERN(Q)
#undef CONTACTCERT_INSERTION_EXTERN

}  // namespace contactcert::solvers
