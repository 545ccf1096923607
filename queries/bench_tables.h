// The tables of `contactcert bench`: a row per group of instances (times, cost ratios, errors per rung) and the
// precision ladder per family, as aligned text, markdown or HTML rows.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "queries/bench_aggregate.h"

namespace contactcert::queries::bench_report {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// printf of one number.
std::string fmt(const char* f, double x);
/// A row per group: times per rung, the cost of each rung over the first, and each inexact rung's errors.
Table table(const BenchRun& run, Key key, std::optional<bench::Family> family = std::nullopt);
/// A wide table of table() as tables that fit a page: each repeats the 3 key columns; the first holds the times
/// and ratios (2R - 1 columns), the others the error columns of two inexact rungs each (4 per rung).
std::vector<Table> split(const Table& t, std::size_t rungs);
/// The table as aligned plain text / as markdown.
std::string aligned(const Table& t);
std::string markdown(const Table& t);
/// The run's first lines: suite, instances, repeats, and the totals per rung.
std::string header_text(const BenchRun& run);
/// The family's precision ladder: a row per rung.
Table ladder_table(const BenchRun& run, bench::Family f);
/// "Where does the family stop making wrong verdicts?": the rungs (unchecked ones included) with none.
std::string ladder_summary(const BenchRun& run, bench::Family f);

/// What the columns of table() mean; what the precision ladder shows.
extern const char* const kLegend;
extern const char* const kLadderLegend;

}  // namespace contactcert::queries::bench_report
