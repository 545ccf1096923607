// Assembly stability (solvers/assembly) on stacks and rows ("walls") of N = 2, 4, 8, 16 boxes (two contacts per
// interface) and a 9-block corbelled arch, in one run: the verdict with its certificate, the independent check of
// that certificate as `contactcert check` does it (JSON text read, digest, every dead prefix's system rebuilt), and
// the 4^k brute force (tests/solvers/assembly/assembly_brute_force.h) where it finishes (k <= 8), all in verified
// arithmetic. "gravity": every load is a weight, so the energy row kills the root (one LP after the resting one);
// "wind": every box also carries a lateral push (a quarter of its weight in rows and the arch, a sixteenth in stacks,
// under which a stack of 16 still stands: with a quarter it tips over), so the root's system is feasible and the
// contact walk proves each dead prefix; "NoReuse" is the same walk without reusing dead prefixes' certificates
// (AssemblyStabilityOptions::reuse_certificates). Counters: N, k, the walk's nodes, LPs and dead prefixes, the
// certificate's size in kB, the verdict (0 strongly stable, 1 weakly, 2 unstable), and whether the certificate checked
// valid. A verdict gets kLimitSeconds (decided = 0 past it; a row of 16 takes about 7.5 s under load, docs/bench.md).
//   build-bench/bench/assembly_bench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include "checker/assembly_check.h"
#include "solvers/assembly/assembly_certificate.h"
#include "tests/solvers/assembly/assembly_brute_force.h"
#include "tests/solvers/assembly/assembly_fixtures.h"

namespace {

using namespace contactcert;
using solvers::assembly::testing::SceneText;

enum Family { kStack, kRow, kArch };

constexpr double kLimitSeconds = 120;

solvers::assembly::AssemblyStabilityResult stability(const geometry::Assembly& a, bool reuse = true) {
  solvers::assembly::AssemblyStabilityOptions o;
  o.deadline = exact::Deadline::after(kLimitSeconds);
  o.reuse_certificates = reuse;
  return solvers::assembly::assembly_stability(a, o);
}

SceneText family(Family f, std::size_t n, bool wind) {
  SceneText s = f == kStack ? solvers::assembly::testing::box_stack(n)
                : f == kRow ? solvers::assembly::testing::box_row(n)
                            : solvers::assembly::testing::corbel_arch();
  const std::string load = f == kStack ? R"(, "load": ["1/8", -2, 0])" : R"(, "load": ["1/2", -2, 0])";
  if (wind)  // every body is a 2 x 1 box of mass 2 but the arch's keystone (mass 9/2)
    for (std::string& b : s.bodies) b.insert(b.size() - 1, load);
  return s;
}

void verdict(benchmark::State& state, Family f, bool wind, bool reuse = true) {
  const SceneText s = family(f, static_cast<std::size_t>(state.range(0)), wind);
  const geometry::Assembly a = s.read();
  solvers::assembly::AssemblyStabilityResult r;
  for (auto _ : state) r = stability(a, reuse);
  const bool decided = r.status == solvers::assembly::AssemblyStatus::kDecided;
  const std::string certificate = decided ? solvers::assembly::assembly_certificate(s.json(), r) : std::string();
  state.counters["N"] = static_cast<double>(a.bodies.size());
  state.counters["k"] = static_cast<double>(a.contacts.size());
  state.counters["nodes"] = static_cast<double>(r.nodes);
  state.counters["lps"] = static_cast<double>(r.lps);
  state.counters["dead"] = static_cast<double>(r.dead.size());
  state.counters["cert_kB"] = static_cast<double>(certificate.size()) / 1000;
  state.counters["verdict"] = static_cast<double>(static_cast<int>(r.verdict));
  state.counters["decided"] = decided;
}

void check(benchmark::State& state, Family f, bool wind) {
  const SceneText s = family(f, static_cast<std::size_t>(state.range(0)), wind);
  const solvers::assembly::AssemblyStabilityResult r = stability(s.read());
  if (r.status != solvers::assembly::AssemblyStatus::kDecided) {
    state.SkipWithError("the verdict did not finish");
    for (auto _ : state) {
    }
    return;
  }
  const std::string certificate = solvers::assembly::assembly_certificate(s.json(), r);
  checker::AssemblyCertificateCheck c;
  for (auto _ : state)
    c = checker::check_assembly_certificate(exact::JsonInput::parse(certificate, "certificate.json"));
  state.counters["valid"] = c.valid;
}

void brute(benchmark::State& state, Family f, bool wind) {
  const geometry::Assembly a = family(f, static_cast<std::size_t>(state.range(0)), wind).read();
  solvers::assembly::AssemblyVerdict v{};
  for (auto _ : state) v = solvers::assembly::testing::brute_force(a);
  state.counters["k"] = static_cast<double>(a.contacts.size());
  state.counters["verdict"] = static_cast<double>(static_cast<int>(v));
}

void BM_StackGravity(benchmark::State& s) { verdict(s, kStack, false); }
void BM_RowGravity(benchmark::State& s) { verdict(s, kRow, false); }
void BM_Arch9Gravity(benchmark::State& s) { verdict(s, kArch, false); }
void BM_StackWind(benchmark::State& s) { verdict(s, kStack, true); }
void BM_RowWind(benchmark::State& s) { verdict(s, kRow, true); }
void BM_Arch9Wind(benchmark::State& s) { verdict(s, kArch, true); }
void BM_StackWindNoReuse(benchmark::State& s) { verdict(s, kStack, true, false); }
void BM_RowWindNoReuse(benchmark::State& s) { verdict(s, kRow, true, false); }
void BM_Arch9WindNoReuse(benchmark::State& s) { verdict(s, kArch, true, false); }
void BM_CheckStackWind(benchmark::State& s) { check(s, kStack, true); }
void BM_CheckRowWind(benchmark::State& s) { check(s, kRow, true); }
void BM_CheckArch9Wind(benchmark::State& s) { check(s, kArch, true); }
void BM_BruteStackWind(benchmark::State& s) { brute(s, kStack, true); }
void BM_BruteRowWind(benchmark::State& s) { brute(s, kRow, true); }

BENCHMARK(BM_StackGravity)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RowGravity)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Arch9Gravity)->Arg(9)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StackWind)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_StackWindNoReuse)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CheckStackWind)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BruteStackWind)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RowWind)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RowWindNoReuse)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CheckRowWind)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BruteRowWind)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Arch9Wind)->Arg(9)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Arch9WindNoReuse)->Arg(9)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CheckArch9Wind)->Arg(9)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
