#include "solvers/stability/strong_stability.h"

#include "exact/input_error.h"

namespace contactcert::solvers {

using exact::StrictStatus;
using Index = Eigen::Index;

const char* verdict_name(StabilityVerdict v) {
  switch (v) {
    case StabilityVerdict::kStronglyStable: return "strongly_stable";
    case StabilityVerdict::kWeaklyStable: return "weakly_stable";
    case StabilityVerdict::kUnstable: return "unstable";
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
  static constexpr Interaction kLetters[] = {Interaction::kSeparate, Interaction::kSlideLeft,
                                             Interaction::kSlideRight, Interaction::kRoll};
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

}  // namespace

template <class T>
StabilityResult<T> strong_stability(const geometry::PlanarScene& full, const Vec<T>& g,
                                    const StabilityOptions& options) {
  StabilityResult<T> out;
  const geometry::PlanarScene scene = touching_scene(full, &out.touching);
  const std::size_t k = scene.fixels.size();
  if (k > 8 || (std::size_t{1} << (2 * k)) > static_cast<std::size_t>(options.max_modes))
    throw exact::BudgetExceeded("strong stability over " + std::to_string(k) + " touching fixels needs 4^" +
                                    std::to_string(k) + " modes",
                                "no mode checked");

  // Resting solutions: J c + g = 0 with every c in its static friction cone.
  const MotionSystem<T> rest = motion_system<T>(scene, all_rolling(k), /*zero_acceleration=*/true);
  const auto r = exact::strict_feasibility(rest.with_wrench(g), options.arith);
  out.lps += r.lps;
  out.has_resting = r.status == StrictStatus::kFeasible;
  if (out.has_resting) out.resting_forces = rest.forces(r.x);
  else out.resting_farkas = r.motzkin;

  // Moving solutions: every mode but n..n, kinematic feasibility first (independent of g).
  std::vector<ModeString> modes = moving_modes(k);
  modes.push_back(all_rolling(k));  // last: n..n moves only if vdot != 0 (null space of J^T)
  for (const ModeString& mode : modes) {
    const bool rolling = &mode == &modes.back();
    if (rolling && out.has_resting) break;  // then every all-rolling solution has vdot = 0
    const MotionSystem<T> ms = motion_system<T>(scene, mode);
    ++out.modes_checked;
    if (!rolling) {
      const auto kin = exact::strict_feasibility(ms.kinematic(), options.arith);
      out.lps += kin.lps;
      if (kin.status == StrictStatus::kInfeasible) {
        Vec<T> y = Vec<T>::Zero(ms.system.A.rows());
        y.head(ms.kinematic_rows) = kin.motzkin;
        out.proofs.push_back({mode, true, y});
        continue;
      }
      ++out.modes_kinematically_feasible;
    }
    const auto f = exact::strict_feasibility(ms.with_wrench(g), options.arith);
    out.lps += f.lps;
    if (f.status == StrictStatus::kFeasible && (!rolling || nonzero<T>(ms.acceleration(f.x)))) {
      out.has_moving = true;
      out.moving = {mode, ms.forces(f.x), ms.acceleration(f.x)};
      break;
    }
    if (!rolling) out.proofs.push_back({mode, false, f.motzkin});
  }
  if (out.has_moving) out.proofs.clear();  // no longer evidence of anything
  out.verdict = !out.has_resting ? StabilityVerdict::kUnstable
                : out.has_moving ? StabilityVerdict::kWeaklyStable
                                 : StabilityVerdict::kStronglyStable;
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
    // Rebuild the system's point from the forces: c_n, c_t, then the slacks mu_s c_n -+ c_t.
    Vec<Q> x = Vec<Q>::Zero(rest.system.A.cols());
    if (claim.resting_forces.size() != static_cast<Index>(2 * k)) return "resting forces have the wrong size";
    for (std::size_t i = 0; i < k; ++i) {
      const Index cn = rest.c_n_column[i], ct = rest.c_t_column[i];
      const Q c_n = claim.resting_forces(static_cast<Index>(i)), c_t = claim.resting_forces(static_cast<Index>(k + i));
      x(cn) = c_n;
      x(ct) = c_t;
      x(ct + 1) = scene.fixels[i].mu_s * c_n - c_t;
      x(ct + 2) = scene.fixels[i].mu_s * c_n + c_t;
    }
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
    // M vdot = J c + g and Table 2 for its mode, checked on the motion system's point.
    const MotionSystem<Q> ms = motion_system<Q>(scene, w.mode);
    Vec<Q> x = Vec<Q>::Zero(ms.system.A.cols());
    x.head(3) = w.acceleration;
    const Mat<Q>& A = ms.system.A;
    for (std::size_t i = 0; i < k; ++i) {
      const Index cn = ms.c_n_column[i], ct = ms.c_t_column[i];
      if (cn >= 0) x(cn) = w.forces(static_cast<Index>(i));
      if (ct >= 0) {
        x(ct) = w.forces(static_cast<Index>(k + i));
        x(ct + 1) = scene.fixels[i].mu_s * x(cn) - x(ct);
        x(ct + 2) = scene.fixels[i].mu_s * x(cn) + x(ct);
      } else if (cn >= 0 && w.forces(static_cast<Index>(k + i)) != ms.c_t_per_c_n[i] * x(cn)) {
        return "a sliding force is not on the edge of its friction cone";
      } else if (cn < 0 && (sgn(w.forces(static_cast<Index>(i))) != 0 || sgn(w.forces(static_cast<Index>(k + i))) != 0)) {
        return "a separating contact carries force";
      }
    }
    // Kinematic slacks: each strict slack column appears in exactly one kinematic row with entry +-1.
    for (Index row = 0; row < ms.kinematic_rows; ++row)
      for (Index j = 3; j < A.cols(); ++j)
        if (sgn(A(row, j)) != 0) {
          Q a = 0;
          for (Index d = 0; d < 3; ++d) a += A(row, d) * x(d);
          x(j) = -a / A(row, j);
        }
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

template StabilityResult<double> strong_stability<double>(const geometry::PlanarScene&, const Vec<double>&,
                                                          const StabilityOptions&);
template StabilityResult<Q> strong_stability<Q>(const geometry::PlanarScene&, const Vec<Q>&, const StabilityOptions&);

}  // namespace contactcert::solvers
