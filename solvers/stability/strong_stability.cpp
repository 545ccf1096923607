#include "solvers/stability/strong_stability.h"

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
  std::vector<ModeString> out;
  std::size_t total = 1;
  for (std::size_t i = 0; i < k; ++i) total *= 4;
  for (std::size_t code = 0; code + 1 < total; ++code) {  // the last code is n..n
    ModeString m;
    std::size_t c = code;
    for (std::size_t i = 0; i < k; ++i, c /= 4) m.letters.push_back(kLetters[c % 4]);
    out.push_back(m);
  }
  return out;
}

namespace {

ModeString all_rolling(std::size_t k) { return ModeString{std::vector<Interaction>(k, Interaction::kRoll)}; }

template <class T>
bool nonzero(const Vec<T>& v) {
  for (Index i = 0; i < v.size(); ++i)
    if (!exact::is_zero(v(i))) return true;
  return false;
}

// The touching fixels of the scene, within the budget on 4^k modes.
geometry::PlanarScene budgeted_touching_scene(const geometry::PlanarScene& full, const StabilityOptions& options,
                                              std::vector<Index>& touching) {
  geometry::PlanarScene scene = touching_scene(full, &touching);
  const std::size_t k = scene.fixels.size();
  if (k > 8 || (std::size_t{1} << (2 * k)) > static_cast<std::size_t>(options.max_modes))
    throw exact::BudgetExceeded(
        "strong stability over " + std::to_string(k) + " touching fixels needs 4^" + std::to_string(k) + " modes",
        "no mode checked");
  return scene;
}

// A moving mode prepared for verdicts: its system and LP if it is kinematically feasible (n..n always is);
// else only its Motzkin certificate on the kinematic rows, padded with zeros to every row of its system (it
// holds for all g; the system itself is not built).
template <class T>
struct PreparedMode {
  MotionSystem<T> ms;
  std::optional<exact::StrictSolver<T>> solver;
  Vec<T> kinematic_proof;
  long lps = 0, lps_checked_from_float = 0;  // the kinematic LP's
};

// Prepares the modes of a scene one by one, in the order a verdict visits them. A kinematic proof y of one mode
// also proves every later mode that has each row y weighs: per fixel, the normal row is the same for the letters
// l, r, n (a_n = 0) and another for s (a_n - sigma = 0); the tangent row is its letter's own (l, r, n). Column by
// column the conditions of strict_feasibility.h on y then hold as before (vdot: the same rows; a sigma column:
// the same entries where y weighs, zero elsewhere), so such a mode gets y, moved to its rows, without an LP.
template <class T>
class ModePreparer {
 public:
  ModePreparer(const MotionModel<T>& model, exact::Arith arith) : model_(model), arith_(arith) {}

  PreparedMode<T> operator()(const ModeString& mode, bool rolling) {
    PreparedMode<T> p;
    if (!rolling) {
      if (reuse(mode, p.kinematic_proof)) return p;
      auto kin = exact::strict_feasibility(kinematic_system(model_, mode), arith_);
      p.lps = kin.lps;
      if (kin.rounded_float_checked) p.lps_checked_from_float = kin.lps;
      if (kin.status != StrictStatus::kFeasible) {
        p.kinematic_proof = Vec<T>::Zero(motion_system_rows(mode));
        p.kinematic_proof.head(kin.motzkin.size()) = kin.motzkin;
        remember(mode, std::move(kin.motzkin));
        return p;
      }
    }
    p.ms = motion_system(model_, mode);
    p.solver.emplace(p.ms.system, arith_);
    return p;
  }

 private:
  struct Known {
    ModeString mode;
    std::vector<bool> normal, tangent;  // per fixel: y is non-zero on its normal / tangent row
    Vec<T> y;                           // on the kinematic rows of `mode`
  };

  // The first kinematic row of each fixel (its normal row; l r n have a tangent row after it).
  static std::vector<Index> first_rows(const ModeString& mode) {
    std::vector<Index> first;
    Index r = 0;
    for (Interaction L : mode.letters) {
      first.push_back(r);
      r += L == Interaction::kSeparate ? 1 : 2;
    }
    return first;
  }

  void remember(const ModeString& mode, Vec<T> y) {
    const std::vector<Index> first = first_rows(mode);
    const std::size_t k = first.size();
    std::vector<bool> normal(k), tangent(k, false);
    for (std::size_t i = 0; i < k; ++i) {
      normal[i] = !exact::is_zero(y(first[i]));
      if (mode.letters[i] != Interaction::kSeparate) tangent[i] = !exact::is_zero(y(first[i] + 1));
    }
    known_.push_back({mode, std::move(normal), std::move(tangent), std::move(y)});
  }

  bool reuse(const ModeString& mode, Vec<T>& proof) const {
    auto separates = [](Interaction L) { return L == Interaction::kSeparate; };
    for (const Known& known : known_) {
      bool same = true;
      for (std::size_t i = 0; same && i < known.normal.size(); ++i) {
        const Interaction was = known.mode.letters[i], is = mode.letters[i];
        same = (!known.normal[i] || separates(was) == separates(is)) && (!known.tangent[i] || was == is);
      }
      if (!same) continue;
      const std::vector<Index> from = first_rows(known.mode), to = first_rows(mode);
      proof = Vec<T>::Zero(motion_system_rows(mode));
      for (std::size_t i = 0; i < known.normal.size(); ++i) {
        if (known.normal[i]) proof(to[i]) = known.y(from[i]);
        if (known.tangent[i]) proof(to[i] + 1) = known.y(from[i] + 1);
      }
      return true;
    }
    return false;
  }

  const MotionModel<T>& model_;
  exact::Arith arith_;
  std::vector<Known> known_;
};

// The modes a verdict visits: moving_modes(k), then n..n (it moves only if vdot != 0).
std::vector<ModeString> verdict_modes(std::size_t k) {
  std::vector<ModeString> modes = moving_modes(k);
  modes.push_back(all_rolling(k));
  return modes;
}

// Mode i as the verdict sees it: its system, and its LP or none (kinematically infeasible).
template <class T>
struct ModeLp {
  const MotionSystem<T>* ms;
  const exact::StrictSolver<T>* solver;
};

// The verdict for g (SPEC section 7): the resting LP, then the modes of verdict_modes in order until one moves.
// mode_at(i, out) gives mode i; for a kinematically infeasible one it appends the mode's proof to out.proofs if
// out.has_resting (only then is it evidence). Every other moving mode gets its proof from its LP here; at most
// `own_proofs` proofs are the result's own (the others are shared).
template <class T, class ModeAt>
StabilityResult<T> decide(const std::vector<Index>& touching, const MotionSystem<T>& rest,
                          const exact::StrictSolver<T>& rest_solver, const std::vector<ModeString>& modes,
                          const Vec<T>& g, std::size_t own_proofs, ModeAt&& mode_at) {
  StabilityResult<T> out;
  out.touching = touching;
  auto count = [&out](const exact::StrictFeasibility<T>& f) {
    out.lps += f.lps;
    if (f.rounded_float_checked) out.lps_checked_from_float += f.lps;
  };

  // Resting solutions: J c + g = 0 with every c in its static friction cone.
  auto r = rest_solver.solve(rest.rhs(g));
  count(r);
  out.has_resting = r.status == StrictStatus::kFeasible;
  if (out.has_resting) {
    out.resting_forces = rest.forces(r.x);
    out.proofs.reserve(modes.size() - 1, own_proofs);
  } else {
    out.resting_farkas = std::move(r.motzkin);
  }

  // Moving solutions: every mode but n..n, then n..n, which moves only if vdot != 0 (null space of J^T).
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const bool rolling = i + 1 == modes.size();
    if (rolling && out.has_resting) break;  // then every all-rolling solution has vdot = 0
    ++out.modes_checked;
    const ModeLp<T> m = mode_at(i, out);
    if (!m.solver) continue;
    if (!rolling) ++out.modes_kinematically_feasible;
    auto f = m.solver->solve(m.ms->rhs(g));
    count(f);
    if (f.status == StrictStatus::kFeasible && (!rolling || nonzero<T>(m.ms->acceleration(f.x)))) {
      out.has_moving = true;
      out.moving = {modes[i], m.ms->forces(f.x), m.ms->acceleration(f.x)};
      break;
    }
    if (!rolling && out.has_resting) out.proofs.push_back({modes[i], false, std::move(f.motzkin)});
  }
  if (out.has_moving) out.proofs.clear();  // no longer evidence of anything
  out.verdict = !out.has_resting ? StabilityVerdict::kUnstable
                : out.has_moving ? StabilityVerdict::kWeaklyStable
                                 : StabilityVerdict::kStronglyStable;
  return out;
}

}  // namespace

template <class T>
StabilityOracle<T>::StabilityOracle(const geometry::PlanarScene& full, const StabilityOptions& options)
    : model_(motion_model<T>(budgeted_touching_scene(full, options, touching_))),
      rest_(motion_system(model_, all_rolling(model_.mu_s.size()), /*zero_acceleration=*/true)),
      rest_solver_(rest_.system, options.arith),
      mode_names_(verdict_modes(model_.mu_s.size())) {
  // Kinematic feasibility of each moving mode: its kinematic rows alone (they do not involve g).
  auto proofs = std::make_shared<std::vector<ModeProof<T>>>();
  ModePreparer<T> prepare(model_, options.arith);
  modes_.reserve(mode_names_.size());
  for (std::size_t i = 0; i < mode_names_.size(); ++i) {
    PreparedMode<T> p = prepare(mode_names_[i], i + 1 == mode_names_.size());
    preparation_lps_ += p.lps;
    preparation_lps_checked_from_float_ += p.lps_checked_from_float;
    modes_.push_back({std::move(p.ms), std::move(p.solver), proofs->size()});
    if (!modes_.back().solver) proofs->push_back({mode_names_[i], true, std::move(p.kinematic_proof)});
  }
  kinematic_proofs_ = std::move(proofs);
}

template <class T>
StabilityResult<T> StabilityOracle<T>::verdict(const Vec<T>& g) const {
  const std::size_t own = mode_names_.size() - 1 - kinematic_proofs_->size();  // the LPs' proofs
  return decide(touching_, rest_, rest_solver_, mode_names_, g, own, [this](std::size_t i, StabilityResult<T>& out) {
    const Mode& m = modes_[i];
    if (!m.solver && out.has_resting) out.proofs.push_shared(kinematic_proofs_, m.kinematic_proof);
    return ModeLp<T>{&m.ms, m.solver ? &*m.solver : nullptr};
  });
}

template <class T>
StabilityResult<T> strong_stability(const geometry::PlanarScene& full, const Vec<T>& g,
                                    const StabilityOptions& options) {
  std::vector<Index> touching;
  const MotionModel<T> model = motion_model<T>(budgeted_touching_scene(full, options, touching));
  const std::size_t k = model.mu_s.size();
  const MotionSystem<T> rest = motion_system(model, all_rolling(k), /*zero_acceleration=*/true);
  const exact::StrictSolver<T> rest_solver(rest.system, options.arith);
  const std::vector<ModeString> modes = verdict_modes(k);
  ModePreparer<T> prepare(model, options.arith);
  std::optional<PreparedMode<T>> current;  // the mode being decided
  return decide(touching, rest, rest_solver, modes, g, modes.size() - 1, [&](std::size_t i, StabilityResult<T>& out) {
    current.emplace(prepare(modes[i], i + 1 == modes.size()));
    out.lps += current->lps;
    out.lps_checked_from_float += current->lps_checked_from_float;
    if (!current->solver && out.has_resting)
      out.proofs.push_back({modes[i], true, std::move(current->kinematic_proof)});
    return ModeLp<T>{&current->ms, current->solver ? &*current->solver : nullptr};
  });
}

std::string check_stability(const geometry::PlanarScene& full, const Vec<Q>& g, const StabilityResult<Q>& claim) {
  const geometry::PlanarScene scene = touching_scene(full);
  const std::size_t k = scene.fixels.size();
  if (g.size() != 3) return "the wrench must have 3 entries";
  const MotionModel<Q> model = motion_model<Q>(scene);
  const MotionSystem<Q> rest = motion_system(model, all_rolling(k), true);
  // Resting evidence: a point (J c + g = 0, c in the friction cones) or a Motzkin certificate.
  bool resting = false;
  if (claim.has_resting) {
    if (claim.resting_forces.size() != static_cast<Index>(2 * k)) return "resting forces have the wrong size";
    const Vec<Q> x = rest.point(Vec<Q>(), claim.resting_forces);
    if (!exact::verify_strict_point(rest.with_wrench(g), x))
      return "the resting forces do not balance the wrench inside the friction cones";
    resting = true;
  } else if (!exact::verify_motzkin(rest.with_wrench(g), claim.resting_farkas)) {
    return "the certificate that no resting solution exists does not verify";
  }
  // Moving evidence: a witness solution, or one proof per moving mode.
  bool moving = false;
  if (claim.has_moving) {
    const MotionWitness<Q>& w = claim.moving;
    if (w.mode.letters.size() != k) return "the witness mode has the wrong length";
    if (w.acceleration.size() != 3 || w.forces.size() != static_cast<Index>(2 * k)) return "witness sizes";
    bool nz = false;
    for (Index i = 0; i < 3; ++i) nz = nz || sgn(w.acceleration(i)) != 0;
    if (!nz) return "the witness does not move";
    // M vdot = J c + g and Table 2 for its mode, checked on the motion system's point; the forces the
    // mode fixes (which point() does not read) are checked here.
    const MotionSystem<Q> ms = motion_system(model, w.mode);
    for (std::size_t i = 0; i < k; ++i) {
      const Index cn = ms.c_n_column[i], ct = ms.c_t_column[i];
      const Q& c_n = w.forces(static_cast<Index>(i));
      const Q& c_t = w.forces(static_cast<Index>(k + i));
      if (cn >= 0 && ct < 0 && c_t != ms.c_t_per_c_n[i] * c_n)
        return "a sliding force is not on the edge of its friction cone";
      if (cn < 0 && (sgn(c_n) != 0 || sgn(c_t) != 0)) return "a separating contact carries force";
    }
    const Vec<Q> x = ms.point(w.acceleration, w.forces);
    if (!exact::verify_strict_point(ms.with_wrench(g), x)) return "the moving witness violates its mode";
    moving = true;
  } else if (resting) {
    const std::vector<ModeString> modes = moving_modes(k);
    if (claim.proofs.size() != modes.size()) return "expected one proof per moving mode";
    for (std::size_t i = 0; i < modes.size(); ++i) {
      const ModeProof<Q>& p = claim.proofs[i];
      if (p.mode.text() != modes[i].text()) return "proof " + std::to_string(i) + " is for the wrong mode";
      if (p.kinematic) {
        // The kinematic rows lead the mode's system: the certificate is zero on every other row.
        const exact::SparseStrictSystem<Q> kin = kinematic_system(model, p.mode);
        bool zero_tail = p.motzkin.size() == motion_system_rows(p.mode);
        for (Index j = kin.rows; zero_tail && j < p.motzkin.size(); ++j) zero_tail = sgn(p.motzkin(j)) == 0;
        if (!zero_tail || !exact::verify_motzkin(kin.dense(), p.motzkin.head(kin.rows)))
          return "the kinematic proof for mode " + p.mode.text() + " does not verify";
      } else if (!exact::verify_motzkin(motion_system(model, p.mode).with_wrench(g), p.motzkin)) {
        return "the proof for mode " + p.mode.text() + " does not verify";
      }
    }
  }
  const StabilityVerdict v = !resting ? StabilityVerdict::kUnstable
                             : moving ? StabilityVerdict::kWeaklyStable
                                      : StabilityVerdict::kStronglyStable;
  if (v != claim.verdict) return std::string("the evidence supports ") + verdict_name(v);
  return "";
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
