// Quasistatic time-stepping (solvers/motion, issue 32) on the bundled pushed box: steps per second of the exact,
// verified and float paths side by side in one run, and verified per step over float (the target: within
// 3x). The box slides (finger at height 1/2) or tips about its front corner (3/2); "bare" runs the steps only,
// "full" also decides each step's uniqueness and keeps its certificate (exact paths; the float path has neither).
// Then the 1000-step run, verified, with every step's certificate (no uniqueness), in seconds.
//   build/bench/motion_bench
#include <benchmark/benchmark.h>

#include "exact/json_input.h"
#include "runtime/scenes.h"
#include "solvers/motion/simulate.h"

namespace {

using namespace contactcert;
using exact::Q;
using solvers::motion::MotionScene;
using solvers::motion::SimulateOptions;

/// The bundled pushed box with the finger at height h, N steps of H.
MotionScene pushed_box(const Q& h, const Q& H, long N) {
  MotionScene s = solvers::motion::read_motion_scene(
      exact::JsonInput::load(runtime::bundled_scenes_dir() + "/motion_pushed_box.json"));
  s.fingers.at(0).tip.y = h;
  s.dt = H;
  s.steps = N;
  return s;
}

/// Seconds per step of one run.
template <class T>
double per_step(const MotionScene& scene, SimulateOptions o, exact::Arith arith) {
  o.arith = arith;
  const solvers::motion::Trajectory<T> r = solvers::motion::simulate<T>(scene, o);
  return r.seconds / static_cast<double>(std::max<std::size_t>(1, r.steps.size()));
}

void BM_PushedBox(benchmark::State& state) {
  const bool tips = state.range(0) == 1, full = state.range(1) == 1;
  const MotionScene scene = pushed_box(tips ? Q(3, 2) : Q(1, 2), Q(1, 200), 100);
  SimulateOptions o;
  o.uniqueness = o.certificates = full;
  double exact = 0, verified = 0, fl = 0;
  for (auto _ : state) {
    exact += per_step<Q>(scene, o, exact::Arith::kExact);
    verified += per_step<Q>(scene, o, exact::Arith::kVerified);
    fl += per_step<double>(scene, o, exact::Arith::kFloat);
  }
  const auto n = static_cast<double>(state.iterations());
  state.counters["exact_steps_per_s"] = n / exact;
  state.counters["verified_steps_per_s"] = n / verified;
  state.counters["float_steps_per_s"] = n / fl;
  state.counters["verified_over_float"] = verified / fl;
  state.counters["exact_over_float"] = exact / fl;
  state.SetLabel(std::string(tips ? "tips" : "slides") + (full ? ", uniqueness + certificates" : ", bare"));
}
BENCHMARK(BM_PushedBox)->ArgsProduct({{0, 1}, {0, 1}})->Unit(benchmark::kMillisecond)->Iterations(3);

/// 1000 steps of 1/20000, verified, every step's certificate kept, no uniqueness: seconds for the whole run.
void BM_ThousandSteps(benchmark::State& state) {
  const bool tips = state.range(0) == 1;
  const MotionScene scene = pushed_box(tips ? Q(3, 2) : Q(1, 2), Q(1, 20000), 1000);
  SimulateOptions o;
  o.uniqueness = false;
  std::size_t steps = 0;
  for (auto _ : state) steps = solvers::motion::simulate<Q>(scene, o).steps.size();
  state.counters["steps"] = static_cast<double>(steps);
  state.SetLabel(tips ? "tips" : "slides");
}
BENCHMARK(BM_ThousandSteps)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
