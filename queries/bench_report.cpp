// `contactcert bench --out DIR`: the text, markdown, SVG and JSON reports and the HTML page that gathers them.
#include "queries/bench_report.h"

#include <filesystem>

#include "exact/input_error.h"
#include "queries/bench_tables.h"
#include "queries/html_report.h"

namespace contactcert::queries {

using namespace bench_report;

std::vector<std::string> write_bench_report(const BenchRun& run, const std::string& dir) {
  create_output_dir(dir);
  const auto path = [&](const char* name) { return (std::filesystem::path(dir) / name).string(); };
  std::vector<std::string> written = {path("report.txt"), path("report.md"), path("time_vs_error.svg"),
                                      path("bench.json"), path("precision_ladder.svg")};
  write_text_file(written[0], bench_text(run));
  write_text_file(written[1], bench_markdown(run));
  const std::string svg = bench_svg(run);
  write_text_file(written[2], svg);
  write_text_file(written[3], bench_json(run).dump(1) + "\n");
  const std::string ladder = ladder_svg(run);
  write_text_file(written[4], ladder);
  HtmlReport html("contactcert bench: speed against error");
  html.preformatted(header_text(run));
  html.figure(svg,
              "Each dot is one instance on one rung: its median time and its largest error against the exact "
              "answer. Errors of exactly 0 sit in the bottom strip and errors of 1 or more (a wrong or undecided "
              "answer counts as 1) in the top one, a row per rung with its count of dots at the right; dots that "
              "would cover each other there are moved up or down.");
  html.heading("summary by family");
  for (const Table& t : split(table(run, Key::kFamilyQuestion), run.rungs.size())) html.table(t.header, t.rows);
  for (bench::Family f : families_in(run)) {
    html.heading(bench::family_name(f));
    html.paragraph(bench::family_description(f));
    for (const Table& t : split(table(run, Key::kQuestionKnob, f), run.rungs.size())) html.table(t.header, t.rows);
  }
  html.paragraph(kLegend);
  html.heading("precision ladder");
  html.figure(ladder,
              "One point per family and rung: the median time over the family's instances and the worst error of "
              "its decided answers (any wrong or undecided answer: 1, in the top strip; exactly 0: the bottom "
              "strip, a row per family).");
  for (bench::Family f : families_in(run)) {
    const Table t = ladder_table(run, f);
    html.heading(std::string(bench::family_name(f)) + ": precision ladder");
    html.paragraph(ladder_summary(run, f));
    html.table(t.header, t.rows);
  }
  html.paragraph(kLadderLegend);
  written.push_back(html.write(dir));
  return written;
}

}  // namespace contactcert::queries
