// Strong stability on many touching fixels: the prefix tree of contact modes (solvers/stability/mode_tree.h)
// beside the 4^k route (every moving mode string, each with its kinematic LP and, if feasible, its LP in g), in
// one run. Per verdict (verified arithmetic, g = (0,-1,0), strongly stable, so every moving mode needs a proof):
// time, LPs, prefixes visited and the certificate's size in bytes; and the stable region's time.
// And the contact modes from rest of bench/modes_polygons.py's polygons (k fixels in convex position on a lower
// chain, touching or all at a gap) in process: by the prefixes' cones (what `modes` runs), by an LP per prefix
// (verified) and in doubles (the float LP walk, no certificate): time, prefixes, modes.
// It runs with the command line's memory settings (runtime/memory.h), so that it times what a user's run does.
//   build/bench/mode_tree_bench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <algorithm>
#include <numeric>
#include <sstream>
#include <string>

#include "bench/user_memory_main.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "solvers/stability/contact_modes.h"
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

// The disk's verdict in Q with its certificate text (range(1) = 0: the tree by cones) against the float path
// (range(1) = 1: strong_stability<double>, no certificate), k = range(0) fixels.
void BM_DiskVerdictExactAgainstFloat(benchmark::State& state) {
  const int k = static_cast<int>(state.range(0));
  const std::string text = disk_text(k);
  const auto scene = parse(text);
  exact::Vec<double> g_float(3);
  g_float << 0, -1, 0;
  bool strong = false;
  for (auto _ : state) {
    if (state.range(1) == 0) {
      const auto r = solvers::strong_stability<Q>(scene, gravity());
      benchmark::DoNotOptimize(solvers::stability_certificate(text, gravity(), r).size());
      strong = r.verdict == solvers::StabilityVerdict::kStronglyStable;
    } else {
      const auto r = solvers::strong_stability<double>(scene, g_float);
      strong = r.verdict == solvers::StabilityVerdict::kStronglyStable;
    }
  }
  state.counters["strong"] = strong;
  state.SetLabel("disk k=" + std::to_string(k) + (state.range(1) == 0 ? " verified + certificate" : " float"));
}
BENCHMARK(BM_DiskVerdictExactAgainstFloat)->ArgsProduct({{16, 32, 64, 128}, {0, 1}})->Unit(benchmark::kMillisecond);

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

// bench/modes_polygons.py in C++: the lower chain of the k shortest primitive directions (a, b), a > 0, by slope;
// a fixel at each edge's midpoint, or a quarter of its normal (-b, a) below it (gap).
std::string chain_text(int k, bool gap) {
  std::vector<std::pair<long, long>> dirs;
  for (long r = 1; static_cast<int>(dirs.size()) < k; ++r) {
    dirs.clear();
    for (long a = 1; a <= r; ++a)
      for (long b = -r; b <= r; ++b)
        if (std::gcd(a, b) == 1) dirs.emplace_back(a, b);
  }
  auto slope = [](const std::pair<long, long>& d) {
    return static_cast<double>(d.second) / static_cast<double>(d.first);
  };
  std::stable_sort(dirs.begin(), dirs.end(), [&](const auto& u, const auto& v) {
    const long nu = u.first * u.first + u.second * u.second, nv = v.first * v.first + v.second * v.second;
    return nu != nv ? nu < nv : slope(u) < slope(v);
  });
  dirs.resize(static_cast<std::size_t>(k));
  std::stable_sort(dirs.begin(), dirs.end(), [&](const auto& u, const auto& v) { return slope(u) < slope(v); });
  std::ostringstream s, fixels;
  long x = 0, y = 0;
  s << R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0])";
  for (int i = 0; i < k; ++i) {
    const auto [a, b] = dirs[static_cast<std::size_t>(i)];
    Q mx = Q(2 * x + a, 2), my = Q(2 * y + b, 2);
    if (gap) mx += Q(b, 4), my -= Q(a, 4);
    fixels << (i ? "," : "") << R"({"position":[")" << mx << R"(",")" << my << R"("]})";
    x += a, y += b;
    s << ",[" << x << "," << y << "]";
  }
  s << R"(]}},"mu_s":"1/2","mu_k":"1/2","fixels":[)" << fixels.str() << "]}";
  return s.str();
}

// Contact modes from rest of the chain polygon; range(0): 0 touching, 1 gap; range(1): k; range(2): 0 by cones
// (contact_modes, certified), 1 by a verified LP per prefix, 2 in doubles.
void BM_ModesPolygon(benchmark::State& state) {
  const bool gap = state.range(0) == 1;
  const int k = static_cast<int>(state.range(1)), route = static_cast<int>(state.range(2));
  const auto scene = parse(chain_text(k, gap));
  solvers::ContactModeOptions options;
  const solvers::ContactModes cones = solvers::contact_modes(scene, options);
  const solvers::MotionModel<double> float_model = solvers::motion_model<double>(scene);
  long nodes = 0, modes = 0;
  for (auto _ : state) {
    if (route == 0) {
      const solvers::ContactModes m = solvers::contact_modes(scene, options);
      nodes = m.tree.nodes, modes = static_cast<long>(m.tree.modes.size());
    } else if (route == 1) {
      const auto t = solvers::walk_modes(cones.model, cones.alphabet, options.tree);
      nodes = t.nodes, modes = static_cast<long>(t.modes.size());
    } else {
      const auto t = solvers::walk_modes(float_model, cones.alphabet, options.tree);
      nodes = t.nodes, modes = static_cast<long>(t.modes.size());
    }
    benchmark::DoNotOptimize(nodes);
  }
  state.counters["nodes"] = static_cast<double>(nodes);
  state.counters["modes"] = static_cast<double>(modes);
  state.SetLabel(std::string(gap ? "gap" : "touching") + " k=" + std::to_string(k) +
                 (route == 0   ? " cones"
                  : route == 1 ? " LPs (verified)"
                               : " float LPs"));
}
BENCHMARK(BM_ModesPolygon)->ArgsProduct({{0, 1}, {4, 16, 32, 64}, {0, 1, 2}})->Unit(benchmark::kMillisecond);

// The exact stable region (the labelled cells of wrench space) of the disk.
void BM_Region(benchmark::State& state) {
  const auto scene = parse(disk_text(static_cast<int>(state.range(0))));
  std::size_t cells = 0;
  for (auto _ : state) cells = solvers::stable_region<Q>(scene).cells.size();
  state.counters["cells"] = static_cast<double>(cells);
}
BENCHMARK(BM_Region)->Arg(4)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) { return contactcert::bench::run_with_user_memory(argc, argv); }
