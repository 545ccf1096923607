// The query of `contactcert modes FILE`: every kinematically feasible augmented contact mode of a planar scene from
// rest (wrench cone paper, Table 2), each with a witness, found by the prefix tree of solvers/stability/mode_tree.h,
// and the tree as a completeness proof (the "modes" certificate) for `contactcert check`.
#pragma once

#include <map>
#include <string>

#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "queries/scene_input.h"
#include "solvers/stability/contact_modes.h"

namespace contactcert::queries {

/// The time budget of the enumerations whose letters overlap (--unions, a printed `s`), whose list can be
/// exponential in the fixels, when no time limit is given.
inline constexpr double kModesDefaultSeconds = 60;

struct ModesOptions {
  CommonOptions common;    ///< exact or verified (float is refused); time_limit 0: see time_budget()
  bool kinematic = false;  ///< list the accelerations only, no witness wrench
  bool unions = false;     ///< also the letters m (l, r or n) and u (s or a)
  Table2 table2 = Table2::kStrict;
  long max_nodes = solvers::ModeTreeOptions{}.max_nodes;  ///< prefixes visited at most
  long max_modes = solvers::ModeTreeOptions{}.max_modes;  ///< modes listed at most
  std::string certificate;                                ///< the file the proof is written to ("" = none)
  /// Overlapping letters with no time limit: the run takes the default budget kModesDefaultSeconds.
  bool default_time_budget() const;
  /// The seconds the run may take (0 = no limit).
  double time_budget() const;
};

struct ModesAnswer {
  ModesOptions options;
  solvers::ContactModes modes;
  std::string certificate_text;  ///< the certificate written ("" = none)
};

/// Writes a modes certificate's `text` to `file` and returns it, unless it is larger than the kMaxInputBytes that
/// `check` reads: then BudgetExceeded (a Limit of the query) with the counts of the list (no certificate written).
std::string write_modes_certificate(const std::string& file, std::string text, std::size_t modes, std::size_t dead);

/// The feasible modes (InputError for --arith float; a Limit past a budget, or for a certificate larger than
/// `check` reads), the certificate written where asked.
Limited<ModesAnswer> run_modes(const SceneInput& input, const ModesOptions& options);

/// The number of modes of each group (solvers::mode_group), by group name.
std::map<std::string, long> mode_counts(const solvers::ContactModes& modes);

/// The object `modes --json` prints.
json to_json(const ModesAnswer& answer);

}  // namespace contactcert::queries
