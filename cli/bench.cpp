// `contactcert bench [--suite NAME] [--quick] [--rungs LIST] [--json] [--out DIR]`: runs the
// hard-case families of bench/families on the chosen rungs of the arithmetic ladder (default float, verified,
// adaptive, exact; also interval and MPFR 113/256/1024 bits) in one run and reports, per
// instance, the median time of each rung and the float path's error against the exact answer.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/bench/rungs.h"
#include "cli/bench_report.h"
#include "cli/command.h"
#include "cli/progress_line.h"
#include "exact/input_error.h"

namespace contactcert::cli {
namespace {

struct BenchOptions {
  std::string suite = "all";
  bool quick = false;
  bool json = false;
  std::string out = "contactcert-bench";
  std::string rungs = "float,verified,adaptive,exact";
};

/// Which instances a run covers: quick = 3 difficulties x 5 seeds; full = every knob value (at most 12 per
/// family) x 6 seeds. A rung repeats an instance up to `repeats` times but stops after kRepeatSeconds.
struct Plan {
  std::vector<bench::Family> families;
  int levels = 0;  ///< knob values per family, at most
  int seeds = 0;
  int repeats = 0;
  /// `levels` (or fewer) difficulties evenly spread over [0, 1].
  std::vector<double> difficulties(bench::Family f) const {
    const int n = std::min(bench::family_levels(f), levels);
    std::vector<double> d;
    for (int i = 0; i < n; ++i) d.push_back(n == 1 ? 0.0 : static_cast<double>(i) / (n - 1));
    return d;
  }
};
constexpr double kRepeatSeconds = 0.5;

/// Runs one instance on every rung: the first run's answer, the median time over the repeats.
InstanceRecord run_instance(const bench::Instance& inst, const std::vector<bench::Rung>& rungs, int repeats) {
  InstanceRecord rec{inst.family, bench::question_kind(inst.question), inst.knob, inst.difficulty, inst.seed, {}};
  std::vector<bench::Answer> answers;
  for (const bench::Rung& rung : rungs) {
    std::vector<double> times;
    std::optional<bench::Answer> first;
    double spent = 0;
    do {
      const auto t0 = std::chrono::steady_clock::now();
      bench::Answer a = bench::run_rung(inst.question, rung);
      times.push_back(seconds_since(t0));
      spent += times.back();
      if (!first) first = std::move(a);
    } while (static_cast<int>(times.size()) < repeats && spent < kRepeatSeconds);
    answers.push_back(std::move(*first));
    RungRecord r;
    r.verdict = answers.back().verdict;
    r.failure = answers.back().failure;
    r.repeats = static_cast<int>(times.size());
    r.median_seconds = median(times);
    rec.rungs.push_back(r);
  }
  for (std::size_t k = 0; k + 1 < rungs.size(); ++k)
    rec.rungs[k].errors = bench::measure(inst.question, answers[k], answers.back());
  return rec;
}

int run_bench(const BenchOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  create_output_dir(o.out);  // fail before the run, not after it
  std::vector<bench::Rung> rungs;
  try {
    rungs = bench::parse_rungs(o.rungs);
  } catch (const std::invalid_argument& e) {
    throw exact::InputError("command line", "--rungs", std::string("a list of known rungs: ") + e.what());
  }
  Plan plan;
  plan.families = o.suite == "all" ? bench::all_families() : std::vector<bench::Family>{*bench::parse_family(o.suite)};
  plan.levels = o.quick ? 3 : 12;
  plan.seeds = o.quick ? 5 : 6;
  plan.repeats = o.quick ? 3 : 5;
  BenchRun run;
  run.suite = o.suite;
  run.quick = o.quick;
  run.max_repeats = plan.repeats;
  run.rungs = std::move(rungs);
  ProgressLine progress("bench");
  for (bench::Family f : plan.families)
    for (double d : plan.difficulties(f))
      for (int s = 1; s <= plan.seeds; ++s)
        for (const bench::Instance& inst : bench::generate(f, d, static_cast<std::uint64_t>(s))) {
          progress.update(std::string(bench::family_name(f)) + ", " + inst.knob + ", seed " + std::to_string(s) + " (" +
                          std::to_string(run.instances.size() + 1) + " instances)");
          run.instances.push_back(run_instance(inst, run.rungs, plan.repeats));
        }
  progress.finish();
  run.seconds = seconds_since(start);
  const std::vector<std::string> files = write_bench_report(run, o.out);
  if (o.json) {
    std::cout << bench_json(run).dump() << "\n";
    return 0;
  }
  std::cout << bench_text(run);
  for (std::size_t k = 0; k + 1 < run.rungs.size(); ++k)
    if (run.rungs[k].arith == exact::Arith::kVerified && disagreements(run, k) > 0)
      std::cout << "WARNING: the " << run.rungs[k].name << " rung disagrees with exact on " << disagreements(run, k)
                << " instances\n";
  std::cout << "written:";
  for (const auto& f : files) std::cout << " " << f;
  std::cout << "\n";
  return 0;
}

}  // namespace

void register_bench(CLI::App& app, Action& action) {
  auto opts = std::make_shared<BenchOptions>();
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
  sub->callback([opts, &action] { action = [opts] { return run_bench(*opts); }; });
}

}  // namespace contactcert::cli
