// The report of `contactcert bench`: per-instance records, a table per family (plain text, markdown, HTML),
// an SVG plot of time against error (one series per rung, log scales) and the same numbers as JSON.
#pragma once

#include <string>
#include <vector>

#include "queries/bench/rungs.h"
#include "queries/json_out.h"

namespace contactcert::queries {

/// One rung's result on one instance.
struct RungRecord {
  std::string verdict;
  std::string failure;
  double median_seconds = 0;
  int repeats = 0;
  bench::Errors errors;  ///< against the exact rung (all zero / NaN for the exact rung itself)
};

/// One instance with a record per rung (in the order of BenchRun::rungs).
struct InstanceRecord {
  bench::Family family = bench::Family::kParallel;
  std::string kind, knob;
  double difficulty = 0;
  std::uint64_t seed = 0;
  std::vector<RungRecord> rungs;
};

struct BenchRun {
  std::string suite;
  bool quick = false;
  int max_repeats = 0;
  std::vector<bench::Rung> rungs;  ///< the last one is exact
  std::vector<InstanceRecord> instances;
  double seconds = 0;  ///< wall time of the whole run
};

/// The median (NaN if empty).
double median(std::vector<double> v);
/// Rung records whose verdict differs from the exact rung's (the verified rung must have none).
long disagreements(const BenchRun& run, std::size_t rung);

/// Everything, for scripts: the rungs, a summary per family and rung, and every instance.
json bench_json(const BenchRun& run);
/// A table per family, aligned plain text.
std::string bench_text(const BenchRun& run);
/// A table per family, markdown.
std::string bench_markdown(const BenchRun& run);
/// Time (x) against error (y), log scales, one series per rung; an error of exactly 0 sits on the bottom line.
std::string bench_svg(const BenchRun& run);
/// The precision ladder: one point per family and rung, median time against the worst error.
std::string ladder_svg(const BenchRun& run);
/// The precision ladder as text: per family, a row per rung (median time, wrong verdicts, undecided, worst error).
std::string ladder_text(const BenchRun& run);
/// Writes DIR/report.txt, report.md, time_vs_error.svg, bench.json, precision_ladder.svg and index.html; returns
/// the paths.
std::vector<std::string> write_bench_report(const BenchRun& run, const std::string& dir);

}  // namespace contactcert::queries
