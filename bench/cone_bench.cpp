// Cone conversion (generators -> facets): our exact (Q, fraction-free) and float paths against cddlib
// GMP and cddlib double, in one run. Workloads: random integer cones (entries in [-20, 20], ANCHORS.md)
// of dimension 3-12 with up to 40 generators (pointed: first coordinate positive), and the K matrices
// of the wrench cone algorithm (eq. 15) for 1-6 fixels on a disk (arguments 0/fixels). Counters: facets, and for the
// float paths the number of instances whose facet count differs from the exact answer (wrong).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "exact/json_input.h"
#include "geometry/canonical.h"
#include "geometry/double_description.h"
#include "geometry/scene_json.h"
#include "solvers/wrench_cone/cone_form.h"
#include "solvers/wrench_cone/contact_model.h"
#include "solvers/wrench_cone/mode.h"
#include "tests/reference/cdd_cone.h"

namespace {

using contactcert::exact::Mat;
using contactcert::exact::Q;
using contactcert::geometry::SpanCone;

constexpr int kInstances = 20;

std::vector<SpanCone<Q>> random_cones(long dim, long gens) {
  std::mt19937_64 rng(static_cast<unsigned long>(1000 * dim + gens));
  std::uniform_int_distribution<long> u(-20, 20);
  std::vector<SpanCone<Q>> out;
  for (int i = 0; i < kInstances; ++i) {
    Mat<Q> R(gens, dim);
    // Pointed cones over random polytopes: first coordinate in [1, 20] (otherwise most random cones
    // with many generators are the whole space).
    for (long r = 0; r < gens; ++r) {
      for (long j = 0; j < dim; ++j) R(r, j) = Q(u(rng));
      R(r, 0) = abs(R(r, 0)) + 1;
    }
    out.push_back(SpanCone<Q>::from_rows(dim, R, Mat<Q>(0, dim)));
  }
  return out;
}

// The K matrices of the wrench cone algorithm (eq. 15) for a unit disk with `fixels` touching fixels
// at rational points of the circle, for 12 seeded random modes (letters that fit a touching fixel).
std::vector<SpanCone<Q>> wrench_k_cones(long fixels) {
  namespace solvers = contactcert::solvers;
  const char* points[] = {"[0, -1]", "[1, 0]", "[0, 1]", "[-1, 0]", "[\"3/5\", \"4/5\"]", "[\"-4/5\", \"-3/5\"]"};
  std::string text = R"({"kind": "planar", "workpiece": {"shape": {"type": "disk", "center": [0, 0], "radius": 1},
      "mass": 1, "inertia": "1/2"}, "mu_s": "1/5", "mu_k": "1/5", "fixels": [)";
  for (long i = 0; i < fixels; ++i) text += std::string(i ? ", " : "") + "{\"position\": " + points[i] + "}";
  text += "]}";
  const auto scene = contactcert::geometry::read_planar_scene(contactcert::exact::JsonInput::parse(text, "bench"));
  const auto model = solvers::contact_model<Q>(scene);
  const auto letters = solvers::letters_for(true);
  std::mt19937_64 rng(static_cast<unsigned long>(fixels));
  std::vector<SpanCone<Q>> out;
  for (int k = 0; k < 12; ++k) {
    std::string mode;
    for (long i = 0; i < fixels; ++i) mode += static_cast<char>(letters[rng() % letters.size()]);
    const auto parsed = solvers::parse_mode(mode, std::vector<bool>(static_cast<size_t>(fixels), true));
    if (parsed.status != solvers::ModeStatus::kValid) continue;
    const auto form = solvers::cone_form<Q>(scene, model, parsed.mode);
    out.push_back(SpanCone<Q>::from_columns(form.K));
  }
  return out;
}

std::vector<SpanCone<Q>> workload(const benchmark::State& state) {
  // range(0) == 0: the wrench cone K matrices for range(1) fixels; otherwise random (dim, generators).
  return state.range(0) == 0 ? wrench_k_cones(state.range(1)) : random_cones(state.range(0), state.range(1));
}

std::vector<long> exact_facets(const std::vector<SpanCone<Q>>& cones) {
  std::vector<long> f;
  for (const auto& c : cones) f.push_back(static_cast<long>(contactcert::geometry::to_face(c).inequalities.rows()));
  return f;
}

void BM_ours_exact(benchmark::State& state) {
  const auto cones = workload(state);
  long facets = 0;
  size_t i = 0;
  for (auto _ : state) {
    auto F = contactcert::geometry::to_face(cones[i++ % cones.size()]);
    facets += static_cast<long>(F.inequalities.rows());
    benchmark::DoNotOptimize(F);
  }
  state.counters["facets"] = static_cast<double>(facets) / static_cast<double>(state.iterations());
}

void BM_ours_float(benchmark::State& state) {
  const auto cones = workload(state);
  const auto truth = exact_facets(cones);
  std::vector<SpanCone<double>> dc;
  for (const auto& c : cones)
    dc.push_back(SpanCone<double>::from_rows(c.dim, contactcert::exact::to_double(c.rays), Mat<double>(0, c.dim)));
  std::vector<bool> wrong(dc.size(), false);
  size_t i = 0;
  for (auto _ : state) {
    const size_t k = i++ % dc.size();
    auto F = contactcert::geometry::to_face(dc[k]);
    if (F.inequalities.rows() != truth[k]) wrong[k] = true;
    benchmark::DoNotOptimize(F);
  }
  state.counters["wrong_of_20"] = static_cast<double>(std::count(wrong.begin(), wrong.end(), true));
}

void BM_cdd_gmp(benchmark::State& state) {
  const auto cones = workload(state);
  size_t i = 0;
  for (auto _ : state) {
    auto F = contactcert::reference::cdd_to_face(cones[i++ % cones.size()]);
    benchmark::DoNotOptimize(F);
  }
}

void BM_cdd_double(benchmark::State& state) {
  const auto cones = workload(state);
  const auto truth = exact_facets(cones);
  std::vector<SpanCone<double>> dc;
  for (const auto& c : cones)
    dc.push_back(SpanCone<double>::from_rows(c.dim, contactcert::exact::to_double(c.rays), Mat<double>(0, c.dim)));
  std::vector<bool> wrong(dc.size(), false);
  size_t i = 0;
  for (auto _ : state) {
    const size_t k = i++ % dc.size();
    try {
      auto F = contactcert::reference::cddf_to_face(dc[k]);
      if (F.inequalities.rows() != truth[k]) wrong[k] = true;
      benchmark::DoNotOptimize(F);
    } catch (const std::runtime_error&) {
      wrong[k] = true;  // cddlib's float conversion gave up (numerical inconsistency)
    }
  }
  state.counters["wrong_of_20"] = static_cast<double>(std::count(wrong.begin(), wrong.end(), true));
}

void sizes(benchmark::internal::Benchmark* b) {
  for (auto [d, n] : std::vector<std::pair<long, long>>{
           {3, 6}, {3, 20}, {3, 40}, {4, 12}, {6, 15}, {6, 30}, {6, 40}, {8, 20}, {9, 30}, {12, 18}})
    b->Args({d, n});
  for (long fixels = 1; fixels <= 6; ++fixels) b->Args({0, fixels});
  // Every instance once per repetition, so that all four converters time the same cones.
  b->Iterations(kInstances)->Unit(benchmark::kMicrosecond);
}

BENCHMARK(BM_ours_exact)->Apply(sizes);
BENCHMARK(BM_cdd_gmp)->Apply(sizes);
BENCHMARK(BM_ours_float)->Apply(sizes);
BENCHMARK(BM_cdd_double)->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
