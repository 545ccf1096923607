// Strong stability on many touching fixels: the prefix tree of contact modes (solvers/stability/mode_tree.h)
// beside the 4^k route (every moving mode string, each with its kinematic LP and, if feasible, its LP in g), in
// one run. Per verdict (verified arithmetic, g = (0,-1,0), strongly stable, so every moving mode needs a proof):
// time, LPs, prefixes visited and the certificate's size in bytes; and the stable region's time.
//   build/bench/mode_tree_bench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <sstream>
#include <string>

#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "solvers/stability/stability_certificate.h"
#include "solvers/stability/stable_region.h"
#include "solvers/stability/strong_stability.h"

namespace {

using namespace contactcert;
using exact::Q;

// A unit disk (I/m = 1/2) held by k fixels at rational points of the arc ((1 - t^2), 2t) / (1 + t^2),
// t = 3 (2i + 1 - k) / k: all around but the top, mu = 1/2.
std::string disk_text(int k) {
  std::ostringstream s;
  s << R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1},"mass":1,"inertia":"1/2"},)"
    << R"("mu_s":"1/2","mu_k":"1/2","fixels":[)";
  for (int i = 0; i < k; ++i) {
    const Q t = Q(3 * (2 * i + 1 - k), k);
    s << (i ? "," : "") << R"({"position":[")" << (1 - t * t) / (1 + t * t) << R"(",")" << 2 * t / (1 + t * t)
      << R"("]})";
  }
  s << "]}";
  return s.str();
}

// The block [0, k] x [0, 1] on k fixels along its bottom, mu = 1/2.
std::string block_text(int k) {
  std::ostringstream s;
  s << R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[)" << k << R"(,0],[)" << k
    << R"(,1],[0,1]]}},"mu_s":"1/2","mu_k":"1/2","fixels":[)";
  for (int i = 0; i < k; ++i) s << (i ? "," : "") << R"({"position":[")" << 2 * i + 1 << R"(/2",0]})";
  s << "]}";
  return s.str();
}

std::string scene_text(int shape, int k) { return shape == 0 ? disk_text(k) : block_text(k); }

geometry::PlanarScene parse(const std::string& text) {
  return geometry::read_planar_scene(exact::JsonInput::parse(text, "bench"));
}

exact::Vec<Q> gravity() {
  exact::Vec<Q> g(3);
  g << 0, -1, 0;
  return g;
}

// The verdict and its certificate text, from the scene alone (what `stability --wrench --certificate` does).
void BM_TreeVerdict(benchmark::State& state) {
  const int shape = static_cast<int>(state.range(0)), k = static_cast<int>(state.range(1));
  const std::string text = scene_text(shape, k);
  const auto scene = parse(text);
  solvers::StabilityResult<Q> r;
  std::size_t bytes = 0;
  for (auto _ : state) {
    r = solvers::strong_stability<Q>(scene, gravity());
    bytes = solvers::stability_certificate(text, gravity(), r).size();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["lps"] = static_cast<double>(r.lps);
  state.counters["nodes"] = static_cast<double>(r.tree_nodes);
  state.counters["feasible"] = static_cast<double>(r.modes_kinematically_feasible);
  state.counters["cert_bytes"] = static_cast<double>(bytes);
  state.counters["strong"] = r.verdict == solvers::StabilityVerdict::kStronglyStable;
  state.SetLabel(std::string(shape == 0 ? "disk" : "block") + " k=" + std::to_string(k));
}
BENCHMARK(BM_TreeVerdict)->ArgsProduct({{0, 1}, {2, 4, 6, 8, 12, 16, 24, 32}})->Unit(benchmark::kMillisecond);

// The 4^k route: the resting LP, then every moving mode string in turn - its kinematic LP and, when feasible,
// its LP in g - as the engine did before the tree (without its certificate).
void BM_AllModeStrings(benchmark::State& state) {
  const int shape = static_cast<int>(state.range(0)), k = static_cast<int>(state.range(1));
  const auto scene = solvers::touching_scene(parse(scene_text(shape, k)));
  const solvers::MotionModel<Q> model = solvers::motion_model<Q>(scene);
  const std::vector<solvers::ModeString> modes = solvers::moving_modes(static_cast<std::size_t>(k));
  const solvers::ModeString rolling{std::vector<solvers::Interaction>(k, solvers::Interaction::kRoll)};
  long lps = 0;
  bool strong = false;
  for (auto _ : state) {
    lps = 1;
    strong = exact::strict_feasibility(solvers::motion_system(model, rolling, true).with_wrench(gravity())).status ==
             exact::StrictStatus::kFeasible;
    for (const auto& m : modes) {
      ++lps;
      if (exact::strict_feasibility(solvers::kinematic_system(model, m)).status != exact::StrictStatus::kFeasible)
        continue;
      ++lps;
      if (exact::strict_feasibility(solvers::motion_system(model, m).with_wrench(gravity())).status ==
          exact::StrictStatus::kFeasible)
        strong = false;
    }
  }
  state.counters["lps"] = static_cast<double>(lps);
  state.counters["strong"] = strong;
  state.SetLabel(std::string(shape == 0 ? "disk" : "block") + " k=" + std::to_string(k));
}
BENCHMARK(BM_AllModeStrings)->ArgsProduct({{0, 1}, {2, 4, 6, 8}})->Unit(benchmark::kMillisecond);

// The exact stable region (the labelled cells of wrench space) of the disk.
void BM_Region(benchmark::State& state) {
  const auto scene = parse(disk_text(static_cast<int>(state.range(0))));
  std::size_t cells = 0;
  for (auto _ : state) cells = solvers::stable_region<Q>(scene).cells.size();
  state.counters["cells"] = static_cast<double>(cells);
}
BENCHMARK(BM_Region)->Arg(4)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
