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

}  // namespace

template <class T>
StabilityOracle<T>::StabilityOracle(const geometry::PlanarScene& full, const StabilityOptions& options)
    : scene_(budgeted_touching_scene(full, options, touching_)),
      rest_(motion_system<T>(scene_, all_rolling(scene_.fixels.size()), /*zero_acceleration=*/true)),
      rest_solver_(rest_.system, options.arith) {
  // Kinematic feasibility of each moving mode: its kinematic rows alone (they do not involve g).
  const std::size_t k = scene_.fixels.size();
  for (const ModeString& mode : moving_modes(k)) {
    Mode m{mode, motion_system<T>(scene_, mode), std::nullopt, {}};
    const auto kin = exact::strict_feasibility(m.ms.kinematic(), options.arith);
    preparation_lps_ += kin.lps;
    if (kin.rounded_float_checked) preparation_lps_checked_from_float_ += kin.lps;
    if (kin.status == StrictStatus::kFeasible) {
      m.solver.emplace(m.ms.system, options.arith);
    } else {
      m.kinematic_proof = Vec<T>::Zero(m.ms.system.A.rows());
      m.kinematic_proof.head(m.ms.kinematic_rows) = kin.motzkin;
    }
    modes_.push_back(std::move(m));
  }
  Mode rolling{all_rolling(k), motion_system<T>(scene_, all_rolling(k)), std::nullopt, {}};
  rolling.solver.emplace(rolling.ms.system, options.arith);
  modes_.push_back(std::move(rolling));
}

template <class T>
StabilityResult<T> StabilityOracle<T>::verdict(const Vec<T>& g) const {
  StabilityResult<T> out;
  out.touching = touching_;
  auto count = [&out](const exact::StrictFeasibility<T>& f) {
    out.lps += f.lps;
    if (f.rounded_float_checked) out.lps_checked_from_float += f.lps;
  };

  // Resting solutions: J c + g = 0 with every c in its static friction cone.
  const auto r = rest_solver_.solve(rest_.rhs(g));
  count(r);
  out.has_resting = r.status == StrictStatus::kFeasible;
  if (out.has_resting)
    out.resting_forces = rest_.forces(r.x);
  else
    out.resting_farkas = r.motzkin;

  // Moving solutions: every mode but n..n, then n..n, which moves only if vdot != 0 (null space of J^T).
  for (const Mode& m : modes_) {
    const bool rolling = &m == &modes_.back();
    if (rolling && out.has_resting) break;  // then every all-rolling solution has vdot = 0
    ++out.modes_checked;
    if (!m.solver) {
      out.proofs.push_back({m.mode, true, m.kinematic_proof});
      continue;
    }
    if (!rolling) ++out.modes_kinematically_feasible;
    const auto f = m.solver->solve(m.ms.rhs(g));
    count(f);
    if (f.status == StrictStatus::kFeasible && (!rolling || nonzero<T>(m.ms.acceleration(f.x)))) {
      out.has_moving = true;
      out.moving = {m.mode, m.ms.forces(f.x), m.ms.acceleration(f.x)};
      break;
    }
    if (!rolling) out.proofs.push_back({m.mode, false, f.motzkin});
  }
  if (out.has_moving) out.proofs.clear();  // no longer evidence of anything
  out.verdict = !out.has_resting ? StabilityVerdict::kUnstable
                : out.has_moving ? StabilityVerdict::kWeaklyStable
                                 : StabilityVerdict::kStronglyStable;
  return out;
}

template <class T>
StabilityResult<T> strong_stability(const geometry::PlanarScene& scene, const Vec<T>& g,
                                    const StabilityOptions& options) {
  const StabilityOracle<T> oracle(scene, options);
  StabilityResult<T> out = oracle.verdict(g);
  out.lps += oracle.preparation_lps();
  out.lps_checked_from_float += oracle.preparation_lps_checked_from_float();
  return out;
}

std::string check_stability(const geometry::PlanarScene& full, const Vec<Q>& g, const StabilityResult<Q>& claim) {
  const geometry::PlanarScene scene = touching_scene(full);
  const std::size_t k = scene.fixels.size();
  if (g.size() != 3) return "the wrench must have 3 entries";
  const MotionSystem<Q> rest = motion_system<Q>(scene, all_rolling(k), true);
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
    const MotionSystem<Q> ms = motion_system<Q>(scene, w.mode);
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
      const MotionSystem<Q> ms = motion_system<Q>(scene, p.mode);
      if (p.kinematic) {
        bool zero_tail = p.motzkin.size() == ms.system.A.rows();
        for (Index j = ms.kinematic_rows; zero_tail && j < p.motzkin.size(); ++j) zero_tail = sgn(p.motzkin(j)) == 0;
        if (!zero_tail || !exact::verify_motzkin(ms.kinematic(), p.motzkin.head(ms.kinematic_rows)))
          return "the kinematic proof for mode " + p.mode.text() + " does not verify";
      } else if (!exact::verify_motzkin(ms.with_wrench(g), p.motzkin)) {
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
