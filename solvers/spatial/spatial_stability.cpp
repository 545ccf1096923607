#include "solvers/spatial/spatial_stability.h"

#include <algorithm>

#include "exact/input_error.h"

namespace contactcert::solvers::spatial {

using Index = Eigen::Index;
using exact::StrictStatus;

std::vector<std::size_t> force_edges(std::size_t m, char L) {
  if (L == 's') return {};
  std::vector<std::size_t> out;
  if (L == 'f') {
    for (std::size_t j = 0; j < m; ++j) out.push_back(j);
    return out;
  }
  const std::size_t j = static_cast<std::size_t>(L - 'A') / 2;
  out.push_back(j);
  if ((L - 'A') % 2 == 1) out.push_back((j + 1) % m);
  return out;
}

exact::SparseStrictSystem<Q> spatial_motion_system(const geometry::SpatialBody& body, const SpatialModel& model,
                                                   const std::string& mode, bool zero_acceleration) {
  exact::SparseStrictSystem<Q> sys;
  auto column = [&](bool free, bool strict) {
    sys.is_free.push_back(free);
    sys.strict.push_back(strict);
    return sys.cols++;
  };
  auto put = [&](Index row, Index col, const Q& v) {
    if (sgn(v) != 0) sys.entries.push_back({row, col, v});
  };
  if (!zero_acceleration) {
    for (Index c = 0; c < 6; ++c) column(true, false);
    for (std::size_t i = 0; i < mode.size(); ++i)
      for (const SignRow& row : letter_rows(model.contacts[i], mode[i])) {
        for (Index c = 0; c < 6; ++c) put(sys.rows, c, row.f(c));
        if (row.strict) put(sys.rows, column(false, true), Q(-1));  // f . vdot - sigma = 0, sigma > 0
        ++sys.rows;
      }
    // M vdot: m a and I alpha.
    for (Index d = 0; d < 3; ++d) put(sys.rows + d, d, body.mass);
    for (Index r = 0; r < 3; ++r)
      for (Index c = 0; c < 3; ++c) put(sys.rows + 3 + r, 3 + c, body.inertia[r][c]);
  }
  // - sum beta w(n + d) on the six dynamics rows.
  for (std::size_t i = 0; i < mode.size(); ++i) {
    const SpatialModel::Contact& k = model.contacts[i];
    for (const std::size_t j : force_edges(k.d.size(), mode[i])) {
      const Index col = column(false, false);
      const Vec<Q> w = k.n + k.d[j];
      for (Index d = 0; d < 6; ++d) put(sys.rows + d, col, -w(d));
    }
  }
  sys.rows += 6;
  return sys;
}

namespace {

// The weights of every edge of every contact (zero off the mode's force_edges) read off a point x of the mode's
// system, whose beta columns are its last ones.
Vec<Q> weights_of(const SpatialModel& model, const std::string& mode, const Vec<Q>& x) {
  std::size_t total = 0, used = 0;
  for (std::size_t i = 0; i < mode.size(); ++i) {
    total += model.contacts[i].d.size();
    used += force_edges(model.contacts[i].d.size(), mode[i]).size();
  }
  Vec<Q> w = Vec<Q>::Zero(static_cast<Index>(total));
  Index at = x.size() - static_cast<Index>(used), base = 0;
  for (std::size_t i = 0; i < mode.size(); ++i) {
    const std::size_t m = model.contacts[i].d.size();
    for (const std::size_t j : force_edges(m, mode[i])) w(base + static_cast<Index>(j)) = x(at++);
    base += static_cast<Index>(m);
  }
  return w;
}

// The Motzkin vectors of the latest moving modes proven infeasible, most recently used first: a mode whose system
// takes one of them, moved to its rows (move_rows, as the mode tree reuses its dead prefixes' certificates), needs
// no LP. Modes in tree order share most letters with their predecessors.
class RecentProofs {
 public:
  explicit RecentProofs(const SpatialModel& model) : model_(model) {}

  Vec<Q> take(const std::string& mode, const exact::SparseStrictSystem<Q>& sys, const Vec<Q>& b) {
    for (std::size_t i = 0; i < held_.size(); ++i) {
      Vec<Q> y = move_rows(model_, held_[i].first, held_[i].second, mode);
      if (y.size() == 0 || !exact::verify_motzkin(sys, b, y)) continue;
      std::rotate(held_.begin(), held_.begin() + static_cast<std::ptrdiff_t>(i),
                  held_.begin() + static_cast<std::ptrdiff_t>(i) + 1);
      return y;
    }
    return Vec<Q>();
  }

  void add(const std::string& mode, const Vec<Q>& y) {
    if (held_.size() == kHeld) held_.pop_back();
    held_.insert(held_.begin(), {mode, y});
  }

 private:
  static constexpr std::size_t kHeld = 8;
  const SpatialModel& model_;
  std::vector<std::pair<std::string, Vec<Q>>> held_;
};

}  // namespace

SpatialStability spatial_stability(const geometry::SpatialScene& scene, const Vec<Q>& g,
                                   const SpatialModeOptions& options) {
  const SpatialModel model = spatial_model(scene);
  const std::string sticking(model.contacts.size(), 'f');
  SpatialStability out;
  auto solve = [&](const exact::SparseStrictSystem<Q>& sys, const Vec<Q>& b) {
    if (options.deadline.expired())
      throw exact::BudgetExceeded("spatial stability: " + options.deadline.reached_text(),
                                  std::to_string(out.modes_checked) + " moving modes checked");
    exact::StrictFeasibility<Q> f = exact::StrictSolver<Q>(sys, options.arith).solve(b);
    out.lps += f.lps;
    return f;
  };
  const exact::SparseStrictSystem<Q> rest = spatial_motion_system(scene.body, model, sticking, true);
  Vec<Q> rest_b = Vec<Q>::Zero(rest.rows);
  rest_b.tail(6) = g;
  auto r = solve(rest, rest_b);
  out.has_resting = r.status == StrictStatus::kFeasible;
  if (out.has_resting)
    out.resting_weights = weights_of(model, sticking, r.x);
  else
    out.resting_motzkin = std::move(r.motzkin);

  SpatialModeTree tree = spatial_modes(model, options);
  out.lps += tree.lps;
  out.tree_nodes = tree.nodes;
  out.dead_prefixes = static_cast<long>(tree.dead.size());
  if (out.has_resting) out.proofs.reserve(tree.modes.size());  // no copies on growth
  // Every feasible moving mode but f..f in tree order until one admits g; f..f last, only without a resting
  // solution (then its solutions have vdot != 0).
  std::vector<std::string> moving;
  for (std::string& m : tree.modes)
    if (m != sticking) moving.push_back(std::move(m));
  tree.modes.clear();
  tree.accelerations.clear();
  out.modes_kinematically_feasible = static_cast<long>(moving.size());
  if (!out.has_resting) moving.push_back(sticking);
  RecentProofs recent(model);
  for (const std::string& m : moving) {
    ++out.modes_checked;
    const exact::SparseStrictSystem<Q> sys = spatial_motion_system(scene.body, model, m);
    Vec<Q> b = Vec<Q>::Zero(sys.rows);
    b.tail(6) = g;
    if (Vec<Q> y = recent.take(m, sys, b); y.size()) {
      ++out.modes_by_reuse;
      if (out.has_resting) out.proofs.push_back({m, std::move(y)});
      continue;
    }
    auto f = solve(sys, b);
    if (f.status == StrictStatus::kInfeasible) recent.add(m, f.motzkin);
    bool still = true;
    for (Index d = 0; d < 6 && f.status == StrictStatus::kFeasible; ++d) still = still && sgn(f.x(d)) == 0;
    if (f.status == StrictStatus::kFeasible && !still) {
      out.has_moving = true;
      out.moving = {m, weights_of(model, m, f.x), f.x.head(6)};
      break;
    }
    if (out.has_resting) out.proofs.push_back({m, std::move(f.motzkin)});
  }
  if (out.has_moving || !out.has_resting)
    out.proofs.clear();  // evidence only of a strongly stable verdict
  else
    out.tree = std::move(tree);
  out.verdict = !out.has_resting ? StabilityVerdict::kUnstable
                : out.has_moving ? StabilityVerdict::kWeaklyStable
                                 : StabilityVerdict::kStronglyStable;
  return out;
}

std::vector<geometry::Vec3> contact_forces(const geometry::SpatialScene& scene, const Vec<Q>& weights) {
  std::vector<geometry::Vec3> out;
  Index at = 0;
  for (const geometry::SpatialContact& c : scene.contacts) {
    geometry::Vec3 f{Q(0), Q(0), Q(0)};
    for (std::size_t j = 0; j < c.edges.size(); ++j, ++at) {
      const geometry::Vec3 d = c.edge(j);
      for (std::size_t x = 0; x < 3; ++x) f[x] += weights(at) * (c.normal[x] + d[x]);
    }
    out.push_back(f);
  }
  return out;
}

}  // namespace contactcert::solvers::spatial
