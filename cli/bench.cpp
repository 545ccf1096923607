// `contactcert bench [--suite NAME] [--quick] [--rungs LIST] [--json] [--out DIR]`: runs the
// hard-case families (queries/bench/families.h) on the chosen rungs of the arithmetic ladder (default float,
// verified, adaptive, exact; also interval and MPFR 113/256/1024 bits) in one run and reports, per
// instance, the median time of each rung and the float path's error against the exact answer (the query:
// queries/bench_query.h).
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "cli/command.h"
#include "cli/progress_line.h"
#include "queries/bench_query.h"

namespace contactcert::cli {
namespace {

struct BenchArgs {
  std::string suite = "all";
  bool quick = false;
  bool json = false;
  std::string out = BenchOptions{}.out;
  std::string rungs = rung_names(BenchOptions{}.rungs);
  double time_limit = 0;
};

int bench_command(const BenchArgs& a) {
  BenchOptions o;
  o.family = parse_bench_suite(a.suite, "--suite");
  o.quick = a.quick;
  o.rungs = parse_bench_rungs(a.rungs, "--rungs");
  o.out = a.out;
  o.time_limit = a.time_limit;
  ProgressLine progress("bench");
  const Limited<BenchAnswer> r = run_bench(o, [&](const std::string& what) { progress.update(what); });
  progress.finish();
  if (!r) return report_limit("bench", r.limit(), a.json);
  const BenchAnswer& answer = *r;
  if (a.json)
    std::cout << to_json(answer).dump() << "\n";
  else
    std::cout << to_text(answer);
  return 0;
}

}  // namespace

void register_bench(CLI::App& app, Action& action) {
  auto opts = std::make_shared<BenchArgs>();
  CLI::App* sub = app.add_subcommand(
      "bench", "Speed against error: hard-case families on the float, verified and exact paths (docs/bench.md)");
  std::vector<std::string> suites = {"all"};
  for (bench::Family f : bench::all_families()) suites.push_back(bench::family_name(f));
  sub->add_option("--suite", opts->suite, "all, or one family")->check(CLI::IsMember(suites))->capture_default_str();
  sub->add_flag("--quick", opts->quick, "3 difficulties x 5 seeds per family, 3 repeats (well under two minutes)");
  sub->add_flag("--json", opts->json, "Machine output: one JSON object on stdout (also written to DIR/bench.json)");
  sub->add_option("--rungs", opts->rungs,
                  "Comma-separated rungs, run in ladder order (exact always added): float, interval, mpfr113, "
                  "mpfr256, mpfr1024, verified, adaptive, exact. interval/mpfrN answer every question unchecked in "
                  "that number type (an uncertain interval sign: undecided)")
      ->capture_default_str();
  sub->add_option(
         "--out", opts->out,
         "Directory for report.txt, report.md, time_vs_error.svg, precision_ladder.svg, bench.json, index.html")
      ->capture_default_str();
  add_time_limit(*sub, opts->time_limit);
  sub->callback([opts, &action] { action = [opts] { return bench_command(*opts); }; });
}

}  // namespace contactcert::cli
