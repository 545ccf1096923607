#include "solvers/motion/keep_contacts.h"

#include <algorithm>
#include <numeric>
#include <optional>

#include "exact/linalg.h"
#include "solvers/motion/bounded.h"

namespace contactcert::solvers::motion {
namespace {

using Index = Eigen::Index;
using exact::sign;

/// A row m . delta = rhs of one body's correction delta.
template <class T>
struct Row {
  Vec2<T> m;
  T rhs;
};

/// Body b's obstacle rows (step 1): each maintained obstacle contact's m . delta = m . (x - step(x)), a rolling
/// contact's two rows first, then the sliding ones, up to two independent rows.
template <class T>
std::vector<Row<T>> obstacle_rows(const Pose<T>& step, const std::vector<Contact<T>>& contacts,
                                  const std::vector<char>& modes, std::size_t b) {
  std::vector<Row<T>> rows;
  // back = x - step(x), made once per contact and only for a row kept.
  const auto add = [&](const Vec2<T>& m, const Vec2<T>& x, std::optional<Vec2<T>>& back) {
    if (rows.size() == 2 || (rows.size() == 1 && sign(cross2(rows[0].m, m)) == 0)) return;
    if (!back) back = x - step.apply(x);
    rows.push_back({m, dot2(m, *back)});
  };
  for (int rolling = 1; rolling >= 0; --rolling)
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      const Contact<T>& c = contacts[i];
      if (!fixed_party(c, b) || modes[i] == 's' || (modes[i] == 'r') != bool(rolling)) continue;
      const Vec2<T> m = c.kind == ContactKind::kBodyVertex ? c.normal : step.rotate(c.normal);
      std::optional<Vec2<T>> back;
      add(m, c.point, back);
      if (rolling) add(perp2(m), c.point, back);
    }
  return rows;
}

/// The least-norm delta of up to two independent rows: along m for one, by Cramer's rule for two.
template <class T>
Vec2<T> least_norm(const std::vector<Row<T>>& rows) {
  if (rows.size() == 1) return T(rows[0].rhs / dot2(rows[0].m, rows[0].m)) * rows[0].m;
  if (rows.size() != 2) return {T(0), T(0)};
  const Vec2<T>&m1 = rows[0].m, &m2 = rows[1].m;
  const T det = cross2(m1, m2);
  return {T(rows[0].rhs * m2.y - m1.y * rows[1].rhs) / det, T(m1.x * rows[1].rhs - rows[0].rhs * m2.x) / det};
}

/// Whether contact i is maintained: with an obstacle or another body (a finger moves with its body), v_n = 0.
template <class T>
bool maintained(const Contact<T>& c, char mode) {
  return c.kind != ContactKind::kFinger && mode != 's';
}

/// The solution t' of A t' = A t whose free components (the columns of no pivot in A's reduced row echelon form) are
/// t's, bounded(): then its pivot components are too, A t' being the bodies' lines in the world (each row m . t'
/// fixed by the rotated normals and the shapes), so the poses' size stays bounded while every row stays exact; t'
/// differs from t by at most the grid, along the rows' null space.
exact::Vec<Q> on_the_grid(const exact::Mat<Q>& A, const exact::Vec<Q>& t) {
  const Index n = A.cols();
  exact::Mat<Q> Ab(A.rows(), n + 1);
  Ab << A, A * t;
  const exact::Rref<Q> E = exact::rref(Ab);
  exact::Vec<Q> out(n);
  std::vector<bool> pivot(std::size_t(n), false);
  for (Index p : E.pivots) pivot[std::size_t(p)] = true;
  for (Index f = 0; f < n; ++f)
    if (!pivot[std::size_t(f)]) out(f) = bounded(t(f));
  for (Index r = 0; r < E.rank(); ++r) {
    Q v = E.R(r, n);
    for (Index f = 0; f < n; ++f)
      if (!pivot[std::size_t(f)]) v -= E.R(r, f) * out(f);
    out(E.pivots[std::size_t(r)]) = v;
  }
  return out;
}

/// Step 2 for the bodies `group` (joined by maintained body-body contacts): the translations e_b, least-norm over
/// the independent rows, added to their steps (on the exact paths the poses' translations then on_the_grid).
template <class T>
void keep_group(const std::vector<std::size_t>& group, const std::vector<Contact<T>>& contacts,
                const std::vector<char>& modes, const Poses<T>& poses, Poses<T>& steps) {
  std::vector<Index> column(steps.size(), -1);
  for (std::size_t k = 0; k < group.size(); ++k) column[group[k]] = Index(2 * k);
  const Index n = Index(2 * group.size());
  exact::Mat<T> A(0, n);
  std::vector<T> rhs;
  const auto add = [&](const exact::Vec<T>& a, const T& r) {
    exact::Mat<T> grown(A.rows() + 1, n);
    grown << A, a.transpose();
    if (exact::rank(grown) == A.rows()) return;  // dependent: kept only if it agrees
    A = std::move(grown);
    rhs.push_back(r);
  };
  const auto put = [&](exact::Vec<T>& a, std::size_t b, const Vec2<T>& m) {
    a(column[b]) += m.x;
    a(column[b] + 1) += m.y;
  };
  for (std::size_t b : group)
    for (const Row<T>& row : obstacle_rows(steps[b], contacts, modes, b)) {
      exact::Vec<T> a = exact::Vec<T>::Zero(n);
      put(a, b, row.m);
      add(a, T(0));
    }
  const Index obstacle_rows_kept = A.rows();
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact<T>& c = contacts[i];
    if (c.kind != ContactKind::kBodyBody || !maintained(c, modes[i]) || column[std::size_t(c.which)] < 0) continue;
    const Pose<T>&Sa = steps[std::size_t(c.which)], &Sb = steps[std::size_t(c.other)];
    const Vec2<T> m = Sb.rotate(c.normal);
    exact::Vec<T> a = exact::Vec<T>::Zero(n);
    put(a, std::size_t(c.which), m);
    put(a, std::size_t(c.other), T(-1) * m);
    add(a, dot2(m, Sb.apply(c.point) - Sa.apply(c.point)));
  }
  if (A.rows() == obstacle_rows_kept) return;
  exact::Vec<T> r(A.rows());
  for (Index k = 0; k < A.rows(); ++k) r(k) = rhs[std::size_t(k)];
  const exact::Mat<T> At = A.transpose();
  const std::optional<exact::Vec<T>> y = exact::solve(exact::Mat<T>(A * At), r);  // A A^T is non-singular
  if (!y) return;
  const exact::Vec<T> e = At * *y;
  exact::Vec<T> t(n);  // the bodies' translations after the step: step_b(t_b) + e_b
  for (std::size_t k = 0; k < group.size(); ++k) {
    const Vec2<T> tk = steps[group[k]].apply(poses[group[k]].t);
    t(Index(2 * k)) = tk.x + e(Index(2 * k));
    t(Index(2 * k + 1)) = tk.y + e(Index(2 * k + 1));
  }
  if constexpr (std::is_same_v<T, Q>) t = on_the_grid(A, t);
  for (std::size_t k = 0; k < group.size(); ++k) {  // step_b maps t_b to t's block: its translation is that - R t_b
    Pose<T>& S = steps[group[k]];
    S.t = Vec2<T>{t(Index(2 * k)), t(Index(2 * k + 1))} - S.rotate(poses[group[k]].t);
  }
}

/// The gap of contact c after the steps (> 0 open): m . (step_v(x) - step_e(x)) with m the edge's outward normal
/// turned by its owner's step, step_v the vertex owner's and step_e the edge owner's (the identity for an obstacle).
template <class T>
T gap_after(const Contact<T>& c, const Poses<T>& steps) {
  const Pose<T>& S = steps[std::size_t(c.which)];
  const Vec2<T>& x = c.point;
  if (c.kind == ContactKind::kBodyVertex) return dot2(c.normal, S.apply(x) - x);
  if (c.kind == ContactKind::kObstacleVertex) return dot2(S.rotate(c.normal), S.apply(x) - x);  // inward normal
  const Pose<T>& Sb = steps[std::size_t(c.other)];
  return dot2(Sb.rotate(c.normal), S.apply(x) - Sb.apply(x));
}

std::size_t root(std::vector<std::size_t>& up, std::size_t b) {
  while (up[b] != b) b = up[b] = up[up[b]];
  return b;
}

}  // namespace

template <class T>
Poses<T> keep_contacts(const Poses<T>& poses, Poses<T> steps, const std::vector<Contact<T>>& contacts,
                       const std::vector<char>& modes, const std::vector<Twist<T>>& applied) {
  const std::size_t nb = steps.size();
  std::vector<bool> turns(nb);
  for (std::size_t b = 0; b < nb; ++b) turns[b] = sign(applied[b].omega) != 0;
  for (std::size_t b = 0; b < nb; ++b)  // step 1 (a translation keeps every line)
    if (turns[b]) steps[b].t = steps[b].t + least_norm(obstacle_rows(steps[b], contacts, modes, b));
  std::vector<std::size_t> up(nb);
  std::iota(up.begin(), up.end(), std::size_t(0));
  for (std::size_t i = 0; i < contacts.size(); ++i)
    if (contacts[i].kind == ContactKind::kBodyBody && maintained(contacts[i], modes[i]))
      up[root(up, std::size_t(contacts[i].which))] = root(up, std::size_t(contacts[i].other));
  std::vector<std::vector<std::size_t>> groups(nb);
  for (std::size_t b = 0; b < nb; ++b) groups[root(up, b)].push_back(b);
  for (const std::vector<std::size_t>& g : groups)  // step 2, where a body turns (else every gap stays 0)
    if (g.size() > 1 && std::any_of(g.begin(), g.end(), [&](std::size_t b) { return turns[b]; }))
      keep_group(g, contacts, modes, poses, steps);
  return steps;
}

template <class T>
std::vector<std::string> dipping_contacts(const std::vector<Contact<T>>& contacts, const std::vector<char>& modes,
                                          const Poses<T>& steps) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < contacts.size(); ++i)
    if (maintained(contacts[i], modes[i]) && sign(gap_after(contacts[i], steps)) < 0) out.push_back(contacts[i].name);
  return out;
}

template Poses<Q> keep_contacts<Q>(const Poses<Q>&, Poses<Q>, const std::vector<Contact<Q>>&, const std::vector<char>&,
                                   const std::vector<Twist<Q>>&);
template Poses<double> keep_contacts<double>(const Poses<double>&, Poses<double>, const std::vector<Contact<double>>&,
                                             const std::vector<char>&, const std::vector<Twist<double>>&);
template std::vector<std::string> dipping_contacts<Q>(const std::vector<Contact<Q>>&, const std::vector<char>&,
                                                      const Poses<Q>&);
template std::vector<std::string> dipping_contacts<double>(const std::vector<Contact<double>>&,
                                                           const std::vector<char>&, const Poses<double>&);

}  // namespace contactcert::solvers::motion
