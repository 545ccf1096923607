// Strong stability and insertion timings (targets: one verdict under 100 us, the full three-fixel
// region under 10 ms, exact), exact and float side by side in one run, with a table of the verdict timings.
//   build/bench/stability_bench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

#include "exact/json_input.h"
#include "geometry/scene_json.h"
#include "solvers/insertion/insertion.h"
#include "solvers/stability/finger_push.h"
#include "solvers/stability/stable_region.h"
#include "solvers/stability/strong_stability.h"

namespace {

using namespace contactcert;
using exact::Q;

// A unit disk with k touching fixels at rational points of the circle, mu = 1/2.
geometry::PlanarScene disk(int k) {
  static const char* kPoints[] = {"[0,-1]", "[1,0]", "[\"-4/5\",\"-3/5\"]", "[\"3/5\",\"4/5\"]"};
  std::string fixels;
  for (int i = 0; i < k; ++i) fixels += std::string(i ? "," : "") + "{\"position\":" + kPoints[i] + "}";
  return geometry::read_planar_scene(exact::JsonInput::parse(
      R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1},"mass":1,"inertia":1},)"
      R"("fixels":[)" +
          fixels + R"(],"mu_s":"1/2","mu_k":"1/2"})",
      "bench"));
}

exact::Vec<Q> wrench(long x, long y, long z) {
  exact::Vec<Q> g(3);
  g << x, y, z;
  return g;
}

// One verdict at g = (0,-1,0) (strongly stable: every moving mode needs a proof). Cold: scene -> verdict
// (strong_stability); warm: a StabilityOracle prepared once per scene, then verdict(g) (a planner's loop).
// Counters: LPs per verdict, the share of them decided by a float LP's rounded answer checked exactly, and
// whether the verdict differs from the exact one.
void BM_Verdict(benchmark::State& state) {
  const auto scene = disk(static_cast<int>(state.range(0)));
  const auto arith = static_cast<exact::Arith>(state.range(1));
  const bool warm = state.range(2) != 0;
  const exact::Vec<Q> g = wrench(0, -1, 0);
  const solvers::StabilityVerdict truth = solvers::strong_stability<Q>(scene, g, {exact::Arith::kExact}).verdict;
  auto run = [&]<class T>(const exact::Vec<T>& gT) {
    const solvers::StabilityOracle<T> prepared(scene, {arith});
    solvers::StabilityResult<T> r;
    for (auto _ : state) {
      r = warm ? prepared.verdict(gT) : solvers::strong_stability<T>(scene, gT, {arith});
      benchmark::DoNotOptimize(r.verdict);
    }
    state.counters["lps"] = static_cast<double>(r.lps);
    state.counters["from_float"] = static_cast<double>(r.lps_checked_from_float) / static_cast<double>(r.lps);
    state.counters["wrong_verdicts"] = r.verdict != truth;
  };
  if (arith == exact::Arith::kFloat)
    run(exact::to_double(g));
  else
    run(g);
  state.SetLabel(std::string(exact::arith_name(arith)) + (warm ? " warm, " : " cold, ") +
                 std::to_string(state.range(0)) + " fixels");
}
BENCHMARK(BM_Verdict)->ArgsProduct({{2, 3}, {0, 2, 1}, {0, 1}})->Unit(benchmark::kMicrosecond);

template <class T>
void BM_Region(benchmark::State& state) {
  const auto scene = disk(static_cast<int>(state.range(0)));
  std::size_t cells = 0;
  for (auto _ : state) cells = solvers::stable_region<T>(scene).cells.size();
  state.counters["cells"] = static_cast<double>(cells);
}
BENCHMARK(BM_Region<Q>)->DenseRange(2, 4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Region<double>)->DenseRange(2, 4)->Unit(benchmark::kMillisecond);

template <class T>
void BM_FingerPushes(benchmark::State& state) {
  const auto scene = disk(2);
  const auto region = solvers::stable_region<T>(scene);
  for (auto _ : state) benchmark::DoNotOptimize(solvers::finger_pushes<T>(scene, region).arcs.size());
}
BENCHMARK(BM_FingerPushes<Q>)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FingerPushes<double>)->Unit(benchmark::kMicrosecond);

template <class T>
void BM_Insertion3(benchmark::State& state) {
  const auto scene = disk(3);
  for (auto _ : state) {
    const auto ins = solvers::insertion<T>(scene);
    benchmark::DoNotOptimize(solvers::insertion_pushes<T>(scene, ins).arcs.size());
  }
}
BENCHMARK(BM_Insertion3<Q>)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Insertion3<double>)->Unit(benchmark::kMillisecond);

// The console report, then the verdict timings side by side (CPU time, us) with their ratios.
class VerdictTable : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs)
      if (r.run_name.function_name == "BM_Verdict" && !r.error_occurred) us_[r.run_name.args] = r.GetAdjustedCPUTime();
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    if (us_.empty()) return;
    std::printf("\none verdict, CPU us: float / verified / exact, and verified/float, exact/verified\n");
    for (const char* k : {"2", "3"})
      for (const char* warm : {"0", "1"}) {
        auto at = [&](const char* arith) {
          const auto it = us_.find(std::string(k) + "/" + arith + "/" + warm);
          return it == us_.end() ? 0.0 : it->second;
        };
        const double f = at("0"), v = at("2"), e = at("1");
        if (f > 0 && v > 0 && e > 0)
          std::printf("  %s fixels %s: %9.1f %9.1f %9.1f   x%.2f x%.2f\n", k, *warm == '1' ? "warm" : "cold", f, v, e,
                      v / f, e / v);
      }
  }

 private:
  std::map<std::string, double> us_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  VerdictTable table;
  benchmark::RunSpecifiedBenchmarks(&table);
  benchmark::Shutdown();
  return 0;
}
