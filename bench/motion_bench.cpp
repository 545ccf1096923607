// Quasistatic time-stepping (solvers/motion, issue 32): steps per second of the exact, verified and float paths
// side by side in one run, and verified per step over float (the target: within 3x), on the bundled pushed
// box (sliding, finger at height 1/2, or tipping about its front corner, 3/2; 100 steps of 1/200) and the bundled
// peg lowered into a chamfered hole (16 steps of 3/4) and the bundled row of four boxes pushed by a finger (four
// bodies, each step the assembly's problem; 9 steps of 1/3). "bare" runs the steps only, "full" also decides each
// step's uniqueness and keeps its certificate (exact paths; the float path has neither). Then where float goes wrong: a
// grazing family (a ceiling 10^-k above the sliding box's top) and near-threshold pushes (h = 1 +- 10^-k), each with
// the step at which the float run first differs from the verified one (-1: never), its kind and the pose distance
// then. Last, the 1000-step run, verified, with every step's certificate (no uniqueness), in seconds.
//   build/bench/motion_bench
#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>

#include "bench/user_memory_main.h"
#include "exact/json_input.h"
#include "runtime/scenes.h"
#include "solvers/motion/compare.h"
#include "solvers/motion/simulate.h"

namespace {

using namespace contactcert;
using exact::Q;
using solvers::motion::MotionScene;
using solvers::motion::SimulateOptions;

MotionScene bundled(const std::string& name) {
  return solvers::motion::read_motion_scene(exact::JsonInput::load(runtime::bundled_scenes_dir() + "/" + name));
}

/// The bundled pushed box with the finger at height h, N steps of H.
MotionScene pushed_box(const Q& h, const Q& H, long N) {
  MotionScene s = bundled("motion_pushed_box.json");
  s.fingers.at(0).tip.y = h;
  s.dt = H;
  s.steps = N;
  return s;
}

/// 10^-k, exactly.
Q ten_to_minus(long k) {
  exact::Z p = 1;
  for (long i = 0; i < k; ++i) p *= 10;
  return Q(exact::Z(1), p);
}

/// CPU seconds of this process per step of run() (which returns its step count): the machine is shared, so wall
/// clock would measure the other workers too.
template <class F>
double cpu_per_step(F run) {
  const auto cpu = [] {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  };
  const double start = cpu();
  const std::size_t steps = run();
  return (cpu() - start) / static_cast<double>(std::max<std::size_t>(1, steps));
}

/// CPU seconds per step of one run.
template <class T>
double per_step(const MotionScene& scene, SimulateOptions o, exact::Arith arith) {
  o.arith = arith;
  return cpu_per_step([&] { return solvers::motion::simulate<T>(scene, o).steps.size(); });
}

/// range(0): 0 the box slides, 1 it tips, 2 the peg, 3 the four-box row; range(1): 1 with uniqueness and
/// certificates.
void BM_Paths(benchmark::State& state) {
  const long which = state.range(0);
  const bool full = state.range(1) == 1;
  const MotionScene scene = which == 3   ? bundled("motion_pushed_row.json")
                            : which == 2 ? bundled("motion_peg_chamfer.json")
                                         : pushed_box(which == 1 ? Q(3, 2) : Q(1, 2), Q(1, 200), 100);
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
  const char* names[] = {"box slides", "box tips", "peg", "four-box row"};
  state.SetLabel(std::string(names[which]) + (full ? ", uniqueness + certificates" : ", bare"));
}
// Bare runs take a few milliseconds each: 20 iterations keep the ratio's spread between runs small.
BENCHMARK(BM_Paths)->ArgsProduct({{0, 1, 2, 3}, {0}})->Unit(benchmark::kMillisecond)->Iterations(20);
BENCHMARK(BM_Paths)->ArgsProduct({{0, 1, 2, 3}, {1}})->Unit(benchmark::kMillisecond)->Iterations(3);

/// The verified and the float run of `scene` side by side: steps per second of each (CPU), the float run's first
/// divergence of any kind (often a pose ~1e-16 inside a shape: rounding) and its first wrong answer (a different
/// verdict, a missed or phantom contact, a different mode or end), with the pose distance then.
void diverge(benchmark::State& state, const MotionScene& scene, const std::string& name) {
  SimulateOptions o;
  o.uniqueness = false;
  std::vector<solvers::motion::Divergence> d;
  double verified = 0, fl = 0;
  for (auto _ : state) {
    o.arith = exact::Arith::kVerified;
    solvers::motion::Trajectory<Q> ex;
    verified += cpu_per_step([&] { return (ex = solvers::motion::simulate<Q>(scene, o)).steps.size(); });
    o.arith = exact::Arith::kFloat;
    solvers::motion::Trajectory<double> f;
    fl += cpu_per_step([&] { return (f = solvers::motion::simulate<double>(scene, o)).steps.size(); });
    d = solvers::motion::compare_runs(scene, ex, f);
  }
  const auto wrong = std::find_if(d.begin(), d.end(), [](const auto& x) { return x.kind != "penetration"; });
  const auto n = static_cast<double>(state.iterations());
  state.counters["verified_steps_per_s"] = n / verified;
  state.counters["float_steps_per_s"] = n / fl;
  state.counters["first_differs_at_step"] = d.empty() ? -1.0 : static_cast<double>(d[0].step);
  state.counters["first_wrong_at_step"] = wrong == d.end() ? -1.0 : static_cast<double>(wrong->step);
  state.counters["pose_distance_then"] = wrong == d.end() ? 0.0 : wrong->pose_distance;
  state.SetLabel(name + ": " + (wrong == d.end() ? "no wrong answer" : wrong->kind + ": " + wrong->what));
}

/// A ceiling 10^-k above the top of the sliding box (h = 1/2), 20 steps of 1/10: exactly it is never touched.
void BM_Grazing(benchmark::State& state) {
  const long k = state.range(0);
  MotionScene s = pushed_box(Q(1, 2), Q(1, 10), 20);
  const Q gap = ten_to_minus(k);
  solvers::motion::Obstacle ceiling = s.obstacles.at(0);
  ceiling.name = "ceiling";
  ceiling.vertices = {{Q(-1), 2 + gap}, {Q(9), 2 + gap}, {Q(9), Q(3)}, {Q(-1), Q(3)}};
  s.obstacles.push_back(ceiling);
  diverge(state, s, "ceiling 1e-" + std::to_string(k) + " above the box");
}
BENCHMARK(BM_Grazing)->Arg(6)->Arg(9)->Arg(10)->Arg(12)->Unit(benchmark::kMillisecond)->Iterations(1);

/// The box pushed at h = 1 + sign 10^-k (range(1): +1 tips, -1 slides), 10 steps of 1/10.
void BM_NearThreshold(benchmark::State& state) {
  const long k = state.range(0), side = state.range(1);
  const Q h = 1 + side * ten_to_minus(k);
  diverge(state, pushed_box(h, Q(1, 10), 10),
          std::string("h = 1 ") + (side > 0 ? "+" : "-") + " 1e-" + std::to_string(k));
}
BENCHMARK(BM_NearThreshold)
    ->ArgsProduct({{3, 6, 9, 12, 15, 17}, {1, -1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

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

int main(int argc, char** argv) { return contactcert::bench::run_with_user_memory(argc, argv); }
