// The wrench cone paper's Table 4: time per cone for 1 to 6 fixels on a disk (paper: 0.00003 s to
// 0.219 s on an 800 MHz Pentium III), in one run: our exact and float paths on both routes, the
// paper's route with cddlib (GMP) doing K^F, and our K^F alone for comparison; then the projection
// route up to 20 fixels to show its growth. BM_Table4Ratios puts exact, float and cddlib side by side.
//   ./wrench_cone_bench --benchmark_counters_tabular=true
// Modes: 'n...n' (every fixel rolls: K is 2n x 2n) and 'm...m' (maintain contact: K is n x 2n, the
// hardest conversion since pos(K) has 2n generators in n dimensions). Each iteration computes the
// model (J, A, B), K and P, and the cone's canonical face form. "literal-K" runs the paper's route on
// the literal K, P of eqs. (15), (17); the others first row-reduce K z = P g (wrench_cone.h).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "geometry/double_description.h"
#include "geometry/scene_json.h"
#include "solvers/wrench_cone/wrench_cone.h"
#include "tests/reference/cdd_cone.h"

namespace {

using namespace contactcert;
using exact::Mat;
using exact::Q;

/// A unit disk (M = diag(1, 1, 1/2)) touching n fixels at rational points of its lower half
/// (angles -165 to -15 degrees, so that no mode is trivially force closure):
/// ((1 - t^2)/(1 + t^2), 2t/(1 + t^2)) with t = tan(theta/2) rounded to sixteenths. mu_s = 1/5.
geometry::PlanarScene disk_scene(int n) {
  geometry::PlanarScene s;
  const geometry::DiskShape disk{{Q(0), Q(0)}, Q(1)};
  s.workpiece = {disk, {Q(0), Q(0)}, Q(1, 2)};
  for (int i = 0; i < n; ++i) {
    const double theta = n == 1 ? -M_PI / 2 : -M_PI * (165.0 - 150.0 * i / (n - 1)) / 180.0;
    Q t(static_cast<long>(std::lround(std::tan(theta / 2) * 16)), 16);
    t.canonicalize();
    const Q d = 1 + t * t;
    const geometry::Point2 p{Q((1 - t * t) / d), Q(2 * t / d)};
    geometry::Fixel f;
    f.frame = geometry::frame_from_position(disk, p).frame;
    f.mu_s = Q(1, 5);
    f.mu_k = Q(1, 6);
    f.position = p;
    s.fixels.push_back(f);
  }
  return s;
}

solvers::ModeString mode(int n, char letter) {
  solvers::ModeString m;
  m.letters.assign(static_cast<std::size_t>(n), static_cast<solvers::Interaction>(letter));
  return m;
}

char letter_of(int64_t code) { return code == 0 ? 'n' : 'm'; }

template <class T, solvers::Route route, solvers::Preconditioning pre = solvers::Preconditioning::kRowReduce>
void BM_WrenchCone(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const geometry::PlanarScene scene = disk_scene(n);
  const solvers::ModeString m = mode(n, letter_of(state.range(1)));
  Eigen::Index rows = 0;
  for (auto _ : state) {
    const solvers::ContactModel<T> model = solvers::contact_model<T>(scene);
    const geometry::FaceCone<T> f = solvers::wrench_cone_face(scene, model, m, route, {}, pre);
    rows = f.inequalities.rows() + f.strict.rows();
    benchmark::DoNotOptimize(rows);
  }
  // The error of the path beside its time: does its face count match the exact cone's?
  const geometry::FaceCone<Q> exact_face = solvers::wrench_cone_face(scene, solvers::contact_model<Q>(scene), m, route);
  const Eigen::Index exact_rows = exact_face.inequalities.rows() + exact_face.strict.rows();
  state.counters["fixels"] = n;
  state.counters["facets"] = static_cast<double>(rows);
  state.counters["wrong_facet_count"] = rows == exact_rows ? 0 : 1;
  state.SetLabel(std::string(exact::NumberTraits<T>::name) +
                 (route == solvers::Route::kPaper ? " paper " : " project ") +
                 (pre == solvers::Preconditioning::kNone ? "literal-K " : "") +
                 std::string(static_cast<std::size_t>(n), letter_of(state.range(1))));
}

/// Our share outside the conversion: J, A, B (per scene) and K, P (per mode), exact.
void BM_ModelAndConeForm(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const geometry::PlanarScene scene = disk_scene(n);
  const solvers::ModeString m = mode(n, letter_of(state.range(1)));
  for (auto _ : state) {
    const solvers::ContactModel<Q> model = solvers::contact_model<Q>(scene);
    const solvers::ConeForm<Q> form = solvers::cone_form(scene, model, m);
    benchmark::DoNotOptimize(form.K.data());
  }
  state.counters["fixels"] = n;
  state.SetLabel("exact J A B + K P " + std::string(static_cast<std::size_t>(n), letter_of(state.range(1))));
}

/// The raw eq. (18), F = K^F P without row reduction, with K^F from `convert` (cddlib's or ours).
template <class Convert>
void raw_paper_route(benchmark::State& state, Convert convert, const std::string& label) {
  const int n = static_cast<int>(state.range(0));
  const geometry::PlanarScene scene = disk_scene(n);
  const solvers::ModeString m = mode(n, letter_of(state.range(1)));
  Eigen::Index rows = 0;
  for (auto _ : state) {
    const solvers::ContactModel<Q> model = solvers::contact_model<Q>(scene);
    const solvers::ConeForm<Q> form = solvers::cone_form(scene, model, m);
    const geometry::FaceCone<Q> KF = convert(geometry::SpanCone<Q>::from_columns(form.K));
    const Mat<Q> F = KF.inequalities * form.P;  // eq. (18)
    rows = F.rows();
    benchmark::DoNotOptimize(rows);
  }
  state.counters["fixels"] = n;
  state.counters["KF_rows"] = static_cast<double>(rows);
  state.SetLabel(label + " " + std::string(static_cast<std::size_t>(n), letter_of(state.range(1))));
}

/// The paper's route with K^F by cddlib (GMP).
void BM_PaperRouteCddKF(benchmark::State& state) {
  raw_paper_route(
      state, [](const geometry::SpanCone<Q>& c) { return reference::cdd_to_face(c); }, "cddlib-gmp K^F");
}

/// The same with our own exact conversion for K^F (what cddlib's column competes with).
void BM_PaperRouteOwnKF(benchmark::State& state) {
  raw_paper_route(
      state, [](const geometry::SpanCone<Q>& c) { return geometry::to_face(c); }, "own exact K^F");
}

/// Median wall time of `reps` calls of f, in microseconds.
template <class F>
double median_us(F&& f, int reps = 41) {
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(t.begin(), t.begin() + reps / 2, t.end());
  return t[static_cast<std::size_t>(reps / 2)];
}

/// Table 4 side by side: the exact paper route (the timed body), the float paper route and the raw
/// eq. (18) with cddlib's K^F, each as a median per cone (model included), and the ratios.
void BM_Table4Ratios(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const geometry::PlanarScene scene = disk_scene(n);
  const solvers::ModeString m = mode(n, letter_of(state.range(1)));
  auto exact = [&] {
    const geometry::FaceCone<Q> f =
        solvers::wrench_cone_face(scene, solvers::contact_model<Q>(scene), m, solvers::Route::kPaper);
    benchmark::DoNotOptimize(f.inequalities.rows());
  };
  auto flt = [&] {
    const geometry::FaceCone<double> f =
        solvers::wrench_cone_face(scene, solvers::contact_model<double>(scene), m, solvers::Route::kPaper);
    benchmark::DoNotOptimize(f.inequalities.rows());
  };
  auto cdd = [&] {
    const solvers::ContactModel<Q> model = solvers::contact_model<Q>(scene);
    const solvers::ConeForm<Q> form = solvers::cone_form(scene, model, m);
    const Mat<Q> F = reference::cdd_to_face(geometry::SpanCone<Q>::from_columns(form.K)).inequalities * form.P;
    benchmark::DoNotOptimize(F.rows());
  };
  for (auto _ : state) exact();
  const double e = median_us(exact), f = median_us(flt), c = median_us(cdd);
  state.counters["fixels"] = n;
  state.counters["exact_us"] = e;
  state.counters["float_us"] = f;
  state.counters["cddlib_us"] = c;
  state.counters["exact/float"] = e / f;
  state.counters["exact/cddlib"] = e / c;
  state.SetLabel(std::string(static_cast<std::size_t>(n), letter_of(state.range(1))));
}

void table4(benchmark::internal::Benchmark* b) {
  for (int letter = 0; letter < 2; ++letter)
    for (int n = 1; n <= 6; ++n) b->Args({n, letter});
}

void growth(benchmark::internal::Benchmark* b) {
  for (int letter = 0; letter < 2; ++letter)
    for (int n : {8, 10, 12, 16, 20}) b->Args({n, letter});
}

BENCHMARK(BM_Table4Ratios)->Apply(table4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WrenchCone<Q, solvers::Route::kPaper>)->Apply(table4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WrenchCone<Q, solvers::Route::kProject>)->Apply(table4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WrenchCone<Q, solvers::Route::kPaper, solvers::Preconditioning::kNone>)
    ->Apply(table4)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WrenchCone<double, solvers::Route::kPaper>)->Apply(table4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WrenchCone<double, solvers::Route::kProject>)->Apply(table4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ModelAndConeForm)->Apply(table4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PaperRouteCddKF)->Apply(table4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PaperRouteOwnKF)->Apply(table4)->Unit(benchmark::kMicrosecond);
void growth_rolling(benchmark::internal::Benchmark* b) {
  for (int n : {8, 10, 12, 16, 20}) b->Args({n, 0});
}

BENCHMARK(BM_WrenchCone<Q, solvers::Route::kProject>)->Apply(growth)->Unit(benchmark::kMicrosecond);
// The paper's route after row reduction converts pos(K) in 3 dimensions for 'n...n' modes.
BENCHMARK(BM_WrenchCone<Q, solvers::Route::kPaper>)->Apply(growth_rolling)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
