// The translation correction of a step (docs/motion.md, "One step" item 7 and "Several bodies" item 3): a turning
// step moves a sliding contact point along a circle, off its line by O(h^2); translating the bodies' steps by small
// deltas puts every maintained contact (v_n = 0, with an obstacle or between two bodies) back exactly on its line,
// as far as the bodies' translation freedoms allow. Written once over T (Q or double).
#pragma once

#include <string>
#include <vector>

#include "solvers/motion/contacts.h"

namespace contactcert::solvers::motion {

/// Whether contact c holds body b against a fixed obstacle.
template <class T>
bool fixed_party(const Contact<T>& c, std::size_t b) {
  return static_cast<std::size_t>(c.which) == b &&
         (c.kind == ContactKind::kBodyVertex || c.kind == ContactKind::kObstacleVertex);
}

/// Corrects `steps` (from the poses `poses`, each body's rigid step by its applied twist `applied[b]`) so that the
/// maintained contacts of `contacts` (modes[i] != 's', fingers aside: a carried finger moves with its body) stay
/// exactly on their lines.
/// 1. Each turning body alone, as with one body: rows m . delta_b = m . (x - step_b(x)) of its obstacle contacts (m the
///    obstacle edge's normal, or the body edge's normal turned by the step), a rolling contact's two rows (both axes:
///    it stays exactly fixed) first, then the sliding ones, up to two independent rows; delta_b their least-norm
///    solution.
/// 2. Each group of bodies joined by maintained body-body contacts, one of them turning: a vertex x of body a on an
///    edge of body b (outward normal n) has after the step the gap m . (step_a(x) + e_a - step_b(x) - e_b), m =
///    R_b n (R_b the rotation of b's step), so the row m . (e_a - e_b) = m . (step_b(x) - step_a(x)) closes it; each
///    body's rows of step 1 get m . e_b = 0 (they stay kept). The group's e is the least-norm solution
///    e = A^T (A A^T)^-1 r of the independent rows A e = r, taken in that order; a dependent row is kept only if it
///    agrees. On the exact paths the bodies' new translations t' (the poses' `poses[b].t` after the step) then
///    keep A t' and have their free components (no pivot in A's echelon form) bounded (bounded.h), so that the
///    poses keep a bounded size.
/// Returns the corrected steps (per body: world after = steps[b] applied to world before).
template <class T>
Poses<T> keep_contacts(const Poses<T>& poses, Poses<T> steps, const std::vector<Contact<T>>& contacts,
                       const std::vector<char>& modes, const std::vector<Twist<T>>& applied);

/// The names of the maintained contacts that dip into the other shape after `steps` (gap < 0: more independent
/// contact constraints than translation freedoms), asked only when the overlap test finds an overlap.
template <class T>
std::vector<std::string> dipping_contacts(const std::vector<Contact<T>>& contacts, const std::vector<char>& modes,
                                          const Poses<T>& steps);

extern template Poses<Q> keep_contacts<Q>(const Poses<Q>&, Poses<Q>, const std::vector<Contact<Q>>&,
                                          const std::vector<char>&, const std::vector<Twist<Q>>&);
extern template Poses<double> keep_contacts<double>(const Poses<double>&, Poses<double>,
                                                    const std::vector<Contact<double>>&, const std::vector<char>&,
                                                    const std::vector<Twist<double>>&);
extern template std::vector<std::string> dipping_contacts<Q>(const std::vector<Contact<Q>>&, const std::vector<char>&,
                                                             const Poses<Q>&);
extern template std::vector<std::string> dipping_contacts<double>(const std::vector<Contact<double>>&,
                                                                  const std::vector<char>&, const Poses<double>&);

}  // namespace contactcert::solvers::motion
