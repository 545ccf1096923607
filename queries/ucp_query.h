// `ucp FILE`: does the quasistatic contact problem (Pang, Trinkle, Lo) have a solution (x, y in X x Y, x^T y = 0)?
// `ucp --generate random|reduction`: a problem of the paper's section 5 generator or of Proposition 2's reduction
// of a 0-1 problem. One typed query under the CLI and Python: the options (defaults written once, here or in
// solvers/ucp/solve.h), the whole run (solve, recover, certificate file, budgets) and its --json object.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/contact_frame.h"
#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "queries/ucp_uniqueness.h"
#include "solvers/ucp/problem.h"
#include "solvers/ucp/solve.h"

namespace contactcert::queries {

/// A `ucp` problem as a query reads it (docs/formats.md section 2): its name (for messages), its text (what
/// `check --problem` compares), the problem, and for a `"kind": "quasistatic_scene"` its contact frames (else
/// empty), with the CPU seconds of reading it (parse) and of building X and Y (build) and the wall-clock seconds of
/// both.
struct UcpInput {
  std::string name;
  std::string text;
  solvers::ucp::UcpProblem problem;
  std::vector<geometry::ContactFrame> frames;
  solvers::ucp::UcpPhases setup;
  double seconds = 0;
};

/// The problem in `text` named `name`; InputError naming the file and the field.
UcpInput parse_ucp(const std::string& text, const std::string& name);
/// The problem in the file `path` (read once), as parse_ucp; reading the file counts as parse.
UcpInput load_ucp(const std::string& path);

/// The options of `ucp FILE`. A budget left unset is the solver's default (solvers::ucp::UcpOptions); one that
/// `method` would ignore is refused (check_ucp_options).
struct UcpQueryOptions {
  CommonOptions common;
  solvers::ucp::Method method = solvers::ucp::Method::kComplete;
  std::uint64_t seed = 1;         ///< the random choices of Step 3
  std::optional<long> max_nodes;  ///< node budget of the complete search
  std::optional<long> max_bases;  ///< Step 3: bases explored per degenerate vertex
  std::string certificate;        ///< file the certificate of the verdict is written to ("" = none)
  UniquenessOptions uniqueness;   ///< --all: is the solvable problem's motion unique?
  std::function<void(long units, long lps)> progress;  ///< search nodes (or enumerated modes) so far
};

/// "paper" | "modified" | "complete" | "enumerate"; InputError naming `field` otherwise.
solvers::ucp::Method parse_method(const std::string& text, const std::string& field);
/// Refuses (InputError naming the option) what the run would ignore or cannot do: --max-nodes without the complete
/// search's tree, --max-bases without Step 3 (method enumerate), a certificate from the float path or from
/// method enumerate (whose jammed verdict has no proof tree), --all's options without it (check_uniqueness_options).
void check_ucp_options(const UcpQueryOptions& o);

/// The verdict with its evidence, the certificate written (its text, and `certificate` the file, or both empty if
/// none was asked or the verdict is unknown), the frames of the problem's contacts (a quasistatic_scene) and with
/// --all the uniqueness of a decided problem's motion (no_motion when jammed).
struct UcpAnswer {
  solvers::ucp::UcpReport report;
  std::string certificate_text;
  std::string certificate;
  std::vector<geometry::ContactFrame> frames;
  std::optional<UniquenessAnswer> uniqueness;
};

/// Solves `in` (check_ucp_options first), writes the certificate file if asked and one exists; `report.seconds`
/// counts reading the input too. The search's own budgets end it `unknown` with what it covered; a budget deeper
/// down (an LP's pivots) and --all's prefix tree budget (--max-modes) are the Limit.
Limited<UcpAnswer> run_ucp(const UcpInput& in, const UcpQueryOptions& o);

/// The Limit of a run that stopped on a budget or the time limit (report.limited), as `ucp` and `assembly --ucp`
/// report it in place of their `unknown` answer: the reason and what the run covered (its nodes, pairs and LPs);
/// nullopt for an answer (an `unknown` of the bilinear method that cannot decide is one).
std::optional<Limit> limit_of(const solvers::ucp::UcpReport& r);

/// The head of the JSON object of a UCP report, shared by `ucp` and `assembly --ucp`: status, reason, the method
/// (with_method: `ucp`'s) and the arithmetic.
json report_head_json(const solvers::ucp::UcpReport& r, bool with_method);

/// The object `ucp --json` prints: status, reason, the pair, its physical reading (with the world forces of each
/// contact of a quasistatic_scene under physical.contacts), counts, the certificate file and the timings.
json to_json(const UcpAnswer& a);

/// The generators of `ucp --generate`.
enum class UcpGenerator { kRandom, kReduction };

/// `ucp --generate random|reduction`: random's nc contacts, friction in (0, mu_max) and |abar| effort-controlled
/// joints; reduction's rows x cols 0-1 problem, with a planted solution or not.
struct UcpGenerateOptions {
  UcpGenerator generator = UcpGenerator::kRandom;
  std::uint64_t seed = 1;
  int nc = 3;
  exact::Q mu_max = 1;
  int abar = 0;
  int rows = 2, cols = 6;
  bool planted = false;
};

/// "random" | "reduction"; InputError naming `field` otherwise.
UcpGenerator parse_generator(const std::string& text, const std::string& field);
/// An exact number (SPEC section 1) given as option `field`; InputError naming it otherwise.
exact::Q parse_exact_option(const std::string& text, const std::string& field);

/// The generated problem (its `source` names the generator and the seed); InputError naming the options out of
/// range.
solvers::ucp::UcpProblem generate_ucp(const UcpGenerateOptions& o);

}  // namespace contactcert::queries
