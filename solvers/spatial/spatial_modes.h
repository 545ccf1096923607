// Every kinematically feasible contact mode of a spatial scene from rest (issue 34), with a witness acceleration per
// mode and a Motzkin certificate per dead prefix. The body's acceleration vdot = (a, alpha) in R^6 (the com's linear
// acceleration, the angular acceleration); from rest a body point p accelerates by a + alpha x r, r = p - com (the
// velocity products vanish), so along a world direction u the contact acceleration is w_u . vdot, w_u = (u, r x u).
// Contact i has a_n = w_n . vdot and tangential acceleration a_t with d_j . a_t = w_{d_j} . vdot for its pyramid edges.
//
// The letters of a contact, and their rows (each a sign condition f . vdot = 0 or f . vdot > 0, in this order):
//   s (separating):     a_n > 0
//   f (sticking):       a_n = 0, t1 . a_t = 0, t2 . a_t = 0
//   sliding, by the maximal-dissipation law of the linearised (pyramid) friction model (Stewart and Trinkle 1996,
//   their LCP; Anitescu and Potra 1997): the friction force lies on the pyramid's edges d_j that minimise d_j . a_t
//   (its complementarity lambda e + D^T a_t >= 0 _|_ beta >= 0), so the sliding directions split by the normal fan
//   of the friction polygon conv(d_j), strictly convex: letter 2j ('A' + 2j) is friction along edge j alone,
//       a_n = 0, (d_{j-1} - d_j) . a_t > 0, (d_{j+1} - d_j) . a_t > 0          (an open sector of directions)
//   and letter 2j + 1 ('A' + 2j + 1) is friction on the pyramid's face between edges j and j + 1,
//       a_n = 0, (d_{j+1} - d_j) . a_t = 0, (d_{j-1} - d_j) . a_t > 0, (d_{j+2} - d_{j+1}) . a_t > 0   (a ray)
//   (indices mod m). For a_n >= 0 exactly one letter holds, so the modes partition {a_n >= 0 at every contact} and
//   the feasible ones are the cells of an arrangement of hyperplanes through the origin of R^6 (Balkcom and Trinkle
//   2002, section 7, for the planar case with s l r n).
// The tree walks the contacts depth first, as the planar one (solvers/stability/mode_tree.h): a letter that the
// parent's vdot meets needs no LP; a prefix that has every row a known dead prefix's Motzkin certificate weighs (the
// same functionals at the same contacts, signs permitting) is dead by that certificate moved to its rows, as the
// planar tree reuses certificates by row kind; else one strict-feasibility LP decides it. A dead prefix (with its
// certificate) ends its subtree. Every letter implies a_n >= 0 (s: a_n > 0, the others a_n = 0), so a prefix of
// contacts 0..i-1 is decided with the rows a_n >= 0 of the later contacts i..k-1 beside its letters' (prefix_system;
// only those of the contacts whose w_n is not a non-negative combination of the others', chosen once per scene, and
// of those the ones its LP's point pushes into, added until the point meets them all): a prefix feasible alone but
// pushing into a later contact's wall is dead at once, with no subtree below it, and the walk visits (2 + 2m) x
// (prefixes that extend to a mode) nodes, never (2 + 2m)^k. (A peg in a hole with 16 contacts: 9 modes in 1 361
// nodes; 16 541 without those rows.)
#pragma once

#include <string>
#include <vector>

#include "exact/arith.h"
#include "exact/deadline.h"
#include "exact/number.h"
#include "geometry/spatial_scene.h"

namespace contactcert::solvers::spatial {

using exact::Q;
using exact::Vec;

/// The letters of a contact with m pyramid edges: "sf" then 'A' .. 'A' + 2m - 1 (edge 0, face 0-1, edge 1, ...).
std::string letters(std::size_t m);

/// One row of a letter: f . vdot = 0, or f . vdot > 0 if strict.
struct SignRow {
  Vec<Q> f;
  bool strict = false;
};

/// The contact accelerations of a scene as functionals on vdot in R^6: per contact w_n, w_t1, w_t2 and w_{d_j}.
struct SpatialModel {
  struct Contact {
    Vec<Q> n, t1, t2;
    std::vector<Vec<Q>> d;
  };
  std::vector<Contact> contacts;
};

/// The functionals w_u = (u, (p - com) x u) of each contact's n, t1, t2 and pyramid edges d_j.
SpatialModel spatial_model(const geometry::SpatialScene& scene);

/// The rows of letter L at a contact (the header's table); empty if L is not one of its letters.
std::vector<SignRow> letter_rows(const SpatialModel::Contact& c, char L);

struct SpatialModeOptions {
  exact::Arith arith = exact::Arith::kVerified;
  long max_nodes = 1L << 22;   ///< prefixes visited at most; beyond: BudgetExceeded (it bounds the dead ones held)
  long max_modes = 100000;     ///< modes listed at most; beyond: BudgetExceeded
  exact::Deadline deadline{};  ///< tested at every node
};

/// A row of a letter by its functional at its contact: the direction u is n (a = -1, b = 0), t1 (-1, 1), t2 (-1, 2)
/// or the edge difference d_a - d_b; the row is w_u . vdot = 0, or > 0 if strict, or >= 0 if at_least (the row
/// a_n >= 0 of a contact after a prefix's letters).
struct SpatialRowKey {
  int a = -1, b = 0;
  bool strict = false;
  bool at_least = false;
};

/// A Motzkin certificate by the rows it weighs: per weighed row its contact, its key and its weight, in contact order.
/// It was found for a prefix of some length l (its weights at contacts l.. are on their rows a_n >= 0), weighs a row
/// of the letter at contact l - 1, and proves dead every prefix of length l whose letters have rows of these
/// functionals at these contacts, signs permitting (the walk's reuse; dead_motzkin moves it there).
struct SpatialProof {
  struct Weight {
    std::size_t contact;
    SpatialRowKey key;
    Q y;
  };
  std::vector<Weight> support;
};

/// A prefix whose rows have no solution. Its Motzkin certificate (columns vdot (6, free), then one slack per row that
/// is not an equality: sigma > 0 for a strict row, sigma >= 0 for a_n >= 0; rows f . vdot - sigma = 0, or
/// f . vdot = 0, letter by letter in the header's order, then w_n . vdot - sigma = 0 for each later contact; the
/// walk's LP leaves out the later rows implied by the others and those its point meets, and its vectors weigh none of
/// them) is the tree's proof `proof` moved onto its rows (dead_motzkin): most dead prefixes take an earlier prefix's
/// proof, which weighs 2 to 4 of their ~3 k rows, so the prefix holds its index, not a vector.
struct SpatialDeadPrefix {
  std::string prefix;
  std::size_t proof = 0;  ///< index in SpatialModeTree::proofs
};

struct SpatialModeTree {
  std::vector<std::string> modes;     ///< depth first, letters in alphabet order
  std::vector<Vec<Q>> accelerations;  ///< per mode: a vdot (6) that realises it
  std::vector<SpatialDeadPrefix> dead;
  std::vector<SpatialProof> proofs;  ///< the dead prefixes' certificates: one per LP that found a prefix dead
  /// Per contact and letter (letters' order): the keys of the letter's rows, what dead_motzkin moves a proof by.
  std::vector<std::vector<std::vector<SpatialRowKey>>> row_keys;
  long nodes = 0;  ///< prefixes visited, the empty one included
  long lps = 0;    ///< strict-feasibility LPs solved
};

/// The walk. Throws exact::BudgetExceeded (with what was covered) past a budget or the deadline.
SpatialModeTree spatial_modes(const SpatialModel& model, const SpatialModeOptions& options = {});

/// The Motzkin vector of a dead prefix of `tree` over its rows (SpatialDeadPrefix's layout): its proof moved there.
Vec<Q> dead_motzkin(const SpatialModeTree& tree, const SpatialDeadPrefix& dead);

/// Whether vdot meets every row of the letters of `prefix` (a mode or a prefix of one).
bool realises(const SpatialModel& model, const std::string& prefix, const Vec<Q>& vdot);

/// A vector y over the rows of `from` (a mode or prefix; prefix_system's row order, as SpatialDeadPrefix: its letters'
/// rows, then a_n >= 0 per later contact), followed by rows of another kind, moved onto the rows of `to` (as long as
/// `from`): each weighted row to the row of `to`'s letter with the same functional at its contact (an edge difference
/// reversed with its weight negated, as the walk moves a dead prefix's certificate), the later contacts' and the
/// trailing rows copied. Empty if a weighted row has no counterpart; the signs are not checked (a Motzkin vector moved
/// must be checked on its new system).
Vec<Q> move_rows(const SpatialModel& model, const std::string& from, const Vec<Q>& y, const std::string& to);

}  // namespace contactcert::solvers::spatial
