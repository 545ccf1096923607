// The aggregation of `contactcert bench` records: instances grouped by a key and summarised per rung, totals per
// rung, and the precision ladder's cell per family and rung (shared by the tables, the plots and the JSON).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "queries/bench_report.h"

namespace contactcert::queries::bench_report {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// max that skips NaN (NaN only if both are).
double nan_max(double a, double b);

/// Instances that share a key (e.g. question kind and knob value), summarised per rung.
struct Group {
  std::string a, b;  ///< the key
  long n = 0;
  std::vector<std::vector<double>> seconds;  ///< per rung, per instance
  std::vector<long> wrong, undecided;
  std::vector<double> violation, xTy, generators;
};

/// Which two columns a table is keyed on.
enum class Key { kFamilyQuestion, kQuestionKnob };

/// The groups of the instances (of `family`, if given) by `key`, in order of first appearance.
std::vector<Group> groups(const BenchRun& run, Key key, std::optional<bench::Family> family = std::nullopt);

/// The families with at least one instance in the run, in the order of bench::all_families.
std::vector<bench::Family> families_in(const BenchRun& run);

/// Rung k summed over the instances.
struct Totals {
  double seconds = 0;
  long wrong = 0, undecided = 0;
};
Totals totals(const BenchRun& run, std::size_t k);

/// One family on one rung: median time, wrong verdicts, undecided, worst error of the decided
/// answers (largest violation, |x^T y| or generator distance; NaN if none applies).
struct LadderCell {
  long n = 0, wrong = 0, undecided = 0;
  double median_seconds = kNaN, worst = kNaN;
};
LadderCell ladder_cell(const BenchRun& run, bench::Family f, std::size_t k);

}  // namespace contactcert::queries::bench_report
