// Stability of an assembly from rest (Balkcom-Trinkle section 7 for N bodies; SPEC section 7):
//   strongly_stable: every solution of the rigid-body model (assembly_system.h) has every body at rest;
//   weakly_stable:   some solution has every body at rest and some has not;
//   unstable:        no solution has every body at rest.
// A resting solution is one LP (vdot = 0). The moving solutions of a mode are the solutions of its system with the
// energy row g^T vdot > 0 (assembly_system.h), n..n included (a body may pivot about a single rolling contact).
// The modes are not listed (4^k strings, their kinematically feasible ones growing like k^(3N)): a depth-first walk
// over the contacts keeps the loads' Newton-Euler rows and the energy row in every partial system (the later
// contacts relaxed) and stops at a prefix whose system is infeasible, with its Motzkin certificate. Under gravity
// alone a structure whose every allowed acceleration lowers no com has an infeasible root: one LP after the resting
// one. Before its LP, a prefix tries the certificates of the latest dead prefixes of its length, carried onto its
// system by row labels and checked exactly (assembly_certificate_memory.h): a local contradiction (a body pushed
// against its friction) recurs under every choice of the earlier letters, and its certificate with it. Exact answers
// are needed only for a dead prefix (its certificate) and a whole mode (the moving witness): an interior prefix the
// float LP finds feasible is extended even if its point does not round to an exact one, and so is a child whose
// letter that float point meets within a tolerance, without an LP. A dead prefix whose float certificate does not
// round gets the exact Farkas vector of the float LP's own basis, not a second LP (exact::FloatInfeasible;
// docs/bench.md section 8).
#pragma once

#include <string>
#include <vector>

#include "exact/arith.h"
#include "exact/deadline.h"
#include "solvers/assembly/assembly_system.h"

namespace contactcert::solvers::assembly {

enum class AssemblyVerdict { kStronglyStable, kWeaklyStable, kUnstable };
const char* verdict_name(AssemblyVerdict v);

/// kDecided, or the budget that ran out first (then `verdict` is not decided unless it is kUnstable): the walk's
/// nodes, its time, or an LP's pivots (exact::BudgetExceeded from the simplex).
enum class AssemblyStatus { kDecided, kNodeLimit, kTimeLimit, kLpLimit };
const char* status_name(AssemblyStatus s);

/// A solution of the model: its mode (one letter s l r n per contact), every body's acceleration
/// (vdot_0..vdot_{N-1}, 3 each) and the contact forces (c_1n..c_kn, c_1t..c_kt).
struct AssemblyMotion {
  std::string mode;
  Vec<Q> acceleration;
  Vec<Q> forces;
};

/// A prefix (letters s l r n for the first contacts) whose system, the later contacts `*`, has no solution.
struct AssemblyDeadPrefix {
  std::string prefix;
  Vec<Q> motzkin;  ///< a Motzkin certificate of assembly_system(model, prefix + "*"...)
};

struct AssemblyStabilityResult {
  AssemblyStatus status = AssemblyStatus::kDecided;
  AssemblyVerdict verdict = AssemblyVerdict::kUnstable;  ///< meaningful when status is kDecided
  bool has_resting = false;
  Vec<Q> resting_forces;  ///< a resting solution (c_1n..c_kn, c_1t..c_kt), if has_resting
  Vec<Q> resting_farkas;  ///< unstable: a Motzkin certificate of the resting system
  bool has_moving = false;
  AssemblyMotion moving;                 ///< weakly stable (and unstable when found): a moving solution
  std::vector<AssemblyDeadPrefix> dead;  ///< strongly stable: they cover every mode
  long nodes = 0;                        ///< prefixes visited, the empty one included
  long lps = 0;                          ///< LPs solved (not where the parent's point or a kept certificate decides)
  std::string covered;                   ///< on a limit: how far the walk got
  /// The walk's order of the contacts: letter j of a dead prefix is contact contact_order[j]'s (every mode's and
  /// system's letters stay in the file's order). Body by body (walk_order), so that a body's contacts are decided
  /// together and its Newton-Euler rows contradict early.
  std::vector<std::size_t> contact_order;
};

struct AssemblyStabilityOptions {
  exact::Arith arith = exact::Arith::kVerified;
  long max_nodes = 1L << 20;   ///< prefixes visited at most; beyond: status kNodeLimit
  exact::Deadline deadline{};  ///< tested at every prefix; expired: status kTimeLimit
  /// Try the latest dead prefixes' certificates on a prefix before its LP (assembly_certificate_memory.h); false
  /// solves one LP per prefix its parent's point does not meet (bench/assembly_bench.cpp compares the two).
  bool reuse_certificates = true;
};

/// The contacts body by body, each body's contacts not yet ordered in the file's order. In the contact graph (the
/// fixed parties one node), first the bodies that hang off the rest, peeled as leaves round by round (a stack from
/// the top down); then the others nearest the fixed parties first (course by course, as a wall or an arch is built),
/// ties to the fewest contacts not yet ordered, then the earlier body (a row of boxes from one end to the other).
/// A row of 8 under wind: 2 341 dead prefixes against 5 938 in the file's order; a stack of 16: 430 against 1 162;
/// the 9-block arch: 688 against 694, and 1 081 with the fewest-contacts rule alone (docs/bench.md section 8).
std::vector<std::size_t> walk_order(const geometry::Assembly& a);

/// The letters of every contact (the file's order) for a prefix in the walk's order; the later contacts `*`.
std::string file_letters(const std::vector<std::size_t>& order, const std::string& prefix);

/// The verdict of assembly `a` under its loads, with its evidence.
AssemblyStabilityResult assembly_stability(const geometry::Assembly& a, const AssemblyStabilityOptions& options = {});

}  // namespace contactcert::solvers::assembly
