// `design`: exact search for fixel placements (wrench cone paper, sections 7-10: "the intended use of our
// algorithm was fixture design"). Every choice of `fixels` among the candidate boundary points is decided exactly
// (solvers/design/evaluate.h); the best `top` are re-decided with their evidence, their scenes and certificates
// written under `out`; the placements are shared out by a Distributor (serial, or MPI under mpirun), with a
// checkpoint to resume from and budgets on time and placements.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "queries/scene_input.h"
#include "solvers/design/distribute.h"
#include "solvers/design/evaluate.h"
#include "solvers/design/problem.h"
#include "solvers/design/ranking.h"
#include "solvers/design/symmetry.h"

namespace contactcert::queries {

/// Budget on the candidate set (each candidate is a few hundred bytes and one membership test per placement).
inline constexpr long kMaxDesignCandidates = 100000;
/// Most placements reported with `top` (each writes its scene and certificates).
inline constexpr int kMaxDesignTop = 1000;
/// Largest `chunk_size` (a chunk is the unit of work of one rank and of the checkpoint).
inline constexpr long kMaxDesignChunkSize = 1000000000;

struct DesignOptions {
  CommonOptions common;
  std::string candidates;  ///< "N" (equally spaced in arc length) or a file {"candidates": [[x, y], ...]}
  std::string lattice;     ///< or a pitch p: the lattice points (i p, j p) on the boundary
  int fixels = 3;          ///< 2 or 3
  std::optional<std::string> stable_under;  ///< "fx,fy,tz[;...]" (a list) or "cone:fx,fy,tz;..." (generators)
  bool insertable = false;                  ///< G_goal non-empty
  bool goal_push = false;                   ///< G_goal holds a push at one of the push points (insertable implied)
  std::string goal_wrench;                  ///< G_goal holds this wrench "fx,fy,tz" (insertable implied)
  std::optional<solvers::Rank> rank;        ///< default: margin with stable_under, else the goal fraction
  int top = 5;
  std::string out = "contactcert-design";  ///< folder of the placement scenes, certificates and design.svg
  std::string checkpoint;                  ///< resume from and save to this file ("" = none)
  long chunk_size = 16;
  long push_points = 120;
  long max_placements = 100000000;  ///< budget: placements evaluated in this run
};

/// "margin" | "goal-fraction"; InputError naming `field` otherwise.
solvers::Rank parse_rank(const std::string& text, const std::string& field);

/// One reported placement, re-decided with its evidence; its files are `stem` + ".json" (the scene),
/// "_wrench_K.cert.json" (K = 1, 2, ...), "_goal.cert.json" and "_goal_wrench.cert.json" (when insertable).
struct PlacementReport {
  std::size_t position = 0;  ///< 1 = best
  solvers::Ranked ranked;
  solvers::PlacementEvidence evidence;
  std::string stem;
};

/// The report of a finished search.
struct DesignReport {
  std::string scene_name;
  std::optional<std::string> stable_under;
  solvers::DesignProblem problem;
  std::string candidate_source;  ///< how the candidates were chosen, e.g. "equally spaced in arc length"
  long placements = 0;           ///< C(N, fixels)
  std::size_t symmetries = 0;    ///< non-trivial symmetries of the candidate set
  solvers::DesignStatistics statistics;
  std::vector<PlacementReport> top;
  std::string svg;  ///< the picture's file
};

/// How a run ended on this rank: kFinished (the root, with the report), kWorkerFinished (another rank, all chunks
/// done), kLimit (another rank, stopped by the root's budget; the root returns the Limit), kRefused (a checkpoint
/// that does not fit; on the root with the message naming the file and field).
enum class DesignStatus { kFinished, kWorkerFinished, kLimit, kRefused };

struct DesignRun {
  DesignStatus status = DesignStatus::kFinished;
  std::string refusal;                 ///< kRefused, on the root
  std::optional<DesignReport> report;  ///< kFinished
};

/// Progress text while chunks finish ("12 of 120 placements, 40/s on 2 ranks, about 3 s left").
using DesignProgress = std::function<void(const std::string&)>;

/// The whole search on this rank of `dist` (every rank calls it). `progress`, if set, is called on the root.
/// Bad input: InputError naming the option or field; an error on one rank ends every rank (Distributor::abort_all).
/// A budget (time, --max-placements) stops the search with a Limit on the root: what was covered.
Limited<DesignRun> run_design(const SceneInput& in, const DesignOptions& o, solvers::Distributor& dist,
                              const DesignProgress& progress = {});

/// `design --json`.
json to_json(const DesignReport& r);
/// The requirements as a person reads them ("strongly stable under ..., insertable (G_goal non-empty, ...)").
std::string requirement_text(const DesignReport& r);
/// "evaluated N, accepted A, ..., LPs L".
std::string statistics_text(const solvers::DesignStatistics& s);
/// The picture's caption of a placement ("candidates 1, 4, 7: margin^2 0.125").
std::string placement_caption(const solvers::DesignProblem& problem, const solvers::Ranked& r);
/// "1, 4, 7": a placement's candidate indices.
std::string candidate_list_text(const solvers::Placement& placement);
/// The wrench whose margin is least (ranked by margin).
std::size_t worst_margin(const solvers::PlacementEvidence& ev);
/// The share of the push points whose push seats the placement, in lowest terms.
exact::Q goal_fraction(const solvers::DesignProblem& problem, const solvers::PlacementEvidence& ev);

}  // namespace contactcert::queries
