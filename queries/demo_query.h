// The query of `contactcert demo`: both papers' worked examples on the scenes of a folder (default the bundled
// ones), every verdict exact and every "no" checked by the independent checker: the wrench cones of section 4 and
// Figure 4, strong stability (section 7, Figure 5), sensorless insertion (sections 8-9, Figures 6, 10, 11), Data
// Sets 1-4 and a small Table 1 of the quasistatic paper, and every other scene of the folder. The answer holds each
// example's result; the HTML report with its pictures is written under `out`.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "queries/json_out.h"
#include "queries/limit.h"
#include "solvers/stability/strong_stability.h"
#include "solvers/ucp/solve.h"

namespace contactcert::queries {

struct DemoOptions {
  std::string scenes;                   ///< the folder of scene files ("" = the bundled scenes)
  std::string out = "contactcert-out";  ///< the folder of the report (index.html) and its pictures
  double time_limit = 0;                ///< seconds (0 = none), tested between worked examples
};

/// Section 4 and Figure 4: the wrench cone of a scene's mode (F = K^F P).
struct DemoCone {
  std::string scene, mode;
  bool empty = false;
  long dimension = -1;
  exact::Mat<exact::Q> generators;  ///< the closure's rays
  std::size_t open_faces = 0;
};

/// Section 7: the verdict under a wrench, its evidence and its certificate as the checker judged it.
struct DemoStability {
  exact::Vec<exact::Q> wrench;
  solvers::StabilityVerdict verdict = solvers::StabilityVerdict::kUnstable;
  std::string evidence;  ///< the moving mode and its acceleration, or how many mode proofs
  bool certificate_valid = false;
  std::string certificate_reason;  ///< why the checker refused it ("" when valid)
  long lps = 0;
};

/// Figure 5: the stable region's cells and the frictionless finger pushes by arc of the boundary.
struct DemoRegion {
  std::size_t cells = 0;
  int strongly_stable_regions = 0;  ///< cells of dimension 3 labelled strongly stable
  struct Push {
    std::string piece;  ///< the arc in words (boundary_text.h)
    solvers::StabilityVerdict verdict = solvers::StabilityVerdict::kUnstable;
  };
  std::vector<Push> pushes;
};

/// Sections 8-9, Figure 11: G_goal of a scene with every fixel's mu_s = mu_k = mu, and the pushes that seat it.
struct DemoInsertion {
  std::string scene, mu;                     ///< mu as the demo writes it (e.g. "0.01")
  std::size_t cones = 0, non_redundant = 0;  ///< the wrench cones of the union, those not redundant
  std::vector<std::string> pushes;           ///< the pieces of the boundary in words
  double boundary_fraction = 0;
};

/// Pang, Trinkle and Lo: a Data Set's verdict with its evidence.
struct DemoDataSet {
  int data_set = 0;
  solvers::ucp::UcpStatus status = solvers::ucp::UcpStatus::kUnknown;
  std::optional<exact::Q> xTy;  ///< of the solution (solvable)
  long pairs = 0, lps = 0;
  std::string evidence;  ///< the solution and conditions (2)-(10), the jamming certificate's check, or the reason
  double seconds = 0;
};

/// A row of the small Table 1: a random problem of section 5 solved by each method.
struct DemoRandomProblem {
  int nc = 0, abar = 0;
  exact::Q mu_max;
  struct Run {
    solvers::ucp::Method method = solvers::ucp::Method::kPaper;
    solvers::ucp::UcpStatus status = solvers::ucp::UcpStatus::kUnknown;
    long pairs = 0, lps = 0;
    double seconds = 0;
  };
  std::array<Run, 3> runs;  ///< paper, modified, complete
};

/// A scene of the folder that is not one of the papers' examples.
struct DemoScene {
  std::string file, kind, verdict, evidence;
};

struct DemoAnswer {
  std::string scenes;  ///< the folder read
  std::vector<DemoCone> cones;
  std::vector<DemoStability> stability;
  std::optional<DemoRegion> region;
  std::vector<DemoInsertion> insertion;
  std::vector<DemoDataSet> data_sets;
  std::vector<DemoRandomProblem> table1;
  std::vector<DemoScene> scenes_of_folder;
  std::string report;  ///< the path of index.html
  double seconds = 0;
};

/// Called with each line of the readable report as soon as it is known (demo_text's lines, in order).
using DemoProgress = std::function<void(const std::string& line)>;

/// Runs every worked example whose scenes are in the folder, and every other scene of it, and writes the report
/// (InputError if the folder does not exist, `out` cannot be created or a paper's scene cannot be read; the
/// time limit ends the run between examples with a Limit naming what was covered, as does a budget inside one).
Limited<DemoAnswer> run_demo(const DemoOptions& options, const DemoProgress& progress = {});

/// `demo --json`.
json to_json(const DemoAnswer& answer);
/// The readable report `demo` prints.
std::string demo_text(const DemoAnswer& answer);

/// The rows of a cone's generators, "(a, b, c), (d, e, f)" ("none" if there are none).
std::string generators_text(const exact::Mat<exact::Q>& M);
/// The lines of demo_text, one per part of the answer (each ends in "\n").
std::string demo_header_line(const std::string& scenes);
std::string demo_line(const DemoCone& c);
std::string demo_line(const DemoStability& s);
std::string demo_line(const DemoRegion& r);
std::string demo_insertion_line(const std::vector<DemoInsertion>& rows);
std::string demo_line(const DemoDataSet& d);
std::string demo_table1_line(const std::vector<DemoRandomProblem>& rows);
std::string demo_line(const DemoScene& s);
std::string demo_report_line(const DemoAnswer& answer);

}  // namespace contactcert::queries
