// Hard-case generators for `contactcert bench`: seeded families of instances with one difficulty
// knob each, chosen where a tolerance-based float path is expected to break. Every instance is exact
// (rational data) and can be run on any rung of the arithmetic ladder (queries/bench/rungs.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "geometry/planar_scene.h"
#include "solvers/ucp/problem.h"
#include "solvers/wrench_cone/mode.h"

namespace contactcert::bench {

using exact::Q;
using exact::Vec;

/// Does the quasistatic problem (or generic UCP) have a complementary pair? `known_solvable` is set when
/// the generator knows the answer independently (Proposition 2 instances, by brute force). `text`: the problem
/// as a file (SPEC section 2), which each run reads and builds X and Y from, as a user's run does.
struct UcpQuestion {
  solvers::ucp::UcpProblem problem;
  std::optional<bool> known_solvable;
  std::string text;
};

/// The question of `problem`, with its file text.
UcpQuestion ucp_question(solvers::ucp::UcpProblem problem, std::optional<bool> known_solvable = std::nullopt);

/// Strongly / weakly stable or unstable under wrench g (wrench cone paper, section 7).
struct StabilityQuestion {
  geometry::PlanarScene scene;
  Vec<Q> wrench;
};

/// The wrench cone of a mode (section 5): empty or not, and its generators.
struct ConeQuestion {
  geometry::PlanarScene scene;
  solvers::ModeString mode;
};

using Question = std::variant<UcpQuestion, StabilityQuestion, ConeQuestion>;

/// "ucp", "stability" or "cone".
const char* question_kind(const Question& q);

/// The families of `contactcert bench`.
enum class Family {
  kParallel,    ///< nearly parallel contact normals, angle 10^-1 .. 10^-12 (rational tangent)
  kBoundary,    ///< the wrench on a friction face of the rolling mode cone, moved off it by 0 or +-10^-k
  kLever,       ///< lever arms 10^-k .. 10^k on a 2*10^k x 10^-k plate, k = 0 .. 6
  kDegenerate,  ///< section 5 UCPs with a fraction of fingers stopped: degenerate vertices of X
  kReduction,   ///< Proposition 2 reductions of 0-1 feasibility, n = 4 .. 14 columns
  kLarge,       ///< UCP with nc = 5 .. 40, wrench cones with 2 .. 8 fixels
  kPaper,       ///< the papers' own data (scenes/): the reference for "paper-sized" costs; no knob
};

/// Every family, in report order.
const std::vector<Family>& all_families();
const char* family_name(Family f);
/// One line: what the family stresses and what its knob means.
const char* family_description(Family f);
/// How many distinct knob values the family has (difficulty i / (levels - 1) gives the i-th).
int family_levels(Family f);
/// The family named `name`, or nullopt.
std::optional<Family> parse_family(const std::string& name);

/// One generated instance: which family, the knob's value as readable text, and the question.
struct Instance {
  Family family = Family::kParallel;
  double difficulty = 0;  ///< in [0, 1]: 0 easiest, 1 hardest
  std::string knob;       ///< the knob at this difficulty, e.g. "angle 1e-09"
  std::uint64_t seed = 0;
  Question question;
};

/// The instances of `family` at `difficulty` in [0, 1] for `seed` (deterministic: same arguments, same
/// instances). Scene families give one stability and one cone question; UCP families one UCP question;
/// kLarge gives both a UCP and a cone question; kPaper gives all of its fixed instances at difficulty 0 and
/// seed 1, and nothing otherwise.
std::vector<Instance> generate(Family family, double difficulty, std::uint64_t seed);

}  // namespace contactcert::bench
