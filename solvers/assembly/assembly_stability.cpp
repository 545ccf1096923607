#include "solvers/assembly/assembly_stability.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "solvers/assembly/assembly_certificate_memory.h"

namespace contactcert::solvers::assembly {
namespace {

/// Strict feasibility of A x = b: the verified route, and if its float simplex runs out of pivots (it can cycle on
/// these degenerate systems) the exact simplex alone. Unless `need_point`, a system the float LP finds feasible but
/// whose point does not round to an exact one is taken as feasible without a point (kFeasible, x empty) instead of
/// solving it again exactly: the walk only extends such a prefix, and were it infeasible after all, its extensions
/// would be proved dead in turn (the certificate still covers every mode), so no verdict rests on the float LP.
/// *float_point: the float LP's point, if it found one (a hint for the children, `meets_float`).
exact::StrictFeasibility<Q> solve(const AssemblySystem& s, exact::Arith arith, bool need_point = true,
                                  Vec<double>* float_point = nullptr) {
  try {
    const exact::StrictSolver<Q> solver(s.system, arith);
    bool float_feasible = false;
    if (std::optional<exact::StrictFeasibility<Q>> f =
            solver.solve_rounded(s.b, &float_feasible, float_point, exact::FloatInfeasible::kBasisCertificate))
      return std::move(*f);
    if (float_feasible && !need_point) {
      exact::StrictFeasibility<Q> f;
      f.status = exact::StrictStatus::kFeasible;
      return f;
    }
    return solver.solve_unrounded(s.b);
  } catch (const exact::BudgetExceeded&) {
    if (arith == exact::Arith::kExact) throw;
    return exact::StrictSolver<Q>(s.system, exact::Arith::kExact).solve(s.b);
  }
}

/// A prefix the walk will extend, with a point of its system: accelerations and forces (empty if only the float LP
/// found one; then the float LP's, in doubles, if it gave one).
struct Node {
  std::string prefix;
  Vec<Q> vdot, c;
  Vec<double> vdot_float, c_float;
};

/// The node of a prefix whose system `s` the LP `f` found feasible, `x_float` the float LP's point.
Node feasible_node(std::string prefix, const AssemblySystem& s, const exact::StrictFeasibility<Q>& f,
                   const Vec<double>& x_float) {
  if (f.x.size() != 0) return {std::move(prefix), s.acceleration(f.x), s.forces(f.x), {}, {}};
  if (x_float.size() == 0) return {std::move(prefix), {}, {}, {}, {}};
  // The forces as AssemblySystem::forces reads them, in doubles.
  const auto k = static_cast<Eigen::Index>(s.c_n_column.size());
  Vec<double> c = Vec<double>::Zero(2 * k);
  for (Eigen::Index i = 0; i < k; ++i) {
    const auto u = static_cast<std::size_t>(i);
    if (s.c_n_column[u] < 0) continue;
    c(i) = x_float(s.c_n_column[u]);
    c(k + i) = s.c_t_column[u] >= 0 ? x_float(s.c_t_column[u]) : s.c_t_per_c_n[u].get_d() * c(i);
  }
  return {std::move(prefix), {}, {}, x_float.head(s.vdot_size), c};
}

/// Whether (vdot, c), a point of the parent's system (contact i relaxed), already satisfies letter L at contact i:
/// then it is a point of the child's system and no LP is needed. No point (empty) meets nothing.
bool meets(const AssemblyModel& model, std::size_t i, char L, const Vec<Q>& vdot, const Vec<Q>& c) {
  if (vdot.size() == 0) return false;
  // The energy row g^T vdot > 0 holds already: the parent's point satisfies it.
  const auto k = static_cast<Eigen::Index>(model.contacts.size());
  const auto [a_n, a_t] = contact_acceleration(model, i, vdot);
  const Q& c_n = c(static_cast<Eigen::Index>(i));
  const Q& c_t = c(k + static_cast<Eigen::Index>(i));
  const ContactJacobian& J = model.contacts[i];
  switch (L) {
    case 's':
      return sgn(a_n) > 0 && sgn(c_n) == 0 && sgn(c_t) == 0;
    case 'l':
      return sgn(a_n) == 0 && sgn(a_t) > 0 && c_t == -J.mu_k * c_n;
    case 'r':
      return sgn(a_n) == 0 && sgn(a_t) < 0 && c_t == J.mu_k * c_n;
    default:
      return sgn(a_n) == 0 && sgn(a_t) == 0 && abs(c_t) <= J.mu_s * c_n;
  }
}

/// meets() for a point in doubles, each sign and equation up to a tolerance: only a hint. A child it admits is
/// extended without an LP, like a prefix the float LP finds feasible (solve): were its system infeasible, its
/// children would be proved dead in turn; a whole mode is never admitted this way (its exact point is the witness).
bool meets_float(const AssemblyModel& model, std::size_t i, char L, const Vec<double>& vdot, const Vec<double>& c) {
  if (vdot.size() == 0) return false;
  const auto k = static_cast<Eigen::Index>(model.contacts.size());
  const double c_n = c(static_cast<Eigen::Index>(i)), c_t = c(k + static_cast<Eigen::Index>(i));
  double a_n = 0, a_t = 0;
  for (const ContactJacobian::Side& s : model.contacts[i].sides) {
    if (s.body < 0) continue;
    for (Eigen::Index d = 0; d < 3; ++d) {
      a_n += s.w_n[static_cast<std::size_t>(d)].get_d() * vdot(3 * s.body + d);
      a_t += s.w_t[static_cast<std::size_t>(d)].get_d() * vdot(3 * s.body + d);
    }
  }
  const double tol = 1e-9 * (1 + vdot.cwiseAbs().maxCoeff() + c.cwiseAbs().maxCoeff());
  const ContactJacobian& J = model.contacts[i];
  switch (L) {
    case 's':
      return a_n > tol && std::abs(c_n) <= tol && std::abs(c_t) <= tol;
    case 'l':
      return std::abs(a_n) <= tol && a_t > tol && std::abs(c_t + J.mu_k.get_d() * c_n) <= tol;
    case 'r':
      return std::abs(a_n) <= tol && a_t < -tol && std::abs(c_t - J.mu_k.get_d() * c_n) <= tol;
    default:
      return std::abs(a_n) <= tol && std::abs(a_t) <= tol && std::abs(c_t) <= J.mu_s.get_d() * c_n + tol;
  }
}

/// The depth-first walk over the contacts' letters, every system with the energy row (so a feasible whole mode is
/// a moving solution). Stops at the first one.
void walk(const AssemblyModel& model, const AssemblyStabilityOptions& options, AssemblyStabilityResult& r) {
  const std::size_t k = model.contacts.size();
  const std::vector<std::size_t>& order = r.contact_order;
  std::vector<Node> stack;
  CertificateMemory memory;
  AssemblySystem s;  // the system of the prefix at hand, rebuilt in place
  {
    const AssemblySystem root = assembly_system(model, std::string(k, '*'));
    Vec<double> x_float;
    const auto f = solve(root, options.arith, k == 0, &x_float);
    ++r.lps;
    ++r.nodes;
    if (f.status == exact::StrictStatus::kInfeasible) {  // no solution at all: every mode is dead
      r.dead.push_back({"", f.motzkin});
      return;
    }
    stack.push_back(feasible_node("", root, f, x_float));
  }
  while (!stack.empty()) {
    Node node = std::move(stack.back());
    stack.pop_back();
    const std::size_t i = node.prefix.size();
    // Children in reverse so that s is taken first.
    for (const char L : {'n', 'r', 'l', 's'}) {
      std::string prefix = node.prefix + L;
      if (r.nodes >= options.max_nodes || options.deadline.expired()) {
        r.status = r.nodes >= options.max_nodes ? AssemblyStatus::kNodeLimit : AssemblyStatus::kTimeLimit;
        r.covered = std::to_string(r.nodes) + " prefixes visited, " + std::to_string(r.dead.size()) + " proved dead, " +
                    std::to_string(stack.size() + 1) + " open";
        return;
      }
      ++r.nodes;
      Node child{prefix, node.vdot, node.c, node.vdot_float, node.c_float};
      if (!meets(model, order[i], L, node.vdot, node.c) &&
          !(prefix.size() < k && meets_float(model, order[i], L, node.vdot_float, node.c_float))) {
        assembly_system(model, file_letters(order, prefix), s);
        if (options.reuse_certificates)
          if (std::optional<Vec<Q>> y = memory.recall(s, prefix.size())) {
            r.dead.push_back({std::move(prefix), std::move(*y)});
            continue;
          }
        Vec<double> x_float;
        const auto f = solve(s, options.arith, prefix.size() == k, &x_float);
        ++r.lps;
        if (f.status == exact::StrictStatus::kInfeasible) {
          memory.remember(s, prefix.size(), f.motzkin);
          r.dead.push_back({std::move(prefix), f.motzkin});
          continue;
        }
        child = feasible_node(std::move(child.prefix), s, f, x_float);
      }
      if (child.prefix.size() == k) {
        r.has_moving = true;
        r.moving = {file_letters(order, child.prefix), child.vdot, child.c};
        return;
      }
      stack.push_back(std::move(child));
    }
  }
}

}  // namespace

std::vector<std::size_t> walk_order(const geometry::Assembly& a) {
  const std::size_t k = a.contacts.size(), N = a.bodies.size();
  // The contact graph: a body's neighbouring parties, every fixed party one node (index N).
  const auto node = [N](const geometry::Party& p) { return p.movable() ? p.index : N; };
  std::vector<std::vector<std::size_t>> neighbours(N);
  for (const geometry::AssemblyContact& c : a.contacts)
    for (const auto& [p, q] : {std::pair{&c.from, &c.to}, std::pair{&c.to, &c.from}})
      if (p->movable()) neighbours[p->index].push_back(node(*q));
  for (std::vector<std::size_t>& v : neighbours) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }
  // Leaves peeled round by round: a body with at most one neighbour not yet peeled hangs off the rest (done).
  std::vector<std::size_t> bodies;
  std::vector<bool> done(N, false);
  for (bool more = true; more;) {
    more = false;
    std::vector<std::size_t> leaves;
    for (std::size_t b = 0; b < N; ++b)
      if (!done[b] && std::count_if(neighbours[b].begin(), neighbours[b].end(),
                                    [&](std::size_t q) { return q == N || !done[q]; }) <= 1)
        leaves.push_back(b);
    for (const std::size_t b : leaves) {
      done[b] = more = true;
      bodies.push_back(b);
    }
  }
  // The distance of every body from the fixed parties in the contact graph (breadth first).
  std::vector<std::size_t> distance(N, N + 1), layer;
  for (std::size_t b = 0; b < N; ++b)
    if (std::binary_search(neighbours[b].begin(), neighbours[b].end(), N)) {
      distance[b] = 1;
      layer.push_back(b);
    }
  while (!layer.empty()) {
    std::vector<std::size_t> next;
    for (const std::size_t b : layer)
      for (const std::size_t q : neighbours[b])
        if (q < N && distance[q] > distance[b] + 1) {
          distance[q] = distance[b] + 1;
          next.push_back(q);
        }
    layer = std::move(next);
  }
  std::vector<bool> placed(k, false);
  std::vector<std::size_t> order;
  const auto touches = [&a](std::size_t i, std::size_t b) {
    const geometry::AssemblyContact& c = a.contacts[i];
    return (c.from.movable() && c.from.index == b) || (c.to.movable() && c.to.index == b);
  };
  const auto take = [&](std::size_t b) {
    for (std::size_t i = 0; i < k; ++i)
      if (!placed[i] && touches(i, b)) {
        placed[i] = true;
        order.push_back(i);
      }
  };
  for (const std::size_t b : bodies) take(b);
  // The rest: the nearest the fixed parties first, then the fewest contacts not yet taken, then the earlier body.
  for (;;) {
    std::size_t best = N, fewest = k + 1;
    for (std::size_t b = 0; b < N; ++b) {
      if (done[b]) continue;
      std::size_t open = 0;
      for (std::size_t i = 0; i < k; ++i) open += !placed[i] && touches(i, b);
      if (best == N || distance[b] < distance[best] || (distance[b] == distance[best] && open < fewest)) {
        best = b;
        fewest = open;
      }
    }
    if (best == N) break;
    done[best] = true;
    take(best);
  }
  for (std::size_t i = 0; i < k; ++i)  // a contact of no movable body (none in a valid assembly) comes last
    if (!placed[i]) order.push_back(i);
  return order;
}

std::string file_letters(const std::vector<std::size_t>& order, const std::string& prefix) {
  std::string letters(order.size(), '*');
  for (std::size_t j = 0; j < prefix.size(); ++j) letters[order[j]] = prefix[j];
  return letters;
}

const char* verdict_name(AssemblyVerdict v) {
  switch (v) {
    case AssemblyVerdict::kStronglyStable:
      return "strongly_stable";
    case AssemblyVerdict::kWeaklyStable:
      return "weakly_stable";
    default:
      return "unstable";
  }
}

const char* status_name(AssemblyStatus s) {
  switch (s) {
    case AssemblyStatus::kDecided:
      return "decided";
    case AssemblyStatus::kNodeLimit:
      return "node_limit";
    case AssemblyStatus::kLpLimit:
      return "lp_limit";
    default:
      return "time_limit";
  }
}

AssemblyStabilityResult assembly_stability(const geometry::Assembly& a, const AssemblyStabilityOptions& options) {
  const AssemblyModel model = assembly_model(a);
  const std::size_t k = model.contacts.size();
  AssemblyStabilityResult r;
  r.contact_order = walk_order(a);
  try {
    const AssemblySystem rest = assembly_system(model, std::string(k, 'n'), true);
    const auto f = solve(rest, options.arith);
    ++r.lps;
    r.has_resting = f.status == exact::StrictStatus::kFeasible;
    if (r.has_resting)
      r.resting_forces = rest.forces(f.x);
    else
      r.resting_farkas = f.motzkin;
    walk(model, options, r);
  } catch (const exact::BudgetExceeded& e) {  // an LP's pivot budget: a status with what was covered
    r.status = AssemblyStatus::kLpLimit;
    r.covered = std::string(e.what()) + " after " + std::to_string(r.nodes) + " prefixes";
    if (r.lps == 0) return r;  // not even the resting LP: nothing is decided
  }
  if (!r.has_resting) {
    r.verdict = AssemblyVerdict::kUnstable;
    r.status = AssemblyStatus::kDecided;  // the resting system's certificate decides, whatever the walk covered
    r.dead.clear();
    return r;
  }
  if (r.status != AssemblyStatus::kDecided) return r;
  r.verdict = r.has_moving ? AssemblyVerdict::kWeaklyStable : AssemblyVerdict::kStronglyStable;
  if (r.has_moving) r.dead.clear();
  return r;
}

}  // namespace contactcert::solvers::assembly
