// The arithmetic ladder of `contactcert bench`: a list of rungs (float, verified, exact today; more
// precisions can be appended), one runner per question kind written once over the number type, and the
// float-against-exact error measures.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "exact/arith.h"
#include "queries/bench/families.h"

namespace contactcert::bench {

/// One way of answering a question: the arithmetic mode and the working precision in bits of the number
/// type it runs on (53 for double; 0 = unbounded, i.e. rationals).
struct Rung {
  std::string name;
  exact::Arith arith = exact::Arith::kExact;
  int precision_bits = 0;
  /// kFloat rungs: the number type of the unchecked run (double; intervals; MPFR of `bits` bits), for every
  /// question kind (UCP, stability, cone): the same algorithms instantiated for that type.
  exact::Rung number{};
};

/// float (doubles, 1e-9 sign tolerance, unchecked), verified (float proposes, exact checks), adaptive (the
/// checked precision ladder), exact (rationals). The last rung must be exact: the others are measured against it.
const std::vector<Rung>& default_rungs();

/// Every rung `contactcert bench --rungs` knows, in ladder order: float, interval, mpfr113, mpfr256, mpfr1024,
/// verified, adaptive, exact. interval and mpfrN are unchecked runs in that number type (intervals prove
/// every sign they take, or stop as undecided: verdict "unknown"; MPFR floats may be wrong).
const std::vector<Rung>& all_rungs();

/// A comma-separated list of rung names -> those rungs in ladder order, exact always last (added if missing).
/// Throws std::invalid_argument naming an unknown rung.
std::vector<Rung> parse_rungs(const std::string& list);

/// What one rung answered, exactly as it answered it (floats converted to rationals without rounding so
/// that the error measures are exact).
struct Answer {
  std::string verdict;            ///< solvable/jammed/unknown, strongly_stable/weakly_stable/unstable, empty/non_empty
  Vec<Q> x, y;                    ///< ucp: the pair (if solvable)
  Vec<Q> forces;                  ///< stability: the resting contact forces (if any)
  exact::Mat<double> generators;  ///< cone: the closure's rays and both signs of its lines, unit length
  std::string failure;            ///< non-empty if the rung threw (budget, singular basis on the float path, ...)
};

/// Runs `question` on `rung` (dispatches to the runner of the question's kind instantiated on the rung's
/// number type). Never throws: a failure is recorded in Answer::failure with verdict "failed".
Answer run_rung(const Question& question, const Rung& rung);

/// The error of an answer against the exact one (computed exactly, except the generator distance: unit vectors
/// in double). NaN: the measure does not apply (another question kind, or no point to measure).
struct Errors {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  bool wrong_verdict = false;         ///< both decided and different
  bool undecided = false;             ///< the rung failed or said unknown where the exact path decided
  double violation = kNone;           ///< ucp, stability: largest constraint violation, relative to max(1, |rhs|)
  double xTy = kNone;                 ///< ucp: |x^T y| of the rung's pair
  double generator_distance = kNone;  ///< cone: Hausdorff distance of the unit generators; 2 if one is empty
};

/// Measures `answer` to `question` against `exact_answer`.
Errors measure(const Question& question, const Answer& answer, const Answer& exact_answer);

/// The largest of an answer's errors, with a wrong verdict counting as 1 (the y axis of the report's plot).
double worst_error(const Errors& e);

}  // namespace contactcert::bench
