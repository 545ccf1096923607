// Quasistatic time-stepping of one or several movable bodies (docs/motion.md): at each step the contacts of the
// current poses are found exactly, the quasistatic problem of those contacts is solved by the complete method
// (solvers/ucp; several bodies: the assembly's problem, solvers/assembly), and each body moves by the exact rigid
// motion of its twist in the solution (geometry/rigid_motion.h), cut at the first contact that closes during the
// step. One algorithm over T: Q (exact and verified paths) or double (float path).
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "solvers/motion/contacts.h"
#include "solvers/motion/uniqueness.h"
#include "solvers/ucp/solve.h"

namespace contactcert::solvers::motion {

/// How a run ended: all steps done; jammed (a proof, at the last step); no contact left to hold the body; a
/// vertex-on-vertex contact (normal not determined); two shapes overlap after a step (a maintained contact the
/// translation correction cannot keep dips, keep_contacts.h); a contact closes at an irrational time (rational poses
/// cannot reach it: the last step ends at a rational time just before it, the gap > 0); unknown (a solver budget or the
/// time limit).
enum class RunStatus {
  kCompleted,
  kJammed,
  kNoContact,
  kUnsupportedContact,
  kOverlap,
  kIrrationalContactTime,
  kUnknown
};
const char* run_status_name(RunStatus s);

struct SimulateOptions {
  /// kExact: exact geometry and exact LPs; kVerified (default): exact geometry, the UCP's verified path;
  /// kFloat: doubles throughout (geometry with the float sign tolerance, the UCP's float path), nothing proven.
  exact::Arith arith = exact::Arith::kVerified;
  std::optional<long> steps;             ///< N, overriding the scene's
  std::optional<Q> dt;                   ///< H, overriding the scene's
  bool uniqueness = true;                ///< decide per step whether the motion is unique (exact paths)
  long max_uniqueness_modes = 1L << 12;  ///< the uniqueness prefix tree's LP budget: past it, `unknown`
  bool certificates = true;              ///< keep each step's UCP certificate text (exact paths)
  /// Seconds of wall clock for the whole run (0 = none): then `unknown`, with the steps done so far. Each step's
  /// solve gets what is left (UcpOptions::time_limit).
  double time_limit = 0;
  ucp::UcpOptions ucp;  ///< method, seed, budgets (its arith is set from `arith`)
};

/// A contact of a step: its name (contacts.h), mode (s separate, r roll, + / - slide along +t / -t, t = n turned
/// by +90 degrees; '?' no solution), point, inward normal (as written, non-unit) and the force's components c_n, c_t
/// along n and t (not unit either).
template <class T>
struct ContactRecord {
  std::string name;
  char mode = 's';
  Vec2<T> point, normal;
  T c_n = T(0), c_t = T(0);
  /// The force c_n n + c_t t on its body (`which`), made only when it is reported (zero without a solution: c_n and
  /// c_t stay 0).
  Vec2<T> force() const {
    const Vec2<T> t = geometry::perp2(normal);
    return {c_n * normal.x + c_t * t.x, c_n * normal.y + c_t * t.y};
  }
};

/// One step: the problem at `poses` (time `time`), its verdict and certificate, the twists, the motion over `h`.
template <class T>
struct StepRecord {
  long index = 0;
  T time = T(0), h = T(0);
  /// What cut the step short (empty: a full step): the contact that closed, a finger reaching a body vertex, or
  /// "schedule change of finger NAME".
  std::string cut_by;
  bool cut_exact = true;        ///< false: the closing time is irrational; h is a rational time just before it
  Poses<T> poses, poses_after;  ///< per body
  std::vector<Vec2<T>> tips_after;
  std::vector<ContactRecord<T>> contacts;
  std::vector<std::string> made, broken;  ///< contacts new at this step, and gone since the previous one
  ucp::UcpStatus verdict = ucp::UcpStatus::kUnknown;
  std::string reason;
  /// Per body its q_dot: the velocity v of the body point at the world origin, and omega.
  std::vector<Twist<T>> twists;
  /// Per body the twist the step applies: (v, omega) itself when omega = 0; turning, a rotation about a rolling
  /// obstacle contact's point (exactly the instantaneous centre) or else about the instantaneous centre, by the Cayley
  /// parameter that brings the pose's tan(theta / 2) after a full step to its exact value if that takes at most 128
  /// bits, else to the nearest multiple of 2^-40 (the centre likewise): exact where cheap, and the pose's numbers
  /// stay bounded (exact paths). The float path applies (v, omega).
  std::vector<Twist<T>> applied;
  /// "ucp_solvable" / "ucp_jammed" (exact paths; several bodies: with the step's assembly embedded)
  std::string certificate;
  std::optional<MotionUniqueness> uniqueness;
  /// "motion_uniqueness" of a decided uniqueness (exact paths, with certificates; uniqueness_certificate.h), or ""
  std::string uniqueness_certificate;
  double seconds = 0;
};

/// A whole run: its steps, how it ended and the final state.
template <class T>
struct Trajectory {
  RunStatus status = RunStatus::kCompleted;
  std::string reason;
  std::vector<StepRecord<T>> steps;
  Poses<T> final_poses;
  T final_time = T(0);
  std::vector<Vec2<T>> final_tips;
  double seconds = 0;
};

/// A run in progress, one step at a time (a planner may stop early): trajectory() holds the steps made and the
/// state after them. T = Q: the exact or verified path (opts.arith kExact or kVerified; kFloat is taken as
/// kVerified); T = double: the float path, whatever opts.arith says. The time limit counts from construction.
template <class T>
class Stepper {
 public:
  Stepper(MotionScene scene, const SimulateOptions& opts);
  /// Makes the next step (appended to trajectory().steps); false once the run has ended (its status says how).
  bool step();
  const Trajectory<T>& trajectory() const { return out_; }
  Trajectory<T> take() { return std::move(out_); }

 private:
  void finish(RunStatus s, std::string why);
  MotionScene scene_;
  SimulateOptions opts_;
  SceneGeometry<T> g_;
  T H_;
  long N_;
  ucp::UcpOptions uopts_;
  std::chrono::steady_clock::time_point start_;
  std::vector<std::string> previous_;  ///< the contacts of the last step
  /// Exact paths: a carried finger's tip in the frame of the body carrying it (that body's index), kept while it stays.
  std::vector<std::optional<std::pair<int, Vec2<T>>>> tips_in_body_;
  bool ended_ = false;
  Trajectory<T> out_;     ///< final_pose, final_time, final_tips: the state now
  WorldBodies<T> world_;  ///< the bodies' vertices at out_.final_poses
};

/// Runs the scene for N steps (or until the run ends): a Stepper stepped to its end.
template <class T>
Trajectory<T> simulate(const MotionScene& scene, const SimulateOptions& opts);

extern template class Stepper<Q>;
extern template class Stepper<double>;
extern template Trajectory<Q> simulate<Q>(const MotionScene&, const SimulateOptions&);
extern template Trajectory<double> simulate<double>(const MotionScene&, const SimulateOptions&);

}  // namespace contactcert::solvers::motion
