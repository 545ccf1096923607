// LPs of the shapes the UCP produces: X = {x in R^{3nc}_+ : Zn vn + Zt (vt+ - vt-) = b} with Z the
// left null space of a random planar contact matrix P (2nc x 3), and Y = {y in R^{3nc}_+ : C y = -d} with C
// of size (nc + 3 + nc/2) x 3nc. Our float, exact and verified paths against CGAL's solve_linear_program
// (Gmpzf) and cddlib's GMP dd_LPSolve on the same LPs, and the precision ladder (filtered:
// intervals then exact; adaptive: double, intervals, MPFR 113 and 256 bits, exact). Each iteration solves
// kInstances LPs.
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>
#include <benchmark/benchmark.h>

#include <map>
#include <random>
#include <vector>

#include "exact/adjacent_vertices.h"
#include "exact/linalg.h"
#include "exact/simplex.h"
#include "exact/verified_lp.h"
#include "tests/reference/cdd_lp.h"

namespace {

using namespace contactcert::exact;
using Index = Eigen::Index;
constexpr int kInstances = 4;

/// Scales each row of M to primitive integers (the row space is unchanged).
Mat<Q> integer_rows(Mat<Q> M) {
  for (Index i = 0; i < M.rows(); ++i) {
    mpz_class den = 1, num = 0;
    for (Index j = 0; j < M.cols(); ++j) den = lcm(den, M(i, j).get_den());
    for (Index j = 0; j < M.cols(); ++j) num = gcd(num, Q(M(i, j) * den).get_num());
    if (num == 0) continue;
    for (Index j = 0; j < M.cols(); ++j) M(i, j) = M(i, j) * den / num;
  }
  return M;
}

LpProblem<Q> with_feasible_rhs_and_cost(Mat<Q> A, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> x0d(0, 2), cd(0, 3);
  Vec<Q> x0(A.cols()), c(A.cols());
  for (Index j = 0; j < A.cols(); ++j) {
    x0(j) = x0d(rng);
    c(j) = cd(rng);
  }
  Vec<Q> b = A * x0;
  return {std::move(A), std::move(b), std::move(c), {}};
}

/// X: A = [Zn | Zt | -Zt], Z = left null space of P (2nc x 3): (2nc - 3) x 3nc.
LpProblem<Q> x_lp(int nc, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> d(-3, 3);
  Mat<Q> P(2 * nc, 3);
  for (Index i = 0; i < P.rows(); ++i)
    for (Index j = 0; j < 3; ++j) P(i, j) = d(rng);
  const Mat<Q> Z = integer_rows(left_null_space<Q>(P));
  Mat<Q> A(Z.rows(), 3 * nc);
  A << Z.leftCols(nc), Z.rightCols(nc), -Z.rightCols(nc);
  return with_feasible_rhs_and_cost(std::move(A), rng);
}

/// Y: C with 3 dense wrench rows, one friction row (mu, -1, -1) per contact, nc/2 rows fixing a y_j to 0.
LpProblem<Q> y_lp(int nc, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> d(-3, 3), mu(1, 3), col(0, 3 * nc - 1);
  Mat<Q> C = Mat<Q>::Zero(nc + 3 + nc / 2, 3 * nc);
  for (Index i = 0; i < 3; ++i)
    for (Index j = 0; j < 3 * nc; ++j) C(i, j) = d(rng);
  for (int i = 0; i < nc; ++i) {
    C(3 + i, i) = mu(rng);
    C(3 + i, nc + i) = -1;
    C(3 + i, 2 * nc + i) = -1;
  }
  for (int k = 0; k < nc / 2; ++k) C(3 + nc + k, col(rng)) = 1;
  return with_feasible_rhs_and_cost(std::move(C), rng);
}

struct Instances {
  std::vector<LpProblem<Q>> exact;
  std::vector<LpProblem<double>> floats;
  std::vector<CGAL::Quadratic_program<int>> cgal;
};

const Instances& instances(char shape, int nc) {
  static std::map<std::pair<char, int>, Instances> cache;
  auto it = cache.find({shape, nc});
  if (it != cache.end()) return it->second;
  Instances& out = cache[{shape, nc}];
  std::mt19937_64 rng(static_cast<unsigned long>(1000 * nc + shape));
  for (int k = 0; k < kInstances; ++k) {
    LpProblem<Q> p = shape == 'X' ? x_lp(nc, rng) : y_lp(nc, rng);
    CGAL::Quadratic_program<int> qp(CGAL::EQUAL, true, 0, false, 0);
    for (Index i = 0; i < p.rows(); ++i) {
      for (Index j = 0; j < p.cols(); ++j)
        if (p.A(i, j) != 0)
          qp.set_a(static_cast<int>(j), static_cast<int>(i), static_cast<int>(p.A(i, j).get_num().get_si()));
      qp.set_b(static_cast<int>(i), static_cast<int>(p.b(i).get_num().get_si()));
    }
    for (Index j = 0; j < p.cols(); ++j) qp.set_c(static_cast<int>(j), static_cast<int>(p.c(j).get_num().get_si()));
    out.floats.push_back(to_double(p));
    out.exact.push_back(std::move(p));
    out.cgal.push_back(std::move(qp));
  }
  return out;
}

void set_counters(benchmark::State& state, const Instances& in) {
  state.counters["rows"] = static_cast<double>(in.exact[0].rows());
  state.counters["cols"] = static_cast<double>(in.exact[0].cols());
}

template <char Shape>
void BM_float(benchmark::State& state) {
  const Instances& in = instances(Shape, static_cast<int>(state.range(0)));
  int wrong = 0;
  for (size_t k = 0; k < in.exact.size(); ++k) {
    const LpResult<double> f = solve_lp<double>(in.floats[k]);
    const LpResult<Q> e = solve_lp_verified(in.exact[k]);
    if (f.status != e.status || (f.status == LpStatus::kOptimal && std::abs(f.value - e.value.get_d()) > 1e-6)) ++wrong;
  }
  for (auto _ : state)
    for (const LpProblem<double>& p : in.floats) benchmark::DoNotOptimize(solve_lp<double>(p));
  set_counters(state, in);
  state.counters["wrong_verdicts"] = wrong;
}

template <char Shape>
void BM_exact(benchmark::State& state) {
  const Instances& in = instances(Shape, static_cast<int>(state.range(0)));
  double pivots = 0;
  for (auto _ : state)
    for (const LpProblem<Q>& p : in.exact) pivots = static_cast<double>(solve_lp<Q>(p).pivots);
  set_counters(state, in);
  state.counters["pivots_last"] = pivots;
}

template <char Shape>
void BM_verified(benchmark::State& state) {
  const Instances& in = instances(Shape, static_cast<int>(state.range(0)));
  int checked = 0;
  for (const LpProblem<Q>& p : in.exact)
    checked += solve_lp_verified(p).decided_by == DecidedBy::kFloatBasisCheckedExactly;
  for (auto _ : state)
    for (const LpProblem<Q>& p : in.exact) benchmark::DoNotOptimize(solve_lp_verified(p));
  set_counters(state, in);
  state.counters["float_basis_checked"] = checked;
}

/// The filter alone in front of exact arithmetic: intervals propose, exact arithmetic checks.
const std::vector<Rung>& filtered_ladder() {
  static const std::vector<Rung> ladder{{Rung::Kind::kInterval, 0}, {Rung::Kind::kExact, 0}};
  return ladder;
}

/// solve_lp_ladder on a ladder; decided_by_first_rung counts the LPs whose first rung's basis checked out.
template <char Shape, const std::vector<Rung>& (*Ladder)()>
void BM_ladder(benchmark::State& state) {
  const Instances& in = instances(Shape, static_cast<int>(state.range(0)));
  int first = 0;
  for (const LpProblem<Q>& p : in.exact) {
    const LpResult<Q> r = solve_lp_ladder(p, Ladder());
    first += r.decided_by == DecidedBy::kFloatBasisCheckedExactly && r.proposed_by == Ladder().front();
  }
  for (auto _ : state)
    for (const LpProblem<Q>& p : in.exact) benchmark::DoNotOptimize(solve_lp_ladder(p, Ladder()));
  set_counters(state, in);
  state.counters["decided_by_first_rung"] = first;
}

template <char Shape>
void BM_cgal(benchmark::State& state) {
  const Instances& in = instances(Shape, static_cast<int>(state.range(0)));
  int disagree = 0;
  for (size_t k = 0; k < in.exact.size(); ++k) {
    const auto s = CGAL::solve_linear_program(in.cgal[k], CGAL::Gmpzf());
    const LpResult<Q> e = solve_lp_verified(in.exact[k]);
    const bool same = (s.is_optimal() && e.status == LpStatus::kOptimal) ||
                      (s.is_infeasible() && e.status == LpStatus::kInfeasible) ||
                      (s.is_unbounded() && e.status == LpStatus::kUnbounded);
    disagree += same ? 0 : 1;
  }
  for (auto _ : state)
    for (const auto& qp : in.cgal) benchmark::DoNotOptimize(CGAL::solve_linear_program(qp, CGAL::Gmpzf()));
  set_counters(state, in);
  state.counters["status_disagreements"] = disagree;
}

template <char Shape>
void BM_cdd(benchmark::State& state) {
  const Instances& in = instances(Shape, static_cast<int>(state.range(0)));
  int disagree = 0;
  for (const LpProblem<Q>& p : in.exact) {
    const contactcert::reference::CddLpResult r = contactcert::reference::cdd_solve_lp_once(p);
    const LpResult<Q> e = solve_lp_verified(p);
    disagree += (r.status != e.status || (e.status == LpStatus::kOptimal && r.value != e.value)) ? 1 : 0;
  }
  for (auto _ : state)
    for (const LpProblem<Q>& p : in.exact) benchmark::DoNotOptimize(contactcert::reference::cdd_solve_lp_once(p));
  set_counters(state, in);
  state.counters["disagreements"] = disagree;
}

template <char Shape>
void BM_adjacent(benchmark::State& state) {
  const Instances& in = instances(Shape, static_cast<int>(state.range(0)));
  std::vector<std::vector<Index>> bases;
  for (const LpProblem<Q>& p : in.exact) bases.push_back(solve_lp_verified(p).basis);
  double edges = 0;
  for (auto _ : state)
    for (size_t k = 0; k < in.exact.size(); ++k)
      edges = static_cast<double>(adjacent_vertices<Q>(in.exact[k], bases[k]).edges.size());
  set_counters(state, in);
  state.counters["edges_last"] = edges;
}

#define LP_BENCH_RUNS(name)           \
  Name(name)                          \
      ->Arg(3)                        \
      ->Arg(10)                       \
      ->Arg(20)                       \
      ->Arg(40)                       \
      ->Unit(benchmark::kMicrosecond) \
      ->Repetitions(3)                \
      ->ReportAggregatesOnly(true)
#define LP_BENCH(fn, shape, name) BENCHMARK(fn<shape>)->LP_BENCH_RUNS(name)

LP_BENCH(BM_float, 'X', "X/float");
LP_BENCH(BM_verified, 'X', "X/verified");
BENCHMARK(BM_ladder<'X', filtered_ladder>)->LP_BENCH_RUNS("X/filtered");
BENCHMARK(BM_ladder<'X', adaptive_ladder>)->LP_BENCH_RUNS("X/adaptive");
LP_BENCH(BM_exact, 'X', "X/exact");
LP_BENCH(BM_cgal, 'X', "X/cgal");
LP_BENCH(BM_cdd, 'X', "X/cdd");
LP_BENCH(BM_float, 'Y', "Y/float");
LP_BENCH(BM_verified, 'Y', "Y/verified");
BENCHMARK(BM_ladder<'Y', filtered_ladder>)->LP_BENCH_RUNS("Y/filtered");
BENCHMARK(BM_ladder<'Y', adaptive_ladder>)->LP_BENCH_RUNS("Y/adaptive");
LP_BENCH(BM_exact, 'Y', "Y/exact");
LP_BENCH(BM_cgal, 'Y', "Y/cgal");
LP_BENCH(BM_cdd, 'Y', "Y/cdd");
LP_BENCH(BM_adjacent, 'X', "X/adjacent_vertices_exact");
LP_BENCH(BM_adjacent, 'Y', "Y/adjacent_vertices_exact");

}  // namespace

BENCHMARK_MAIN();
