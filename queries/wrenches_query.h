// Many stability verdicts on one scene (a planner's question): `contactcert stability FILE --wrenches FILE` and
// Python's Oracle. One solvers::StabilityOracle is prepared for the scene (the touching fixels, the mode tree with its
// g-independent proofs, one LP per feasible moving mode); each verdict then decides 1 + (modes visited) LPs, in a
// batch each infeasible one by a certificate of an earlier wrench where one applies (solvers/stability/
// reused_certificates.h), else by its LP.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "queries/limit.h"
#include "queries/stability_query.h"

namespace contactcert::queries {

/// The oracle of one scene in the run's number type (Q on the exact and verified paths, double with float), prepared
/// under the time limit of `common` (exact::BudgetExceeded past it, for with_limits to turn into a Limit; a
/// verdict itself has no budget to exceed).
class StabilityVerdicts {
 public:
  StabilityVerdicts(const geometry::PlanarScene& scene, const CommonOptions& common);
  /// The verdict for g, as strong_stability's; its lps count only the LPs solved for g.
  StabilityOutcome verdict(const exact::Vec<exact::Q>& g) const;
  /// The answer for g: run_stability's without margin or certificate, except for lps (g's only) and the mode tree
  /// (walked whole by the preparation, where a single verdict stops at the first mode that moves).
  StabilityAnswer answer(const exact::Vec<exact::Q>& g) const;
  /// The same from g's verdict (one of verdicts(...)).
  StabilityAnswer answer(const exact::Vec<exact::Q>& g, StabilityOutcome verdict) const;
  /// The verdicts for many wrenches in a row, each verdict(g)'s (the same verdict, witnesses and counts; a system
  /// proved infeasible for an earlier wrench may be decided by that certificate instead of its LP).
  std::vector<StabilityOutcome> verdicts(const std::vector<exact::Vec<exact::Q>>& wrenches) const;
  /// LPs solved while preparing.
  long preparation_lps() const;
  /// The arithmetic of its verdicts (never adaptive) and the scene's force frames (of every fixel).
  exact::Arith arith() const { return arith_; }
  const solvers::ForceFrames& frames() const { return *frames_; }

 private:
  geometry::PlanarScene scene_;
  exact::Arith arith_;
  std::optional<solvers::StabilityOracle<exact::Q>> exact_;
  std::optional<solvers::StabilityOracle<double>> float_;
  std::shared_ptr<const solvers::ForceFrames> frames_;  // of every fixel, for the answers' contact forces
};

struct WrenchesOptions {
  CommonOptions common;  ///< adaptive runs as verified (scene_arith); the time limit bounds the preparation
  std::string wrenches;  ///< the file of wrenches (read_wrenches)
};

struct WrenchesAnswer {
  exact::Arith arith = exact::Arith::kVerified;     ///< as run (never adaptive)
  std::vector<exact::Vec<exact::Q>> wrenches;       ///< in the file's order
  std::vector<solvers::StabilityVerdict> verdicts;  ///< one per wrench
  std::array<long, 3> counts{};                     ///< strongly stable, weakly stable, unstable
  long lps = 0;                                     ///< the preparation's and every verdict's
};

/// The wrenches of a file: a JSON array of [fx, fy, tz], or text with one "fx,fy,tz" per line (blank lines and
/// lines starting with # skipped). InputError names the file and the entry.
std::vector<exact::Vec<exact::Q>> read_wrenches(const std::string& path);

/// One verdict per wrench of options.wrenches, from one StabilityVerdicts.
Limited<WrenchesAnswer> run_wrenches(const SceneInput& input, const WrenchesOptions& options);

/// The object `stability --wrenches --json` prints: each wrench with its verdict, the counts, arith and lps.
json to_json(const WrenchesAnswer& answer);

}  // namespace contactcert::queries
