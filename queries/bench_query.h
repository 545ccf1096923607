// The query of `contactcert bench`: the hard-case families (queries/bench/families.h) on the chosen rungs of the
// arithmetic ladder (queries/bench/rungs.h), each instance repeated for a median time, the float answers measured
// against the exact ones; the report files written under `out` (queries/bench_report.h).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "queries/bench_report.h"
#include "queries/limit.h"

namespace contactcert::queries {

struct BenchOptions {
  std::optional<bench::Family> family;                      ///< one family, or every family (the suite "all")
  bool quick = false;                                       ///< 3 difficulties x 5 seeds, 3 repeats (else 12 x 6, 5)
  std::vector<bench::Rung> rungs = bench::default_rungs();  ///< in ladder order, exact last
  std::string out = "contactcert-bench";                    ///< the folder of the report files
  double time_limit = 0;                                    ///< seconds (0 = none), tested between instances
};

struct BenchAnswer {
  BenchRun run;
  std::vector<std::string> files;  ///< the report files written (write_bench_report)
};

/// Called before each instance runs, with "family, knob, seed S (N instances)".
using BenchProgress = std::function<void(const std::string& what)>;

/// "all" (nullopt) or a family's name; InputError naming `field` otherwise.
std::optional<bench::Family> parse_bench_suite(const std::string& text, const std::string& field);
/// A comma-separated list of rung names (bench::parse_rungs); InputError naming `field` for an unknown one.
std::vector<bench::Rung> parse_bench_rungs(const std::string& text, const std::string& field);
/// The rungs' names, comma-separated (the text parse_bench_rungs reads).
std::string rung_names(const std::vector<bench::Rung>& rungs);

/// Runs the suite and writes its report (InputError if `out` cannot be created, before the run); the time limit
/// ends the run between instances with a Limit naming the instances covered.
Limited<BenchAnswer> run_bench(const BenchOptions& options, const BenchProgress& progress = {});

/// `bench --json`: bench_json of the run.
json to_json(const BenchAnswer& answer);
/// The readable report `bench` prints: the tables, a warning per checked rung that disagrees with exact, the
/// files written.
std::string to_text(const BenchAnswer& answer);

}  // namespace contactcert::queries
