// `contactcert simulate SCENE`: quasistatic time-stepping of a motion scene (docs/motion.md): the typed options,
// the whole run (the exact or verified trajectory, the float one beside it with --compare and where they part, each
// step's certificate written to a folder, the animated picture) and the JSON of the trajectory.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "solvers/motion/compare.h"
#include "solvers/motion/simulate.h"

namespace contactcert::queries {

/// A motion scene as a query reads it: the file's name (for messages), its text and the parsed scene.
struct MotionInput {
  std::string name;
  std::string text;
  solvers::motion::MotionScene scene;
};

/// The motion scene in `text` named `name`; InputError naming the file and field (a scene without "motion" too).
MotionInput parse_motion(const std::string& text, const std::string& name);
/// The motion scene in the file `path`, as parse_motion.
MotionInput load_motion(const std::string& path);

/// The step size H of `--dt`: an exact number > 0 ("1/10", "0.1", "1e-3"); InputError naming `field` otherwise.
exact::Q parse_dt(const std::string& text, const std::string& field);

/// The options of a run; the solver's defaults (budgets) are taken from solvers::motion::SimulateOptions.
struct SimulateOptions {
  CommonOptions common;        ///< arith (verified; adaptive runs as verified), time limit for the whole command
  std::optional<long> steps;   ///< N (1 to 10^6), else the scene's
  std::optional<exact::Q> dt;  ///< H > 0, else the scene's
  bool compare = false;        ///< also run the float path and report where it first differs
  bool uniqueness = solvers::motion::SimulateOptions{}.uniqueness;  ///< decide per step whether the motion is unique
  long max_modes = solvers::motion::SimulateOptions{}.max_uniqueness_modes;  ///< the uniqueness prefix tree's LP budget
  long max_nodes = solvers::ucp::UcpOptions{}.max_nodes;                     ///< each step's complete search budget
  std::string certificates;  ///< folder for step-K.json (each step's certificate), "" = none
  std::string svg;           ///< the animated picture's file, "" = none
};

/// A run's answer: the trajectory in the run's arithmetic (exact_run on the exact and verified paths, float_run on
/// the float path) and, with compare, the float trajectory beside the exact one and their divergences.
struct SimulateAnswer {
  std::string file;
  solvers::motion::MotionScene scene;
  exact::Arith arith = exact::Arith::kVerified;
  exact::Q dt;
  long steps = 0;  ///< N asked
  std::optional<solvers::motion::Trajectory<exact::Q>> exact_run;
  std::optional<solvers::motion::Trajectory<double>> float_run;
  bool compared = false;
  std::vector<solvers::motion::Divergence> divergences;
  std::vector<std::string> certificates;  ///< per step of exact_run: the file written, or "" (none asked)
  /// per step of exact_run: its uniqueness certificate's file (step-K-uniqueness.json), or "" (none written)
  std::vector<std::string> uniqueness_certificates;
  std::string svg;  ///< the picture's file, if written
  double seconds = 0;
};

/// A run in progress (the Python generator): next() makes one step of the run in the answer's arithmetic, writes
/// its certificate and returns the step's JSON (as in to_json's "steps"); finish() makes the rest, the float run
/// and the comparison (compare), the picture, and returns the answer. The time limit counts from construction.
class SimulateRun {
 public:
  /// InputError naming the option for bad options (checked before any step).
  SimulateRun(const MotionInput& input, const SimulateOptions& options);
  /// The next step's JSON, or nullopt once the run has ended.
  std::optional<json> next();
  SimulateAnswer finish();
  const SimulateOptions& options() const { return options_; }

 private:
  bool advance();
  SimulateOptions options_;
  solvers::motion::SimulateOptions solver_;
  std::chrono::steady_clock::time_point start_;
  SimulateAnswer answer_;
  std::optional<solvers::motion::Stepper<exact::Q>> exact_;
  std::optional<solvers::motion::Stepper<double>> float_;
  bool finished_ = false;
};

/// Runs the scene (writing the certificates and the picture where asked): SimulateRun(input, options).finish().
/// A budget or the time limit ends the run `unknown` with the steps done (see stopped_by_budget); a budget deeper
/// down (an LP's pivots) is the Limit.
Limited<SimulateAnswer> run_simulate(const MotionInput& input, const SimulateOptions& options);

/// How the run of the answer's arithmetic ended, why, and how many steps it made.
solvers::motion::RunStatus run_status(const SimulateAnswer& a);
const std::string& run_reason(const SimulateAnswer& a);
std::size_t steps_done(const SimulateAnswer& a);
/// The run ended `unknown` (a budget or the time limit): exit 3, with the steps done.
bool stopped_by_budget(const SimulateAnswer& a);

/// The trajectory as JSON (docs/motion.md): per step exact strings with `_approx` float views beside them (the
/// float path: the views only), the final state and, with compare, the float run and the divergences.
json to_json(const SimulateAnswer& a);

}  // namespace contactcert::queries
