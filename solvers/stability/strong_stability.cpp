#include "solvers/stability/strong_stability.h"

#include <limits>

#include "exact/input_error.h"
#include "exact/ladder_numbers.h"

namespace contactcert::solvers {

using exact::StrictStatus;
using Index = Eigen::Index;

const char* verdict_name(StabilityVerdict v) {
  switch (v) {
    case StabilityVerdict::kStronglyStable:
      return "strongly_stable";
    case StabilityVerdict::kWeaklyStable:
      return "weakly_stable";
    case StabilityVerdict::kUnstable:
      return "unstable";
  }
  return "?";
}

geometry::PlanarScene touching_scene(const geometry::PlanarScene& scene, std::vector<Index>* kept) {
  geometry::PlanarScene out{scene.workpiece, {}};
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    if (!scene.fixels[i].frame.touching()) continue;
    out.fixels.push_back(scene.fixels[i]);
    if (kept) kept->push_back(static_cast<Index>(i));
  }
  return out;
}

std::vector<ModeString> moving_modes(std::size_t k) {
  static constexpr Interaction kLetters[] = {Interaction::kSeparate, Interaction::kSlideLeft, Interaction::kSlideRight,
                                             Interaction::kRoll};
  if (k > 12) throw std::length_error("moving_modes: 4^" + std::to_string(k) + " strings (a test oracle, k <= 12)");
  std::vector<ModeString> out;
  const std::size_t total = std::size_t{1} << (2 * k);
  for (std::size_t code = 0; code + 1 < total; ++code) {  // the last code is n..n
    ModeString m;
    std::size_t c = code;
    for (std::size_t i = 0; i < k; ++i, c /= 4) m.letters.push_back(kLetters[c % 4]);
    out.push_back(m);
  }
  return out;
}

ModeAlphabet moving_alphabet(std::size_t k) { return ModeAlphabet{{std::vector<bool>(k, true), false}, false}; }

namespace {

ModeString all_rolling(std::size_t k) { return ModeString{std::vector<Interaction>(k, Interaction::kRoll)}; }

bool is_all_rolling(const ModeString& m) {
  for (Interaction L : m.letters)
    if (L != Interaction::kRoll) return false;
  return true;
}

template <class T>
bool nonzero(const Vec<T>& v) {
  for (Index i = 0; i < v.size(); ++i)
    if (!exact::is_zero(v(i))) return true;
  return false;
}

// The moving modes over s l r n with a strict `s` are disjoint, O(k^2) of them: the node budget bounds them.
ModeTreeOptions tree_options(const StabilityOptions& o) {
  return {o.arith, o.max_nodes, std::numeric_limits<long>::max(), o.deadline};
}

// The mode tree of the moving modes: in Q its prefixes decided by their cones in integers (walk_modes_by_cones), in
// a float type by its LPs.
template <class T>
ModeTree<T> walk_tree(const MotionModel<T>& model, const ModeAlphabet& alphabet, const ModeTreeOptions& options,
                      const OnMode<T>& on_mode = {}) {
  if constexpr (std::is_same_v<T, Q>)
    return walk_modes_by_cones(model, alphabet, options, on_mode);
  else
    return walk_modes(model, alphabet, options, on_mode);
}

// One feasible mode as the verdict sees it: its name, system, LP and slot in ReusedCertificates (1 + its index).
template <class T>
struct ModeLp {
  const ModeString& name;
  const MotionSystem<T>& ms;
  const exact::StrictSolver<T>& solver;
  std::size_t slot = 0;
};

// The verdict for g (SPEC section 7), in three steps: the resting LP; each kinematically feasible moving mode
// but n..n in tree order until one moves (for_each_mode(visit) calls visit(ModeLp) per mode, stopping when it
// returns false); and if no resting solution exists, n..n, which moves only if vdot != 0 (rolling() gives it).
// kinematic_proofs(out) adds the dead prefixes to out.proofs once a resting solution makes them evidence.
// With `reuse`, a system that one of its certificates proves infeasible for g is decided without its LP, and the
// certificates of the LPs solved are kept there.
template <class T, class ForEachMode, class Rolling, class KinematicProofs>
StabilityResult<T> decide(const std::vector<Index>& touching, const MotionSystem<T>& rest,
                          const exact::StrictSolver<T>& rest_solver, const Vec<T>& g, ForEachMode&& for_each_mode,
                          Rolling&& rolling, KinematicProofs&& kinematic_proofs, ReusedCertificates<T>* reuse) {
  StabilityResult<T> out;
  out.touching = touching;
  auto solve = [&](std::size_t slot, const MotionSystem<T>& ms, const exact::StrictSolver<T>& solver) {
    exact::StrictFeasibility<T> f;
    if (const Vec<T>* y = reuse ? reuse->find(slot, g) : nullptr) {
      f.motzkin = *y;  // status kInfeasible
      ++out.lps;
      ++out.lps_reused;
    } else {
      f = solver.solve(ms.rhs(g));
      out.lps += f.lps;
      if (f.rounded_float_checked) out.lps_checked_from_float += f.lps;
      if (reuse && f.status == StrictStatus::kInfeasible) reuse->keep(slot, ms.system, f.motzkin);
    }
    return f;
  };

  // Resting solutions: J c + g = 0 with every c in its static friction cone.
  auto r = solve(0, rest, rest_solver);
  out.has_resting = r.status == StrictStatus::kFeasible;
  if (out.has_resting)
    out.resting_forces = rest.forces(r.x);
  else
    out.resting_farkas = std::move(r.motzkin);

  // A moving solution in mode m, or its proof that there is none (evidence only beside a resting solution).
  auto try_mode = [&](const ModeLp<T>& m, bool rolling_mode) {
    ++out.modes_checked;
    auto f = solve(m.slot, m.ms, m.solver);
    if (f.status == StrictStatus::kFeasible && (!rolling_mode || nonzero<T>(m.ms.acceleration(f.x)))) {
      out.has_moving = true;
      out.moving = {m.name, m.ms.forces(f.x), m.ms.acceleration(f.x)};
      return false;
    }
    if (!rolling_mode && out.has_resting) out.proofs.push_back({m.name, false, std::move(f.motzkin)});
    return true;
  };
  for_each_mode([&](const ModeLp<T>& m) { return try_mode(m, false); });
  if (!out.has_moving && !out.has_resting) try_mode(rolling(), true);
  if (out.has_moving)
    out.proofs.clear();  // no longer evidence of anything
  else if (out.has_resting)
    kinematic_proofs(out);
  out.verdict = !out.has_resting ? StabilityVerdict::kUnstable
                : out.has_moving ? StabilityVerdict::kWeaklyStable
                                 : StabilityVerdict::kStronglyStable;
  return out;
}

// The kinematic proofs of a tree's dead prefixes.
template <class T>
std::vector<ModeProof<T>> dead_prefix_proofs(std::vector<DeadPrefix<T>> dead) {
  std::vector<ModeProof<T>> out;
  out.reserve(dead.size());
  for (DeadPrefix<T>& d : dead) out.push_back({std::move(d.prefix), true, std::move(d.motzkin)});
  return out;
}

}  // namespace

template <class T>
StabilityOracle<T>::StabilityOracle(const geometry::PlanarScene& full, const StabilityOptions& options)
    : model_(motion_model<T>(touching_scene(full, &touching_))),
      rest_(motion_system(model_, all_rolling(model_.mu_s.size()), /*zero_acceleration=*/true)),
      rest_solver_(rest_.system, options.arith),
      tree_(walk_tree(model_, moving_alphabet(model_.mu_s.size()), tree_options(options))) {
  // The systems of the feasible moving modes (n..n last), and the dead prefixes as shared proofs.
  for (const ModeString& m : tree_.modes) {
    if (is_all_rolling(m)) continue;
    MotionSystem<T> ms = motion_system(model_, m);
    exact::StrictSolver<T> solver(ms.system, options.arith);
    modes_.push_back({m, std::move(ms), std::move(solver)});
  }
  const ModeString rolling = all_rolling(model_.mu_s.size());
  MotionSystem<T> ms = motion_system(model_, rolling);
  exact::StrictSolver<T> solver(ms.system, options.arith);
  modes_.push_back({rolling, std::move(ms), std::move(solver)});
  kinematic_proofs_ = std::make_shared<const std::vector<ModeProof<T>>>(dead_prefix_proofs(std::move(tree_.dead)));
  tree_.dead.clear();
}

template <class T>
StabilityResult<T> StabilityOracle<T>::verdict(const Vec<T>& g) const {
  return decide_for(g, nullptr);
}

template <class T>
StabilityResult<T> StabilityOracle<T>::verdict(const Vec<T>& g, ReusedCertificates<T>& reuse) const {
  return decide_for(g, &reuse);
}

template <class T>
StabilityResult<T> StabilityOracle<T>::decide_for(const Vec<T>& g, ReusedCertificates<T>* reuse) const {
  StabilityResult<T> out = solvers::decide(
      touching_, rest_, rest_solver_, g,
      [this](auto&& visit) {
        for (std::size_t i = 0; i + 1 < modes_.size(); ++i)
          if (!visit(ModeLp<T>{modes_[i].name, modes_[i].ms, modes_[i].solver, 1 + i})) return;
      },
      [this] {
        return ModeLp<T>{modes_.back().name, modes_.back().ms, modes_.back().solver, modes_.size()};
      },
      [this](StabilityResult<T>& r) {
        for (std::size_t j = 0; j < kinematic_proofs_->size(); ++j) r.proofs.push_shared(kinematic_proofs_, j);
      },
      reuse);
  out.modes_kinematically_feasible = static_cast<long>(modes_.size()) - 1;
  out.tree_nodes = tree_.nodes;
  out.dead_prefixes = static_cast<long>(kinematic_proofs_->size());
  return out;
}

template <class T>
StabilityResult<T> strong_stability(const geometry::PlanarScene& full, const Vec<T>& g,
                                    const StabilityOptions& options) {
  std::vector<Index> touching;
  const MotionModel<T> model = motion_model<T>(touching_scene(full, &touching));
  const std::size_t k = model.mu_s.size();
  const MotionSystem<T> rest = motion_system(model, all_rolling(k), /*zero_acceleration=*/true);
  const exact::StrictSolver<T> rest_solver(rest.system, options.arith);
  // The mode tree is walked as the verdict goes: a verdict with a moving witness stops it there.
  ModeTree<T> tree;
  long dead = 0;
  const ModeString rolling_name = all_rolling(k);
  std::optional<MotionSystem<T>> rolling_ms;
  std::optional<exact::StrictSolver<T>> rolling_solver;
  StabilityResult<T> out = decide(
      touching, rest, rest_solver, g,
      [&](auto&& visit) {
        tree = walk_tree<T>(model, moving_alphabet(k), tree_options(options), [&](const ModeString& m, const Vec<T>&) {
          if (is_all_rolling(m)) return true;
          const MotionSystem<T> ms = motion_system(model, m);
          return visit(ModeLp<T>{m, ms, exact::StrictSolver<T>(ms.system, options.arith)});
        });
        dead = static_cast<long>(tree.dead.size());
      },
      [&] {
        rolling_ms.emplace(motion_system(model, rolling_name));
        rolling_solver.emplace(rolling_ms->system, options.arith);
        return ModeLp<T>{rolling_name, *rolling_ms, *rolling_solver};
      },
      [&](StabilityResult<T>& r) {
        std::vector<ModeProof<T>> proofs = dead_prefix_proofs(std::move(tree.dead));
        const std::size_t n = r.proofs.size() + proofs.size();
        r.proofs.reserve(n, n);  // a growing list would copy its rational vectors
        for (ModeProof<T>& p : proofs) r.proofs.push_back(std::move(p));
      },
      static_cast<ReusedCertificates<T>*>(nullptr));
  out.lps += tree.lps;
  out.lps_checked_from_float += tree.lps_checked_from_float;
  out.modes_kinematically_feasible = 0;
  for (const ModeString& m : tree.modes) out.modes_kinematically_feasible += !is_all_rolling(m);
  out.tree_nodes = tree.nodes;
  out.dead_prefixes = dead;
  return out;
}

template class StabilityOracle<double>;
template class StabilityOracle<Q>;
template StabilityResult<double> strong_stability<double>(const geometry::PlanarScene&, const Vec<double>&,
                                                          const StabilityOptions&);
template StabilityResult<Q> strong_stability<Q>(const geometry::PlanarScene&, const Vec<Q>&, const StabilityOptions&);
template class StabilityOracle<exact::Mpfr>;
template class StabilityOracle<exact::Interval>;
template StabilityResult<exact::Mpfr> strong_stability<exact::Mpfr>(const geometry::PlanarScene&,
                                                                    const Vec<exact::Mpfr>&, const StabilityOptions&);
template StabilityResult<exact::Interval> strong_stability<exact::Interval>(const geometry::PlanarScene&,
                                                                            const Vec<exact::Interval>&,
                                                                            const StabilityOptions&);

}  // namespace contactcert::solvers
