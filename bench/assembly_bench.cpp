// Assembly stability (solvers/assembly) on stacks and rows of N = 2, 4, 8, 16 boxes (two contacts per interface)
// and a 9-block corbelled arch, in one run: the verdict with its certificate, and the independent check of that
// certificate, in verified arithmetic. "gravity": every load is a weight, so the energy row kills the root (one
// LP); "wind": every box also carries a lateral push of a quarter of its weight, so the root's system is feasible
// and the contact walk proves each dead prefix (counters: nodes, LPs, dead prefixes, verdict). The 4^k brute
// force (tests/solvers/assembly/assembly_random_test.cpp) finishes only for k <= 6 (N = 2 stacks: 256 LPs).
//   build/bench/assembly_bench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include "checker/assembly_check.h"
#include "tests/solvers/assembly/assembly_fixtures.h"

namespace {

using namespace contactcert;
using solvers::assembly::testing::SceneText;

enum Family { kStack, kRow, kArch };

SceneText family(Family f, std::size_t n, bool wind) {
  SceneText s = f == kStack ? solvers::assembly::testing::box_stack(n)
                : f == kRow ? solvers::assembly::testing::box_row(n)
                            : solvers::assembly::testing::corbel_arch();
  if (wind)  // every body is a 2 x 1 box of mass 2 but the arch's keystone (mass 9/2)
    for (std::string& b : s.bodies) b.insert(b.size() - 1, R"(, "load": ["1/2", -2, 0])");
  return s;
}

void run(benchmark::State& state, Family f, bool wind) {
  const geometry::Assembly a = family(f, static_cast<std::size_t>(state.range(0)), wind).read();
  solvers::assembly::AssemblyStabilityResult r;
  for (auto _ : state) r = solvers::assembly::assembly_stability(a);
  state.counters["N"] = static_cast<double>(a.bodies.size());
  state.counters["k"] = static_cast<double>(a.contacts.size());
  state.counters["nodes"] = static_cast<double>(r.nodes);
  state.counters["lps"] = static_cast<double>(r.lps);
  state.counters["dead"] = static_cast<double>(r.dead.size());
  state.counters["verdict"] = static_cast<double>(static_cast<int>(r.verdict));  // 0 strong, 1 weak, 2 unstable
  state.counters["decided"] = r.status == solvers::assembly::AssemblyStatus::kDecided;
  state.counters["valid"] = checker::check_assembly_stability(a, r).empty();
}

void check(benchmark::State& state, Family f, bool wind) {
  const geometry::Assembly a = family(f, static_cast<std::size_t>(state.range(0)), wind).read();
  const solvers::assembly::AssemblyStabilityResult r = solvers::assembly::assembly_stability(a);
  std::string why;
  for (auto _ : state) why = checker::check_assembly_stability(a, r);
  state.counters["valid"] = why.empty();
}

void BM_StackGravity(benchmark::State& s) { run(s, kStack, false); }
void BM_RowGravity(benchmark::State& s) { run(s, kRow, false); }
void BM_StackWind(benchmark::State& s) { run(s, kStack, true); }
void BM_RowWind(benchmark::State& s) { run(s, kRow, true); }
void BM_Arch9Gravity(benchmark::State& s) { run(s, kArch, false); }
void BM_Arch9Wind(benchmark::State& s) { run(s, kArch, true); }
void BM_CheckStackWind(benchmark::State& s) { check(s, kStack, true); }
void BM_CheckRowWind(benchmark::State& s) { check(s, kRow, true); }

BENCHMARK(BM_StackGravity)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RowGravity)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StackWind)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RowWind)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Arch9Gravity)->Arg(9)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Arch9Wind)->Arg(9)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CheckStackWind)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CheckRowWind)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
