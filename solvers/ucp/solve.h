// One entry point for `contactcert ucp` and the benchmarks: runs a chosen method on a problem and
// gathers the verdict with its evidence (pair, recovered physics and conditions (2)-(10), counts, proof).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "exact/arith.h"
#include "solvers/ucp/float_check.h"
#include "solvers/ucp/phases.h"
#include "solvers/ucp/recovery.h"
#include "solvers/ucp/search.h"

namespace contactcert::solvers::ucp {

/// paper / modified: the bilinear algorithm of section 4 with the paper's or the modified Step 3 (it can
/// prove "jammed" only when X or Y is empty); complete: bilinear first, then the exact search (SPEC default);
/// enumerate: the contact-mode baseline.
enum class Method { kPaper, kModified, kComplete, kEnumerate };

/// "paper" | "modified" | "complete" | "enumerate" (throws std::invalid_argument otherwise).
Method parse_method(const std::string& name);
const char* method_name(Method m);
const char* status_name(UcpStatus s);

struct UcpOptions {
  Method method = Method::kComplete;
  Arith arith = Arith::kVerified;
  /// --arith float: the number type of the unchecked run (doubles by default; intervals or MPFR of `bits` bits
  /// for the bench's precision ladder). An uncertain interval sign ends the run as `unknown`.
  exact::Rung float_rung{};
  std::uint64_t seed = 1;
  long max_nodes = 200000;            ///< complete search node budget
  long max_enumerate_lps = 1L << 22;  ///< enumerate: refuse (unknown) above this many modes
  int max_random_moves = 20;          ///< bilinear: Step 3 random moves before giving up
  long max_bases = 100000;            ///< bilinear Step 3: bases explored per degenerate vertex
  double time_limit = 0;              ///< seconds of wall clock for the whole run (0 = none): then `unknown`
  std::function<void(long units, long lps)> progress;  ///< search nodes or enumerated modes so far
};

/// The verdict with its evidence. On the exact and verified paths every number is exact; on the float
/// path only the `_approx` members are filled and nothing is proven.
struct UcpReport {
  UcpStatus status = UcpStatus::kUnknown;
  std::string reason;
  /// kUnknown because a budget ran out (the complete search's nodes, the time limit), not because the method cannot
  /// decide (the bilinear algorithm's stationary pair, an uncertain interval sign): the run stopped on a limit.
  bool limited = false;
  Method method = Method::kComplete;
  Arith arith = Arith::kVerified;
  /// The complementary pair (exact paths, kSolvable), over a common denominator: x->to_q() or (*x)(i) give
  /// rationals (an adaptive solve makes none).
  std::optional<exact::RationalVector> x, y;
  std::optional<Q> best_xTy;       ///< smallest x^T y seen (exact paths)
  Vec<double> x_approx, y_approx;  ///< float path
  Vec<Q> x_float, y_float;         ///< float path in MPFR or intervals: the pair's values exactly (interval midpoints)
  double best_xTy_approx = 0;
  std::optional<PhysicalSolution> physical;   ///< quasistatic problems, kSolvable
  std::optional<ConditionsCheck> conditions;  ///< (2)-(10) checked exactly on `physical`
  long pairs = 0, lps = 0, nodes = 0, learned_prunes = 0;
  long incomplete_adjacencies = 0;  ///< Step 3 enumerations cut short by max_bases or by a float basis (face_lp.h)
  long solutions = -1;              ///< enumerate: solution modes (-1 = not counted)
  std::vector<std::string> solution_modes;
  std::optional<SearchResult<Q>> proof;  ///< kJammed on an exact path: the tree for the certificate
  /// --arith adaptive: the rung of the precision ladder whose verdict decided ("double", "interval",
  /// "mpfr113", "mpfr256", "exact"); empty otherwise.
  std::string decided_by;
  /// --arith adaptive and verified, kJammed by a float rung: how the leaves of its search tree were proven exactly,
  /// and those whose face was not empty in exact arithmetic, each re-searched exactly below it (float_check.h).
  LeafProofs leaves;
  /// Wall seconds of the whole run: solve_ucp sets its own (solve + recover + check); a caller that also parses,
  /// builds or writes a certificate covers those too (`contactcert ucp` does).
  double seconds = 0;
  UcpPhases phases;  ///< CPU seconds per phase (the caller fills parse, build and certificate)
};

/// Runs the method; never throws for budgets (status kUnknown says so).
UcpReport solve_ucp(const UcpProblem& problem, const UcpOptions& opts);

/// The certificate text of a verdict on an exact path (certificate.h): the proof tree of kJammed, the pair of
/// kSolvable; empty if the report has neither.
std::string certificate_text(const UcpProblem& problem, const UcpReport& r, const std::string& assembly_text = "");

}  // namespace contactcert::solvers::ucp
