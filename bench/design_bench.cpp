// Fixture design on the ratchet pawl (scenes/design_ratchet_pawl.json, strongly stable under (0, -1, 0) and
// insertable, ranked by goal fraction, 3 fixels): placements decided per second on one core at N = 60 and
// N = 120 candidates (a seeded sample of placements, evaluated exactly as `contactcert design` does), the
// measured per-placement cost distribution, and from it a model of the parallel efficiency at P ranks:
// static (C(N, 3) / P consecutive placements per rank) against dynamic (chunks of 16 to the first idle rank,
// 50 us per request round trip). The model draws the C(N, 3) costs independently from the measured sample.
// A whole run at N = 20 (1140 placements in lexicographic order, as `contactcert design` evaluates them) gives
// the throughput of a design run.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <numeric>
#include <queue>
#include <random>

#include "geometry/scene_json.h"
#include "runtime/scenes.h"
#include "solvers/design/ranking.h"

namespace {

using namespace contactcert;
using solvers::DesignProblem;

DesignProblem pawl(long n) {
  const geometry::PlanarScene scene =
      geometry::load_planar_scene(runtime::bundled_scenes_dir() + "/design_ratchet_pawl.json");
  DesignProblem p;
  p.workpiece = scene.workpiece;
  p.mu_s = scene.fixels.front().mu_s;
  p.mu_k = scene.fixels.front().mu_k;
  p.candidates = solvers::arc_length_candidates(p.workpiece.shape, n);
  p.wrenches.kind = solvers::WrenchSet::Kind::kList;
  p.wrenches.rows = exact::Mat<exact::Q>(1, 3);
  p.wrenches.rows << 0, -1, 0;
  p.insertable = true;
  p.pushes = solvers::arc_length_candidates(p.workpiece.shape, 120);
  p.rank = solvers::Rank::kGoalFraction;
  return p;
}

std::vector<solvers::Placement> sample(const DesignProblem& p, int count) {
  const long n = static_cast<long>(p.candidates.size()), total = solvers::placement_count(n, p.fixels);
  std::mt19937_64 rng(20260101);
  std::vector<solvers::Placement> out;
  for (int i = 0; i < count; ++i)
    out.push_back(solvers::placement_at(static_cast<long>(rng() % static_cast<unsigned long>(total)), n, p.fixels));
  return out;
}

void BM_DesignPlacementsPerSecond(benchmark::State& state) {
  const DesignProblem p = pawl(state.range(0));
  const solvers::CandidateSymmetry sym = solvers::candidate_symmetry(p);
  const auto placements = sample(p, 48);
  long accepted = 0;
  for (auto _ : state)
    for (const auto& pl : placements)
      accepted += solvers::evaluate_placement(p, sym, pl).status == solvers::PlacementStatus::kAccepted;
  state.counters["placements_per_s"] =
      benchmark::Counter(static_cast<double>(placements.size()), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["accepted_fraction"] =
      static_cast<double>(accepted) / static_cast<double>(placements.size() * state.iterations());
}
BENCHMARK(BM_DesignPlacementsPerSecond)->Arg(60)->Arg(120)->Unit(benchmark::kMillisecond)->Iterations(1);

/// Every placement at N candidates in lexicographic order, as one `contactcert design` run evaluates them (chunks
/// of 16, insertion cones shared across the run): placements decided per CPU second.
void BM_DesignRunPlacementsPerSecond(benchmark::State& state) {
  const DesignProblem p = pawl(state.range(0));
  const solvers::CandidateSymmetry sym = solvers::candidate_symmetry(p);
  const long total = solvers::placement_count(static_cast<long>(p.candidates.size()), p.fixels), size = 16;
  long accepted = 0;
  for (auto _ : state) {
    solvers::InsertionCones<exact::Q> cones;
    for (long chunk = 0; chunk * size < total; ++chunk) {
      bool complete = false;
      accepted += solvers::run_chunk(p, sym, chunk, size, total, 5, {}, &complete, &cones).statistics.by_status[0];
    }
  }
  state.counters["placements"] = static_cast<double>(total);
  state.counters["placements_per_s"] =
      benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["accepted"] = static_cast<double>(accepted) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_DesignRunPlacementsPerSecond)->Arg(20)->Unit(benchmark::kMillisecond)->Iterations(1);

/// Makespan of a static split into P consecutive blocks.
double static_makespan(const std::vector<double>& cost, int P) {
  double worst = 0;
  const std::size_t n = cost.size();
  for (int r = 0; r < P; ++r) {
    const std::size_t a = n * static_cast<std::size_t>(r) / static_cast<std::size_t>(P),
                      b = n * static_cast<std::size_t>(r + 1) / static_cast<std::size_t>(P);
    worst =
        std::max(worst, std::accumulate(cost.begin() + static_cast<long>(a), cost.begin() + static_cast<long>(b), 0.0));
  }
  return worst;
}

/// Makespan of chunks of `chunk` consecutive placements handed in order to the first idle of P ranks.
double dynamic_makespan(const std::vector<double>& cost, int P, std::size_t chunk, double overhead) {
  std::priority_queue<double, std::vector<double>, std::greater<>> idle;
  for (int r = 0; r < P; ++r) idle.push(0);
  double end = 0;
  for (std::size_t a = 0; a < cost.size(); a += chunk) {
    const double t = idle.top() + overhead +
                     std::accumulate(cost.begin() + static_cast<long>(a),
                                     cost.begin() + static_cast<long>(std::min(cost.size(), a + chunk)), 0.0);
    idle.pop();
    idle.push(t);
    end = std::max(end, t);
  }
  return end;
}

void BM_DesignCostModel(benchmark::State& state) {
  const DesignProblem p = pawl(state.range(0));
  const solvers::CandidateSymmetry sym = solvers::candidate_symmetry(p);
  const auto placements = sample(p, 160);
  std::vector<double> ms;
  for (auto _ : state)
    for (const auto& pl : placements) {
      const auto t0 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(solvers::evaluate_placement(p, sym, pl));
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  auto pct = [&](double q) { return sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))]; };
  const double mean = std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(ms.size());
  state.counters["mean_ms"] = mean;
  state.counters["p10_ms"] = pct(0.1);
  state.counters["p50_ms"] = pct(0.5);
  state.counters["p90_ms"] = pct(0.9);
  state.counters["p99_ms"] = pct(0.99);
  state.counters["max_ms"] = sorted.back();
  const long total = solvers::placement_count(static_cast<long>(p.candidates.size()), 3);
  std::mt19937_64 rng(7);
  std::vector<double> cost(static_cast<std::size_t>(total));
  for (double& c : cost) c = ms[rng() % ms.size()];
  const double sum = std::accumulate(cost.begin(), cost.end(), 0.0);
  for (int P : {64, 1024}) {
    state.counters["static_eff_" + std::to_string(P)] = sum / (P * static_makespan(cost, P));
    state.counters["dynamic_eff_" + std::to_string(P)] = sum / (P * dynamic_makespan(cost, P, 16, 0.05));
  }
}
BENCHMARK(BM_DesignCostModel)->Arg(60)->Arg(120)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
