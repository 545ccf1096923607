#include "queries/bench_query.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "exact/deadline.h"
#include "exact/input_error.h"
#include "exact/json_input.h"

namespace contactcert::queries {
namespace {

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

}  // namespace

std::optional<bench::Family> parse_bench_suite(const std::string& text, const std::string& field) {
  if (text == "all") return std::nullopt;
  if (const auto f = bench::parse_family(text)) return f;
  std::string names = "all";
  for (bench::Family f : bench::all_families()) names += std::string(", ") + bench::family_name(f);
  throw exact::InputError("command line", field, "one of " + names + ", found " + exact::quoted_excerpt(text));
}

std::vector<bench::Rung> parse_bench_rungs(const std::string& text, const std::string& field) {
  try {
    return bench::parse_rungs(text);
  } catch (const std::invalid_argument& e) {
    throw exact::InputError("command line", field, std::string("a list of known rungs: ") + e.what());
  }
}

std::string rung_names(const std::vector<bench::Rung>& rungs) {
  std::string s;
  for (const bench::Rung& r : rungs) s += (s.empty() ? "" : ",") + r.name;
  return s;
}

Limited<BenchAnswer> run_bench(const BenchOptions& o, const BenchProgress& progress) {
  const auto start = std::chrono::steady_clock::now();
  const exact::Deadline deadline = exact::Deadline::after(o.time_limit);
  create_output_dir(o.out);  // fail before the run, not after it
  Plan plan;
  plan.families = o.family ? std::vector<bench::Family>{*o.family} : bench::all_families();
  plan.levels = o.quick ? 3 : 12;
  plan.seeds = o.quick ? 5 : 6;
  plan.repeats = o.quick ? 3 : 5;
  BenchAnswer answer;
  BenchRun& run = answer.run;
  run.suite = o.family ? bench::family_name(*o.family) : "all";
  run.quick = o.quick;
  run.max_repeats = plan.repeats;
  run.rungs = o.rungs;
  for (bench::Family f : plan.families)
    for (double d : plan.difficulties(f))
      for (int s = 1; s <= plan.seeds; ++s)
        for (const bench::Instance& inst : bench::generate(f, d, static_cast<std::uint64_t>(s))) {
          if (deadline.expired())
            return Limit{"bench: " + deadline.reached_text(), std::to_string(run.instances.size()) + " instances",
                         Limit::Kind::kStopped};
          if (progress)
            progress(std::string(bench::family_name(f)) + ", " + inst.knob + ", seed " + std::to_string(s) + " (" +
                     std::to_string(run.instances.size() + 1) + " instances)");
          run.instances.push_back(run_instance(inst, run.rungs, plan.repeats));
        }
  run.seconds = seconds_since(start);
  answer.files = write_bench_report(run, o.out);
  return answer;
}

json to_json(const BenchAnswer& answer) { return bench_json(answer.run); }

std::string to_text(const BenchAnswer& answer) {
  const BenchRun& run = answer.run;
  std::string s = bench_text(run);
  for (std::size_t k = 0; k + 1 < run.rungs.size(); ++k)
    if (run.rungs[k].arith == exact::Arith::kVerified && disagreements(run, k) > 0)
      s += "WARNING: the " + run.rungs[k].name + " rung disagrees with exact on " +
           std::to_string(disagreements(run, k)) + " instances\n";
  s += "written:";
  for (const auto& f : answer.files) s += " " + f;
  return s + "\n";
}

}  // namespace contactcert::queries
