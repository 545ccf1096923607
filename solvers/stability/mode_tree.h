// Output-sensitive enumeration of the kinematically feasible contact modes of a scene, from rest (wrench cone
// paper, section 2.3 and Table 2). The contact accelerations a_n = J_n^T vdot and a_t = J_t^T vdot (eq. 6,
// velocity products neglected) are linear in the workpiece acceleration vdot in R^3, so the letters of a mode
// put rows on vdot alone (kinematic_system), and a prefix of a mode - letters for fixels 1..i - whose rows have
// no solution has no feasible completion. The depth-first tree over the fixels that stops at such a prefix
// visits (letters per fixel) x (feasible prefixes) nodes. With the strict `s` and no unions the letters of a fixel
// split its accelerations into disjoint sets, so each feasible mode of i fixels is a union of cells of an
// arrangement of 2i planes through the origin of R^3 and there are O(i^2) of them (O(i) when every a_n must be
// >= 0), never 4^k. The unions (m, u) and Table 2's printed `s` (a_n >= 0 at a touching fixel) give overlapping
// modes - vdot = 0 alone realises 2^(touching) printed ones - so there the walk is only output-sensitive and its
// output can be exponential: ModeTreeOptions bounds it. Every dead prefix carries a Motzkin certificate, so the
// tree is a completeness proof that a checker verifies by walking only the prefixes it lists
// (checker/mode_coverage.h).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "exact/arith.h"
#include "exact/deadline.h"
#include "solvers/stability/motion_system.h"

namespace contactcert::solvers {

/// The letters the enumeration gives each fixel, and how they read (Table 2).
struct ModeAlphabet {
  KinematicRules rules;  ///< which fixels touch; `s` strict (the physical modes) or as Table 2 prints it
  bool unions = false;   ///< also m (= l, r or n) and u (= s or a), whose modes overlap the finer ones
  /// A touching fixel: s l r n (and m); a gap: s a (and u). Without the unions the letters of a fixel split its
  /// accelerations into disjoint sets: a touching fixel's a_n >= 0 into a_n > 0 (s) and a_n = 0 with the sign
  /// of a_t (r, n, l); a gap's a_n into a_n >= 0 (s) and a_n < 0 (a).
  std::vector<Interaction> letters(std::size_t fixel) const;
};

/// A prefix of a mode whose kinematic rows have no solution: `motzkin` is a Motzkin certificate of
/// kinematic_system(model, prefix, rules) (strict_feasibility.h), so no mode that extends it is feasible.
template <class T>
struct DeadPrefix {
  ModeString prefix;
  Vec<T> motzkin;
};

struct ModeTreeOptions {
  exact::Arith arith = exact::Arith::kVerified;
  long max_nodes = 1L << 22;   ///< prefixes visited at most; beyond: BudgetExceeded
  long max_modes = 100000;     ///< modes listed at most (the output); beyond: BudgetExceeded
  exact::Deadline deadline{};  ///< tested at every node; expired: BudgetExceeded
};

/// The walk's result: the feasible modes with a realising acceleration, and the dead prefixes with their proofs.
template <class T>
struct ModeTree {
  std::vector<ModeString> modes;      ///< kinematically feasible, depth first (letters in alphabet order)
  std::vector<Vec<T>> accelerations;  ///< per mode: a vdot that realises it
  std::vector<DeadPrefix<T>> dead;    ///< depth first
  long nodes = 0;                     ///< prefixes visited, the empty one included
  /// Prefixes decided by a kinematic LP or by their cone (a child whose letter the parent's vdot already meets needs
  /// neither)
  long lps = 0;
  long lps_checked_from_float = 0;  ///< of these, decided by a float LP's answer checked exactly
  long lps_by_cones = 0;            ///< of these, decided by the prefix's cone (walk_modes_by_cones)
  bool complete = true;             ///< false if on_mode stopped the walk
};

/// Called with each feasible mode and its acceleration as the walk finds it; false stops the walk.
template <class T>
using OnMode = std::function<bool(const ModeString&, const Vec<T>&)>;

/// Walks the prefix tree of the model's fixels depth first, iteratively (vdot has J's rows as its dimension: 3, or 3N
/// for the bodies of an assembly, solvers/assembly/assembly_modes.h; memory O(fixels) for the path, whatever
/// the depth). Throws exact::BudgetExceeded (with the nodes covered) past options.max_nodes, options.max_modes or
/// the deadline.
template <class T>
ModeTree<T> walk_modes(const MotionModel<T>& model, const ModeAlphabet& alphabet, const ModeTreeOptions& options,
                       const OnMode<T>& on_mode = {});

/// The same walk with the prefixes that the parent's acceleration does not realise decided by the cone of their rows
/// in integers (mode_tree_cone.h) instead of an LP each: the same modes and dead prefixes; the accelerations are sums
/// of the cones' rays and the Motzkin certificates combine at most four rows. A prefix goes to its LP (the verified
/// arithmetic of options.arith) only where a number outgrows 128 bits or no such certificate is found.
ModeTree<Q> walk_modes_by_cones(const MotionModel<Q>& model, const ModeAlphabet& alphabet,
                                const ModeTreeOptions& options, const OnMode<Q>& on_mode = {});

/// Whether acceleration vdot realises `mode` (or a prefix of one) by Table 2's sign conditions on a_n = J_n^T vdot
/// and a_t = J_t^T vdot, with the sign test of T (exact for Q): a direct reading of the table, not its LP rows.
template <class T>
bool realises(const MotionModel<T>& model, const KinematicRules& rules, const Vec<T>& vdot, const ModeString& mode);

#define CONTACTCERT_MODE_TREE_EXTERN(T)                                                                         \
  extern template ModeTree<T> walk_modes<T>(const MotionModel<T>&, const ModeAlphabet&, const ModeTreeOptions&, \
                                            const OnMode<T>&);                                                  \
  extern template bool realises<T>(const MotionModel<T>&, const KinematicRules&, const Vec<T>&, const ModeString&);
CONTACTCERT_MODE_TREE_EXTERN(double)
CONTACTCERT_MODE_TREE_EXTERN(Q)
#undef CONTACTCERT_MODE_TREE_EXTERN

}  // namespace contactcert::solvers
