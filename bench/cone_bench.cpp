// Cone conversion (generators -> facets): our exact (Q, fraction-free) and float paths against cddlib
// GMP and cddlib double, in one run. Workloads: random integer cones (entries in [-20, 20], ANCHORS.md)
// of dimension 3-12 with up to 40 generators (pointed: first coordinate positive). Counters: facets, and for the float paths the number of
// instances whose facet count differs from the exact answer (wrong).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <vector>

#include "geometry/canonical.h"
#include "geometry/double_description.h"
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

std::vector<long> exact_facets(const std::vector<SpanCone<Q>>& cones) {
  std::vector<long> f;
  for (const auto& c : cones) f.push_back(static_cast<long>(contactcert::geometry::to_face(c).inequalities.rows()));
  return f;
}

void BM_ours_exact(benchmark::State& state) {
  const auto cones = random_cones(state.range(0), state.range(1));
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
  const auto cones = random_cones(state.range(0), state.range(1));
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
  const auto cones = random_cones(state.range(0), state.range(1));
  size_t i = 0;
  for (auto _ : state) {
    auto F = contactcert::reference::cdd_to_face(cones[i++ % cones.size()]);
    benchmark::DoNotOptimize(F);
  }
}

void BM_cdd_double(benchmark::State& state) {
  const auto cones = random_cones(state.range(0), state.range(1));
  const auto truth = exact_facets(cones);
  std::vector<SpanCone<double>> dc;
  for (const auto& c : cones)
    dc.push_back(SpanCone<double>::from_rows(c.dim, contactcert::exact::to_double(c.rays), Mat<double>(0, c.dim)));
  std::vector<bool> wrong(dc.size(), false);
  size_t i = 0;
  for (auto _ : state) {
    const size_t k = i++ % dc.size();
    auto F = contactcert::reference::cddf_to_face(dc[k]);
    if (F.inequalities.rows() != truth[k]) wrong[k] = true;
    benchmark::DoNotOptimize(F);
  }
  state.counters["wrong_of_20"] = static_cast<double>(std::count(wrong.begin(), wrong.end(), true));
}

void sizes(benchmark::internal::Benchmark* b) {
  for (auto [d, n] : std::vector<std::pair<long, long>>{{3, 6}, {3, 20}, {4, 12}, {6, 15}, {6, 30}, {8, 20}, {9, 30}, {12, 20}, {12, 40}})
    b->Args({d, n});
  b->Unit(benchmark::kMicrosecond);
}

BENCHMARK(BM_ours_exact)->Apply(sizes);
BENCHMARK(BM_cdd_gmp)->Apply(sizes);
BENCHMARK(BM_ours_float)->Apply(sizes);
BENCHMARK(BM_cdd_double)->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
