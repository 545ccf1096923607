// Strong stability and insertion timings (issue targets: one verdict under 100 us, the full three-fixel
// region under 10 ms, exact), exact and float side by side in one run.
//   build/bench/stability_bench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <string>

#include "exact/json_input.h"
#include "geometry/scene_json.h"
#include "solvers/insertion/insertion.h"
#include "solvers/stability/finger_push.h"
#include "solvers/stability/stable_region.h"

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
      R"("fixels":[)" + fixels + R"(],"mu_s":"1/2","mu_k":"1/2"})",
      "bench"));
}

exact::Vec<Q> wrench(long x, long y, long z) {
  exact::Vec<Q> g(3);
  g << x, y, z;
  return g;
}

void BM_Verdict(benchmark::State& state) {
  const auto scene = disk(static_cast<int>(state.range(0)));
  const auto arith = static_cast<exact::Arith>(state.range(1));
  const exact::Vec<Q> g = wrench(0, -1, 0);
  for (auto _ : state) {
    if (arith == exact::Arith::kFloat)
      benchmark::DoNotOptimize(solvers::strong_stability<double>(scene, exact::to_double(g), {arith}).verdict);
    else
      benchmark::DoNotOptimize(solvers::strong_stability<Q>(scene, g, {arith}).verdict);
  }
  state.SetLabel(std::string(exact::arith_name(arith)) + ", " + std::to_string(state.range(0)) + " fixels");
}
BENCHMARK(BM_Verdict)->ArgsProduct({{2, 3}, {0, 1, 2}})->Unit(benchmark::kMicrosecond);

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

}  // namespace

BENCHMARK_MAIN();
