// Strong stability of a fixtured workpiece under one external wrench (wrench cone paper, section 7;
// SPEC section 7): from rest, touching fixels only,
//   strongly_stable: every solution of the rigid-body model has zero workpiece acceleration;
//   weakly_stable:   some solution has zero acceleration and some has not;
//   unstable:        no solution has zero acceleration.
// A zero-acceleration solution is a c in the static friction cones with J c + g = 0 (one LP). A moving
// solution lies in some mode other than n..n (each has a strict row, so vdot != 0), or in n..n with
// vdot != 0 in the null space of J^T; the latter cannot coexist with a zero-acceleration solution (vdot is
// the same for every all-rolling solution), so only the 4^k - 1 other modes need a proof.
#pragma once

#include <string>
#include <vector>

#include "exact/arith.h"
#include "geometry/planar_scene.h"
#include "solvers/stability/motion_system.h"

namespace contactcert::solvers {

enum class StabilityVerdict { kStronglyStable, kWeaklyStable, kUnstable };
const char* verdict_name(StabilityVerdict v);

/// Why one moving mode admits no solution: a Motzkin certificate of its system (motion_system.h); when
/// `kinematic`, the certificate lives on the kinematic rows only (zero elsewhere) and holds for every g.
template <class T>
struct ModeProof {
  ModeString mode;
  bool kinematic = false;
  Vec<T> motzkin;
};

/// A solution of the model: its mode, contact forces (c_1n..c_kn, c_1t..c_kt) and acceleration vdot.
template <class T>
struct MotionWitness {
  ModeString mode;
  Vec<T> forces;
  Vec<T> acceleration;
};

template <class T>
struct StabilityResult {
  StabilityVerdict verdict = StabilityVerdict::kUnstable;
  std::vector<Eigen::Index> touching;  ///< indices of the touching fixels (the scene's order)
  bool has_resting = false;
  Vec<T> resting_forces;               ///< a zero-acceleration solution (J c + g = 0), if has_resting
  Vec<T> resting_farkas;               ///< unstable: Motzkin certificate that no resting solution exists
  bool has_moving = false;
  MotionWitness<T> moving;             ///< a moving solution, if has_moving
  std::vector<ModeProof<T>> proofs;    ///< strongly stable: one proof per moving mode (4^k - 1)
  long lps = 0;
  long modes_checked = 0;
  long modes_kinematically_feasible = 0;
};

struct StabilityOptions {
  exact::Arith arith = exact::Arith::kVerified;
  long max_modes = 1 << 16;  ///< budget on 4^k (k touching fixels); beyond it BudgetExceeded
};

/// The scene restricted to its touching fixels (stability considers only those).
geometry::PlanarScene touching_scene(const geometry::PlanarScene& scene, std::vector<Eigen::Index>* kept = nullptr);

/// All mode strings over {s, l, r, n}^k except n..n, in a fixed order.
std::vector<ModeString> moving_modes(std::size_t k);

/// The verdict for wrench g = (f_x, f_y, torque about the com), with witness or certificate.
template <class T>
StabilityResult<T> strong_stability(const geometry::PlanarScene& scene, const Vec<T>& g,
                                    const StabilityOptions& options = {});

/// Independent exact check of a verdict's evidence against the scene and g (re-derives every system).
/// Returns an empty string if valid, else the reason.
std::string check_stability(const geometry::PlanarScene& scene, const Vec<Q>& g, const StabilityResult<Q>& claim);

extern template StabilityResult<double> strong_stability<double>(const geometry::PlanarScene&, const Vec<double>&,
                                                                 const StabilityOptions&);
extern template StabilityResult<Q> strong_stability<Q>(const geometry::PlanarScene&, const Vec<Q>&,
                                                       const StabilityOptions&);

}  // namespace contactcert::solvers
