// Contact modes of a body in space from rest (issue 34; solvers/spatial/spatial_modes.h) on k = 4, 8, 16, 32
// contacts: a 2 x 2 x 1 box on a plane touching it at k points around its bottom face's rim (k / 4 per side from
// each corner: k = 4 is scenes/spatial_box_on_plane.json), and a 2 x 2 x 4 peg in a square hole it fits exactly,
// touching the four walls on their middle lines at k / 4 heights from z = 1/2 to 7/2 (k = 8 is
// scenes/spatial_peg_in_hole.json up to the contacts' order); square pyramids, mu = 1/2. Per case: the walk with
// its certificate text (what `modes SCENE --certificate F` computes), CPU time, and the counters modes, nodes
// (prefixes visited), LPs, the certificate's bytes and check_ms (the independent checker's CPU time on it).
// bench/spatial_growth.py fits the growth in k and times the command line end to end; `spatial_bench --scenes DIR`
// writes the scenes it uses as DIR/{box,peg}_K.json. BM_SpatialStability: strong stability under gravity on the same
// cases, with the certificate's check time.
//   build-bench/bench/spatial_bench --benchmark_filter=BM_SpatialModes
#include <benchmark/benchmark.h>

#include <ctime>
#include <fstream>
#include <sstream>
#include <string>

#include "bench/user_memory_main.h"
#include "checker/spatial_modes_check.h"
#include "checker/spatial_stability_check.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/spatial_scene.h"
#include "solvers/spatial/spatial_modes.h"
#include "solvers/spatial/spatial_modes_certificate.h"
#include "solvers/spatial/spatial_stability.h"
#include "solvers/spatial/spatial_stability_certificate.h"

namespace {

using namespace contactcert;
using exact::Q;

// Box on a plane: the corners (1, 1), (1, -1), (-1, -1), (-1, 1) of the bottom face z = 0, and k / 4 points per side
// from each corner towards the next, normal +z; the com at the centre (0, 0, 1/2).
std::string box_text(int k) {
  const int corner[5][2] = {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}, {1, 1}};
  std::ostringstream s;
  s << R"({"kind":"spatial","name":"box on a plane, )" << k << R"( contacts","body":{"mass":1,)"
    << R"("inertia":[["5/12",0,0],[0,"5/12",0],[0,0,"2/3"]],"com":[0,0,"1/2"],)"
    << R"("box":{"center":[0,0,"1/2"],"half":[1,1,"1/2"]}},"mu":"1/2","contacts":[)";
  for (int side = 0, i = 0; side < 4; ++side)
    for (int j = 0; j < k / 4; ++j, ++i) {
      const Q t(j, k / 4);
      const Q x = corner[side][0] + (corner[side + 1][0] - corner[side][0]) * t;
      const Q y = corner[side][1] + (corner[side + 1][1] - corner[side][1]) * t;
      s << (i ? "," : "") << R"({"point":[")" << x << R"(",")" << y << R"(",0],"normal":[0,0,1]})";
    }
  s << "]}";
  return s.str();
}

// Peg in a square hole: per height z (k / 4 of them, evenly from 1/2 to 7/2; 2 for k = 4) the walls x+, x-, y+, y-
// at the middle of the peg's faces, normals into the peg.
std::string peg_text(int k) {
  const int wall[4][4] = {{1, 0, -1, 0}, {-1, 0, 1, 0}, {0, 1, 0, -1}, {0, -1, 0, 1}};
  std::ostringstream s;
  s << R"({"kind":"spatial","name":"peg in a square hole, )" << k << R"( contacts","body":{"mass":1,)"
    << R"("inertia":[["5/3",0,0],[0,"5/3",0],[0,0,"2/3"]],"com":[0,0,2],)"
    << R"("box":{"center":[0,0,2],"half":[1,1,2]}},"mu":"1/2","contacts":[)";
  const int heights = k / 4;
  for (int h = 0, i = 0; h < heights; ++h) {
    const Q z = heights == 1 ? Q(2) : Q(1, 2) + Q(3 * h, heights - 1);
    for (const auto& w : wall)
      s << (i++ ? "," : "") << R"({"point":[)" << w[0] << "," << w[1] << R"(,")" << z << R"("],"normal":[)" << w[2]
        << "," << w[3] << ",0]}";
  }
  s << "]}";
  return s.str();
}

std::string scene_text(int shape, int k) { return shape == 0 ? box_text(k) : peg_text(k); }

// The independent checker's CPU ms on a certificate (`check`), 0 past the 32 MiB that `check` reads; a certificate it
// refuses ends the case with an error.
template <class Check>
double check_ms(benchmark::State& state, const std::string& certificate, const Check& check) {
  if (certificate.size() > exact::kMaxInputBytes) return 0;
  const std::clock_t start = std::clock();
  const auto verdict = check(checker::CertificateLines(certificate, "certificate.json"));
  const double ms = 1000.0 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  if (!verdict.valid) state.SkipWithError(("certificate refused: " + verdict.reason).c_str());
  return ms;
}

// range(0): 0 box on a plane, 1 peg in a hole; range(1): k.
void BM_SpatialModes(benchmark::State& state) {
  const int shape = static_cast<int>(state.range(0)), k = static_cast<int>(state.range(1));
  const std::string text = scene_text(shape, k);
  const solvers::spatial::SpatialModel model =
      solvers::spatial::spatial_model(geometry::read_spatial_scene(exact::JsonInput::parse(text, "bench")));
  solvers::spatial::SpatialModeTree tree;
  std::string certificate;
  for (auto _ : state) {
    tree = solvers::spatial::spatial_modes(model);
    certificate = solvers::spatial::spatial_modes_certificate(text, tree);
    benchmark::DoNotOptimize(certificate.size());
  }
  state.counters["modes"] = static_cast<double>(tree.modes.size());
  state.counters["nodes"] = static_cast<double>(tree.nodes);
  state.counters["lps"] = static_cast<double>(tree.lps);
  state.counters["cert_bytes"] = static_cast<double>(certificate.size());
  state.counters["check_ms"] = check_ms(state, certificate, checker::check_spatial_modes_certificate);
  state.SetLabel(std::string(shape == 0 ? "box" : "peg") + " k=" + std::to_string(k));
}
BENCHMARK(BM_SpatialModes)
    ->ArgsProduct({{0, 1}, {4, 8, 16, 32}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->Iterations(1);

// Strong stability under gravity g = (0, 0, -1, 0, 0, 0) (solvers/spatial/spatial_stability.h) on the same cases:
// the verdict with its certificate text (what `stability SCENE --wrench 0,0,-1,0,0,0 --certificate F` computes),
// CPU time, and the counters verdict (0 strongly stable, 1 weakly, 2 unstable: StabilityVerdict), LPs, moving modes
// decided and of them proven by a moved Motzkin vector, the certificate's bytes, and check_ms: the independent
// checker's CPU time on the certificate (checker/spatial_stability_check.h), left out (0) past the 32 MiB that `check`
// reads.
void BM_SpatialStability(benchmark::State& state) {
  const int shape = static_cast<int>(state.range(0)), k = static_cast<int>(state.range(1));
  const std::string text = scene_text(shape, k);
  const geometry::SpatialScene scene = geometry::read_spatial_scene(exact::JsonInput::parse(text, "bench"));
  exact::Vec<Q> g = exact::Vec<Q>::Zero(6);
  g(2) = -1;
  solvers::spatial::SpatialStability r;
  std::string certificate;
  for (auto _ : state) {
    r = solvers::spatial::spatial_stability(scene, g);
    certificate = solvers::spatial::spatial_stability_certificate(scene, text, g, r);
    benchmark::DoNotOptimize(certificate.size());
  }
  state.counters["check_ms"] = check_ms(state, certificate, checker::check_spatial_stability_certificate);
  state.counters["verdict"] = static_cast<double>(r.verdict);
  state.counters["lps"] = static_cast<double>(r.lps);
  state.counters["modes_decided"] = static_cast<double>(r.modes_checked);
  state.counters["by_reuse"] = static_cast<double>(r.modes_by_reuse);
  state.counters["cert_bytes"] = static_cast<double>(certificate.size());
  state.SetLabel(std::string(shape == 0 ? "box" : "peg") + " k=" + std::to_string(k));
}
BENCHMARK(BM_SpatialStability)
    ->ArgsProduct({{0, 1}, {4, 8, 16, 32}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--scenes") {
    for (int shape = 0; shape < 2; ++shape)
      for (int k : {4, 8, 16, 32})
        std::ofstream(std::string(argv[2]) + (shape == 0 ? "/box_" : "/peg_") + std::to_string(k) + ".json")
            << scene_text(shape, k) << "\n";
    return 0;
  }
  return contactcert::bench::run_with_user_memory(argc, argv);
}
