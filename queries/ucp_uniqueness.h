// `ucp --all`: is the motion of the single instant unique? After the solve, the prefix tree of
// solvers/motion/uniqueness.h (the one simulate runs per step) finds every solution mode and bounds each body
// velocity component over their faces: `unique` (one q_dot) or `not unique` (the distinct q_dot found). Its
// certificate is the kind simulate writes per step, motion_uniqueness (docs/formats.md section 5). A jammed problem
// has no solution, so no motion (`no_motion`): the jamming certificate is the proof, and no tree is walked.
#pragma once

#include <optional>
#include <string>

#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "solvers/motion/simulate.h"
#include "solvers/motion/uniqueness.h"
#include "solvers/ucp/problem.h"
#include "solvers/ucp/solve.h"

namespace contactcert::queries {

/// `ucp --all`'s options: the question asked, the prefix tree's LP budget (simulate's --max-modes) and the file
/// of the motion_uniqueness certificate ("" = none).
struct UniquenessOptions {
  bool all = false;
  std::optional<long> max_modes;  ///< unset: simulate's default (SimulateOptions::max_uniqueness_modes)
  std::string certificate;
};

/// The verdict (without its evidence once written) and the certificate written (text and file; both empty when
/// none was asked or the verdict is no_motion).
struct UniquenessAnswer {
  solvers::motion::MotionUniqueness verdict;
  std::string certificate_text;
  std::string certificate;
};

/// Refuses (InputError naming the option) --max-modes or --uniqueness-certificate without --all, and --all on the
/// float path.
void check_uniqueness_options(const UniquenessOptions& o, exact::Arith arith);

/// With --all, the uniqueness of the quasistatic problem's motion: a solvable one's by the prefix tree, its certificate
/// written if asked (`assembly_text` embedded, as the UCP certificates do); a jammed one's is no_motion (0 LPs, no
/// certificate); nullopt without --all or for an undecided (unknown) solve. The Limit when the prefix tree's budget
/// runs out, with the LPs it covered; `command` names the run in that Limit.
Limited<std::optional<UniquenessAnswer>> decide_uniqueness(const solvers::ucp::UcpProblem& problem,
                                                           const solvers::ucp::UcpReport& report,
                                                           const UniquenessOptions& o, exact::Arith arith,
                                                           const std::string& command,
                                                           const std::string& assembly_text = "");

/// {"status", "motions", "modes", "solution_modes", "unbounded", "lps"}: a verdict as simulate's steps and `ucp
/// --all` print it.
json uniqueness_json(const solvers::motion::MotionUniqueness& u);
/// uniqueness_json and, if written, "certificate": the file.
json to_json(const UniquenessAnswer& a);
/// "  uniqueness: unique" or "not unique" and the motions, q_dot per body of `body_size` components (3 for an
/// assembly's bodies; a problem file's q_dot is one body of nq), or "no motion" and where its proof is.
std::string to_text(const UniquenessAnswer& a, long body_size);

}  // namespace contactcert::queries
