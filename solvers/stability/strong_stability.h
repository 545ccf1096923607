// Strong stability of a fixtured workpiece under one external wrench (wrench cone paper, section 7;
// SPEC section 7): from rest, touching fixels only,
//   strongly_stable: every solution of the rigid-body model has zero workpiece acceleration;
//   weakly_stable:   some solution has zero acceleration and some has not;
//   unstable:        no solution has zero acceleration.
// A zero-acceleration solution is a c in the static friction cones with J c + g = 0 (one LP). A moving
// solution lies in some mode other than n..n (each has a strict row, so vdot != 0), or in n..n with
// vdot != 0 in the null space of J^T; the latter cannot coexist with a zero-acceleration solution (vdot is
// the same for every all-rolling solution), so only the other modes need a proof. They are not listed one by
// one (4^k - 1 strings): the prefix tree of mode_tree.h finds the kinematically feasible ones, each dead
// prefix with a Motzkin certificate for every mode that extends it, and only the feasible ones get an LP in g.
#pragma once

#include <cassert>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "exact/arith.h"
#include "geometry/planar_scene.h"
#include "solvers/stability/mode_tree.h"
#include "solvers/stability/motion_system.h"
#include "solvers/stability/reused_certificates.h"

namespace contactcert::solvers {

enum class StabilityVerdict { kStronglyStable, kWeaklyStable, kUnstable };
const char* verdict_name(StabilityVerdict v);

/// Why moving modes admit no solution. When `kinematic`, `mode` is a prefix (letters for the first fixels) and
/// `motzkin` a Motzkin certificate of kinematic_system(model, prefix): no mode that extends it is kinematically
/// feasible, for any g. Otherwise `mode` is a whole mode and `motzkin` a certificate of its system for g
/// (motion_system.h).
template <class T>
struct ModeProof {
  ModeString mode;
  bool kinematic = false;
  Vec<T> motzkin;
};

/// The proofs of a strongly stable verdict: the dead prefixes of the mode tree (kinematic), then one proof per
/// kinematically feasible moving mode; together they cover every moving mode (mode_coverage). A kinematic
/// proof holds for every g, so a StabilityOracle finds those once and its verdicts refer to that immutable set
/// (kept alive by shared ownership, also after the oracle is gone) instead of copying it into every result.
template <class T>
class ModeProofs {
 public:
  using Shared = std::shared_ptr<const std::vector<ModeProof<T>>>;
  std::size_t size() const { return slots_.size(); }
  const ModeProof<T>& operator[](std::size_t i) const {
    const std::ptrdiff_t s = slots_[i];
    return s >= 0 ? own_[static_cast<std::size_t>(s)] : (*shared_)[static_cast<std::size_t>(-1 - s)];
  }
  /// Appends a proof of this result's own.
  void push_back(ModeProof<T> p) {
    slots_.push_back(static_cast<std::ptrdiff_t>(own_.size()));
    own_.push_back(std::move(p));
  }
  /// Appends proof j of `set` without copying it. Precondition: every shared proof of one list is from one set.
  void push_shared(const Shared& set, std::size_t j) {
    if (!shared_) shared_ = set;
    assert(shared_ == set);
    slots_.push_back(-1 - static_cast<std::ptrdiff_t>(j));
  }
  /// Room for n proofs, `own` of them this list's own (a growing vector would copy the rational vectors).
  void reserve(std::size_t n, std::size_t own) {
    slots_.reserve(n);
    own_.reserve(own);
  }
  void clear() { *this = ModeProofs(); }

  class const_iterator {
   public:
    const_iterator(const ModeProofs* list, std::size_t i) : list_(list), i_(i) {}
    const ModeProof<T>& operator*() const { return (*list_)[i_]; }
    const ModeProof<T>* operator->() const { return &(*list_)[i_]; }
    const_iterator& operator++() {
      ++i_;
      return *this;
    }
    bool operator==(const const_iterator& o) const { return i_ == o.i_; }

   private:
    const ModeProofs* list_;
    std::size_t i_;
  };
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, size()}; }

 private:
  Shared shared_;
  std::vector<ModeProof<T>> own_;
  std::vector<std::ptrdiff_t> slots_;  ///< >= 0: index in own_; else -1 - index in *shared_
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
  Vec<T> resting_forces;  ///< a zero-acceleration solution (J c + g = 0), if has_resting
  Vec<T> resting_farkas;  ///< unstable: Motzkin certificate that no resting solution exists
  bool has_moving = false;
  MotionWitness<T> moving;  ///< a moving solution, if has_moving
  ModeProofs<T> proofs;     ///< strongly stable: the dead prefixes, then one proof per feasible moving mode
  /// LPs solved (for strong_stability: including the kinematic ones), and systems decided by a reused certificate
  /// instead (each in place of its LP).
  long lps = 0;
  /// Of these, decided by a float LP's rounded answer checked exactly (no rational LP).
  long lps_checked_from_float = 0;
  /// Of these, decided by a certificate of an earlier verdict (StabilityOracle::verdict with ReusedCertificates).
  long lps_reused = 0;
  long modes_checked = 0;                 ///< moving modes whose system in g was solved (n..n included)
  long modes_kinematically_feasible = 0;  ///< feasible moving modes the mode tree found (all, if it finished)
  long tree_nodes = 0;                    ///< prefixes the mode tree visited
  long dead_prefixes = 0;                 ///< prefixes it proved kinematically infeasible
};

struct StabilityOptions {
  exact::Arith arith = exact::Arith::kVerified;
  long max_nodes = 1L << 22;   ///< budget on the prefixes of the mode tree; beyond it BudgetExceeded
  exact::Deadline deadline{};  ///< tested at every prefix; expired: BudgetExceeded
};

/// The scene restricted to its touching fixels (stability considers only those).
geometry::PlanarScene touching_scene(const geometry::PlanarScene& scene, std::vector<Eigen::Index>* kept = nullptr);

/// All 4^k - 1 mode strings over {s, l, r, n}^k except n..n, in a fixed order: a test oracle for small k
/// (k <= 12; larger k throws std::length_error rather than wrap the count).
std::vector<ModeString> moving_modes(std::size_t k);

/// The alphabet of the moving modes of k touching fixels: s l r n each, s strict (SPEC section 5).
ModeAlphabet moving_alphabet(std::size_t k);

/// Strong stability of one scene under many wrenches (a planner's question). Prepared once per scene: the
/// touching fixels, the mode tree (its dead prefixes are g-independent proofs, shared by every verdict) and the
/// motion system and LP (exact::StrictSolver) of each kinematically feasible moving mode. A verdict then solves
/// 1 + (feasible modes visited) LPs.
template <class T>
class StabilityOracle {
 public:
  explicit StabilityOracle(const geometry::PlanarScene& scene, const StabilityOptions& options = {});
  /// The verdict for wrench g, as strong_stability; its lps count only the LPs solved for g.
  StabilityResult<T> verdict(const Vec<T>& g) const;
  /// The same verdict, witnesses and counts for g as verdict(g), for one of many wrenches in a row: a system that a
  /// certificate kept in `reuse` by an earlier verdict proves infeasible for g is decided by that certificate (an
  /// exact dot product, counted in lps and lps_reused) instead of its LP, and the certificates of the LPs solved
  /// are kept there. Exact T only (reuse is a no-op otherwise); a proof may differ from verdict(g)'s, valid alike.
  StabilityResult<T> verdict(const Vec<T>& g, ReusedCertificates<T>& reuse) const;
  /// LPs solved while preparing (the mode tree's), and how many of them were decided by a float LP's rounded
  /// answer checked exactly.
  long preparation_lps() const { return tree_.lps; }
  long preparation_lps_checked_from_float() const { return tree_.lps_checked_from_float; }
  /// The mode tree of the touching fixels (alphabet moving_alphabet(k)): its feasible modes include n..n.
  const ModeTree<T>& mode_tree() const { return tree_; }

 private:
  struct Mode {
    ModeString name;
    MotionSystem<T> ms;
    exact::StrictSolver<T> solver;
  };
  StabilityResult<T> decide_for(const Vec<T>& g, ReusedCertificates<T>* reuse) const;

  std::vector<Eigen::Index> touching_;
  MotionModel<T> model_;  ///< of the touching fixels only
  MotionSystem<T> rest_;
  exact::StrictSolver<T> rest_solver_;
  ModeTree<T> tree_;
  std::vector<Mode> modes_;  ///< the feasible moving modes in tree order, then n..n (moves only if vdot != 0)
  typename ModeProofs<T>::Shared kinematic_proofs_;  ///< the dead prefixes
};

/// The verdict for wrench g = (f_x, f_y, torque about the com), with witness or certificate: the verdict and
/// evidence of StabilityOracle(scene, options).verdict(g), but each moving mode is prepared (its kinematic LP)
/// only when the verdict reaches it, so a verdict with a moving witness prepares no mode after the witness's.
/// Its lps count every LP solved, the kinematic ones included.
template <class T>
StabilityResult<T> strong_stability(const geometry::PlanarScene& scene, const Vec<T>& g,
                                    const StabilityOptions& options = {});

extern template class StabilityOracle<double>;
extern template class StabilityOracle<Q>;
extern template StabilityResult<double> strong_stability<double>(const geometry::PlanarScene&, const Vec<double>&,
                                                                 const StabilityOptions&);
extern template StabilityResult<Q> strong_stability<Q>(const geometry::PlanarScene&, const Vec<Q>&,
                                                       const StabilityOptions&);

}  // namespace contactcert::solvers
