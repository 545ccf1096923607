// Cone conversion in both directions: our exact (fraction-free) and float paths against cddlib GMP,
// PPL and Normaliz (when found, see bench/CMakeLists.txt), lrs (its program on files; BM_lrs reports the
// lrs process's CPU time as its manual time) and cddlib double, in one run, on identical
// integer inputs. Families (first argument): d > 0, random integer cones (entries in [-20, 20],
// ANCHORS.md) in R^d with the second argument generators (pointed: first coordinate positive); 0, the K
// matrices of the wrench cone algorithm (eq. 15) for 1-8 fixels on a disk; -1, 12 random facets in R^4
// to rays; -2 / -4, the facets of the 6- / 10-cube to its rays; -3, the generators of the 6-cross-
// polytope to its 64 facets; -5, the 1024 generators of the 10-cube to its facets; -6, the 906 facets
// of a random cone over 35 points in R^8 (below) to its rays. BM_ours_order: ours with the row order of
// the third argument. Counters: output rows, and for the float paths the instances whose row count
// differs from the exact answer (wrong).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "bench/cone_peers.h"
#include "exact/fraction_free.h"
#include "exact/int_matrix.h"
#include "exact/json_input.h"
#include "geometry/canonical.h"
#include "geometry/double_description.h"
#include "geometry/scene_json.h"
#include "solvers/wrench_cone/cone_form.h"
#include "solvers/wrench_cone/contact_model.h"
#include "solvers/wrench_cone/mode.h"
#include "tests/geometry/polytope_cones.h"
#include "tests/reference/cdd_cone.h"

namespace {

using contactcert::exact::Mat;
using contactcert::exact::Q;
using contactcert::exact::Z;
using contactcert::geometry::FaceCone;
using contactcert::geometry::SpanCone;
namespace testing = contactcert::geometry::testing;

constexpr int kInstances = 20;

// kInstances random integer matrices (entries in [-20, 20]) with first column sign * (|x| + 1): for
// sign 1 generators of pointed cones over random polytopes (otherwise most random cones with many
// generators are the whole space), for sign -1 facets of a cone with (1, 0, ..., 0) inside.
std::vector<Mat<Q>> random_rows(long dim, long rows, unsigned long seed, long sign) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long> u(-20, 20);
  std::vector<Mat<Q>> out;
  for (int i = 0; i < kInstances; ++i) {
    Mat<Q> M(rows, dim);
    for (long r = 0; r < rows; ++r) {
      for (long j = 0; j < dim; ++j) M(r, j) = Q(u(rng));
      M(r, 0) = sign * (abs(M(r, 0)) + 1);
    }
    out.push_back(M);
  }
  return out;
}

std::vector<SpanCone<Q>> random_cones(long dim, long gens) {
  std::vector<SpanCone<Q>> out;
  for (const Mat<Q>& R : random_rows(dim, gens, static_cast<unsigned long>(1000 * dim + gens), 1))
    out.push_back(SpanCone<Q>::from_rows(dim, R, Mat<Q>(0, dim)));
  return out;
}

// The K matrices of the wrench cone algorithm (eq. 15) for a unit disk with `fixels` touching fixels
// at rational points of the circle, for 12 seeded random modes (letters that fit a touching fixel).
std::vector<SpanCone<Q>> wrench_k_cones(long fixels) {
  namespace solvers = contactcert::solvers;
  const char* points[] = {"[0, -1]",
                          "[1, 0]",
                          "[0, 1]",
                          "[-1, 0]",
                          "[\"3/5\", \"4/5\"]",
                          "[\"-4/5\", \"-3/5\"]",
                          "[\"5/13\", \"-12/13\"]",
                          "[\"-12/13\", \"5/13\"]"};
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

// One family: span cones (converted to facets) or face cones (converted to rays).
struct Workload {
  std::vector<SpanCone<Q>> spans;
  std::vector<FaceCone<Q>> faces;
  std::vector<std::vector<std::vector<Z>>> rows;  // the same inputs as primitive integer rows
  std::vector<long> dims;
  std::size_t size() const { return spans.size() + faces.size(); }
};

std::vector<FaceCone<Q>> random_facets(long dim, long rows) {
  std::vector<FaceCone<Q>> out;
  for (const Mat<Q>& F : random_rows(dim, rows, static_cast<unsigned long>(7 * dim + rows), -1))
    out.push_back(FaceCone<Q>::from_rows(dim, F, Mat<Q>(0, dim), Mat<Q>(0, dim)));
  return out;
}

// The dimension-8 case: 35 random generators in [-20, 20]^8 (first coordinate |x| + 1, seed 835) have
// a cone with hundreds of facets; converting those facets back to the 35 rays is the hard direction.
FaceCone<Q> hard_dim8_facets() {
  std::mt19937_64 rng(835);
  std::uniform_int_distribution<long> u(-20, 20);
  Mat<Q> R(35, 8);
  for (long r = 0; r < 35; ++r) {
    for (long j = 0; j < 8; ++j) R(r, j) = Q(u(rng));
    R(r, 0) = abs(R(r, 0)) + 1;
  }
  return contactcert::geometry::canonical(contactcert::geometry::to_face(SpanCone<Q>::from_rows(8, R, Mat<Q>(0, 8))));
}

Workload workload(const benchmark::State& state) {
  Workload w;
  const long code = state.range(0);
  if (code > 0) w.spans = random_cones(code, state.range(1));
  if (code == 0) w.spans = wrench_k_cones(state.range(1));
  if (code == -1) w.faces = random_facets(4, 12);
  if (code == -2) w.faces = {testing::cube_face(6)};
  if (code == -3) w.spans = {testing::cross_polytope_span(6)};
  if (code == -4) w.faces = {testing::cube_face(10)};
  if (code == -5) w.spans = {testing::cube_span(10)};
  if (code == -6) w.faces = {hard_dim8_facets()};
  // The peers' input: the rows of to_ring_rows, as nested vectors (Normaliz's own input type).
  auto peer_rows = [](const Mat<Q>& M) {
    const auto rows = contactcert::exact::ring::to_ring_rows<Z>(M);
    std::vector<std::vector<Z>> out;
    for (long i = 0; i < rows.rows(); ++i) out.emplace_back(rows.row(i), rows.row(i) + rows.cols());
    return out;
  };
  for (const auto& c : w.spans) w.rows.push_back(peer_rows(c.rays)), w.dims.push_back(c.dim);
  for (const auto& c : w.faces) w.rows.push_back(peer_rows(c.inequalities)), w.dims.push_back(c.dim);
  return w;
}

// Runs `convert(i)` (the output row count of instance i) over the workload, every instance once per
// repetition, and reports the mean output rows.
template <class Convert>
void run(benchmark::State& state, const Workload& w, Convert convert) {
  long out = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    const long n = convert(i++ % w.size());
    out += n;
    benchmark::DoNotOptimize(n);
  }
  state.counters["rows_out"] = static_cast<double>(out) / static_cast<double>(state.iterations());
  std::size_t in = 0;
  for (const auto& r : w.rows) in += r.size();
  state.counters["rows_in"] = static_cast<double>(in) / static_cast<double>(w.rows.size());
}

void BM_ours_exact(benchmark::State& state) {
  const Workload w = workload(state);
  run(state, w, [&](std::size_t i) {
    if (!w.spans.empty()) return static_cast<long>(contactcert::geometry::to_face(w.spans[i]).inequalities.rows());
    return static_cast<long>(contactcert::geometry::to_span(w.faces[i]).rays.rows());
  });
}

// Our exact conversion with the row order of the third argument (geometry::RowOrder as an integer).
void BM_ours_order(benchmark::State& state) {
  const Workload w = workload(state);
  contactcert::geometry::DdBudget budget;
  budget.order = static_cast<contactcert::geometry::RowOrder>(state.range(2));
  run(state, w, [&](std::size_t i) {
    if (!w.spans.empty())
      return static_cast<long>(contactcert::geometry::to_face(w.spans[i], budget).inequalities.rows());
    return static_cast<long>(contactcert::geometry::to_span(w.faces[i], budget).rays.rows());
  });
}

void BM_cdd_gmp(benchmark::State& state) {
  const Workload w = workload(state);
  if (state.range(0) == -6) return state.SkipWithError("over a minute per conversion");
  run(state, w, [&](std::size_t i) {
    if (!w.spans.empty()) return static_cast<long>(contactcert::reference::cdd_to_face(w.spans[i]).inequalities.rows());
    return static_cast<long>(contactcert::reference::cdd_to_span(w.faces[i]).rays.rows());
  });
}

void BM_ppl(benchmark::State& state) {
  const Workload w = workload(state);
  if (contactcert::bench::ppl_facets({}, 1) < 0) return state.SkipWithError("built without PPL");
  if (state.range(0) == -6) return state.SkipWithError("over a minute per conversion");
  run(state, w, [&](std::size_t i) {
    return w.spans.empty() ? contactcert::bench::ppl_rays(w.rows[i], w.dims[i])
                           : contactcert::bench::ppl_facets(w.rows[i], w.dims[i]);
  });
}

void BM_normaliz(benchmark::State& state) {
  const Workload w = workload(state);
  if (contactcert::bench::normaliz_facets({{Z(1)}}, 1) < 0) return state.SkipWithError("built without Normaliz");
  run(state, w, [&](std::size_t i) {
    return w.spans.empty() ? contactcert::bench::normaliz_rays(w.rows[i], w.dims[i])
                           : contactcert::bench::normaliz_facets(w.rows[i], w.dims[i]);
  });
}

Mat<Q> to_matrix(const std::vector<std::vector<Z>>& rows, long dim) {
  Mat<Q> M(static_cast<long>(rows.size()), dim);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (long j = 0; j < dim; ++j) M(static_cast<long>(i), j) = Q(rows[i][static_cast<std::size_t>(j)]);
  return M;
}

// lrs's own CPU time per conversion (the program run on files: process start, parsing and printing
// included); `unequal`: the instances whose output differs from ours as a set (canonical forms).
void BM_lrs(benchmark::State& state) {
  namespace geometry = contactcert::geometry;
  namespace bench = contactcert::bench;
  const Workload w = workload(state);
  // (The 10-cube's 1024 generators: one lrs run took over 90 s.)
  if (state.range(0) == -6 || state.range(0) == -5) return state.SkipWithError("over a minute per conversion");
  auto convert = [&](std::size_t i) {
    return w.spans.empty() ? bench::lrs_rays(w.rows[i], w.dims[i]) : bench::lrs_facets(w.rows[i], w.dims[i]);
  };
  long unequal = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const auto out = convert(i);
    if (!out) return state.SkipWithError("the lrs program is missing or failed");
    const long d = w.dims[i];
    if (w.spans.empty()) {
      const auto theirs = SpanCone<Q>::from_rows(d, to_matrix(out->rows, d), to_matrix(out->linearity, d));
      unequal +=
          geometry::identical(geometry::canonical(theirs), geometry::canonical(geometry::to_span(w.faces[i]))) ? 0 : 1;
    } else {
      const auto theirs =
          FaceCone<Q>::from_rows(d, to_matrix(out->rows, d), to_matrix(out->linearity, d), Mat<Q>(0, d));
      unequal +=
          geometry::identical(geometry::canonical(theirs), geometry::canonical(geometry::to_face(w.spans[i]))) ? 0 : 1;
    }
  }
  long rows = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto out = convert(i++ % w.size());
    if (!out) return state.SkipWithError("the lrs program failed");
    state.SetIterationTime(out->cpu_seconds);
    rows += static_cast<long>(out->rows.size());
  }
  state.counters["rows_out"] = static_cast<double>(rows) / static_cast<double>(state.iterations());
  state.counters["unequal"] = static_cast<double>(unequal);
}

std::vector<long> exact_facets(const std::vector<SpanCone<Q>>& cones) {
  std::vector<long> f;
  for (const auto& c : cones) f.push_back(static_cast<long>(contactcert::geometry::to_face(c).inequalities.rows()));
  return f;
}

// A float conversion of the span families timed cone by cone: `wrong_of_20` counts the cones whose facet count
// differs from the exact one, or whose conversion gave up (cddlib's numerical inconsistency).
template <class ToFace>
void run_float(benchmark::State& state, ToFace to_face) {
  const auto cones = workload(state).spans;
  if (cones.empty()) return state.SkipWithError("span families only");
  const auto truth = exact_facets(cones);
  std::vector<SpanCone<double>> dc;
  for (const auto& c : cones)
    dc.push_back(SpanCone<double>::from_rows(c.dim, contactcert::exact::to_double(c.rays), Mat<double>(0, c.dim)));
  std::vector<bool> wrong(dc.size(), false);
  size_t i = 0;
  for (auto _ : state) {
    const size_t k = i++ % dc.size();
    try {
      auto F = to_face(dc[k]);
      if (F.inequalities.rows() != truth[k]) wrong[k] = true;
      benchmark::DoNotOptimize(F);
    } catch (const std::runtime_error&) {
      wrong[k] = true;
    }
  }
  state.counters["wrong_of_20"] = static_cast<double>(std::count(wrong.begin(), wrong.end(), true));
}

void BM_ours_float(benchmark::State& state) {
  run_float(state, [](const SpanCone<double>& c) { return contactcert::geometry::to_face(c); });
}

void BM_cdd_double(benchmark::State& state) {
  run_float(state, [](const SpanCone<double>& c) { return contactcert::reference::cddf_to_face(c); });
}

void sizes(benchmark::internal::Benchmark* b) {
  for (auto [d, n] : std::vector<std::pair<long, long>>{{3, 20}, {4, 12}, {5, 15}, {6, 30}, {7, 20}, {8, 20}})
    b->Args({d, n});
  for (long family = -1; family >= -5; --family) b->Args({family, 0});
  for (long fixels = 4; fixels <= 8; ++fixels) b->Args({0, fixels});
  // Every instance once per repetition, so that all converters time the same cones.
  b->Iterations(kInstances)->Unit(benchmark::kMicrosecond);
}

// Every family with every row order (lexmin, lexmax, min cutoff, max cutoff).
void orders(benchmark::internal::Benchmark* b) {
  for (const std::vector<long>& a : {std::vector<long>{3, 20},
                                     {4, 12},
                                     {5, 15},
                                     {6, 30},
                                     {7, 20},
                                     {8, 20},
                                     {-1, 0},
                                     {-2, 0},
                                     {-3, 0},
                                     {-4, 0},
                                     {-5, 0},
                                     {0, 4},
                                     {0, 5},
                                     {0, 6},
                                     {0, 7},
                                     {0, 8}})
    for (long order = 0; order < 4; ++order) b->Args({a[0], a[1], order});
  b->Iterations(kInstances)->Unit(benchmark::kMicrosecond);
}

BENCHMARK(BM_ours_exact)->Apply(sizes);
BENCHMARK(BM_ours_order)->Apply(orders);
BENCHMARK(BM_ppl)->Apply(sizes);
BENCHMARK(BM_normaliz)->Apply(sizes);
BENCHMARK(BM_cdd_gmp)->Apply(sizes);
BENCHMARK(BM_lrs)->Apply(sizes)->UseManualTime();
BENCHMARK(BM_ours_float)->Apply(sizes);
BENCHMARK(BM_cdd_double)->Apply(sizes);
// The dimension-8 case, once (cddlib and PPL take minutes).
BENCHMARK(BM_ours_exact)->Args({-6, 0})->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_normaliz)->Args({-6, 0})->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ours_order)->ArgsProduct({{-6}, {0}, {0, 1, 2, 3}})->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
