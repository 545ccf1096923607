// Table 1 of Pang, Trinkle, Lo in spirit, and the speed targets of the UCP solver.
//   ucp_bench [--quick]
//   ucp_bench --adaptive [REPEATS [FILTER]]   (only the --arith adaptive table of docs/precision.md; FILTER: the
//                                            problems whose name contains it; "rounded": leaves of a jammed float
//                                            tree proven by rounding / all its leaves)
//   ucp_bench --recovery [REPEATS]           (only the exact physical recovery and the check of (2)-(10))
// Prints, for twenty random problems with the paper's nc, mu range, |alpha| and |abar| (section 5 generator,
// seeded), the pairs, LPs, best x^T y, verdict and time of the paper algorithm, the modified algorithm and the
// complete search (verified arithmetic; end to end with its phases); then the targets: nc = 40 solvable (verified), nc
// = 10 jammed, and LPs of the complete search against the enumerative baseline at nc = 8.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "runtime/memory.h"
#include "runtime/scenes.h"
#include "solvers/ucp/generate.h"
#include "solvers/ucp/solve.h"

using namespace contactcert;
using namespace contactcert::solvers::ucp;
using contactcert::exact::Q;
using contactcert::exact::Vec;

namespace {

struct Table1Row {
  int nc;
  int mu_tenths;  // mu range (0, mu_tenths / 10)
  int alpha, abar;
};

const Table1Row kTable1[20] = {{3, 10, 6, 0},   {10, 10, 20, 0}, {10, 20, 20, 0}, {15, 12, 29, 1},  {18, 8, 27, 9},
                               {20, 10, 40, 0}, {20, 15, 40, 0}, {20, 12, 40, 0}, {20, 10, 30, 10}, {20, 10, 30, 10},
                               {20, 10, 40, 0}, {30, 10, 60, 0}, {30, 5, 45, 15}, {30, 6, 45, 15},  {40, 10, 80, 0},
                               {40, 10, 80, 0}, {10, 13, 15, 5}, {15, 12, 24, 6}, {30, 6, 45, 15},  {40, 10, 60, 20}};

UcpProblem make(int nc, int mu_tenths, int abar, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  RandomProblemOptions o;
  o.nc = nc;
  o.mu_max = Q(mu_tenths, 10);
  o.mu_max.canonicalize();
  o.abar_size = abar;
  return generate_random_problem(o, rng);
}

UcpOptions options(Method m, Arith a, std::uint64_t seed = 1) {
  UcpOptions o;
  o.method = m;
  o.arith = a;
  o.seed = seed;
  o.max_nodes = 100000;
  return o;
}

UcpReport run(const UcpProblem& p, Method m, Arith a = Arith::kVerified, std::uint64_t seed = 1) {
  return solve_ucp(p, options(m, a, seed));
}

/// What a user of `contactcert ucp FILE --certificate C` waits for: the file's text read, X and Y built, the method
/// run, the certificate made (exact paths); report.phases has every phase in CPU seconds.
UcpReport run_end_to_end(const std::string& text, Method m, Arith a) {
  UcpPhases setup;
  const UcpProblem p = read_ucp_problem(exact::JsonInput::parse(text, "bench"), &setup);
  UcpReport r = solve_ucp(p, options(m, a));
  r.phases.parse = setup.parse;
  r.phases.build = setup.build;
  if (a != Arith::kFloat && m != Method::kEnumerate) {
    const PhaseTimer t(r.phases.certificate);
    (void)certificate_text(p, r);
  }
  return r;
}

double best(const UcpReport& r) { return r.best_xTy ? r.best_xTy->get_d() : (r.x ? 0.0 : -1.0); }

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Median over `repeats` batches of the CPU seconds of one call() (a batch repeats the call until it has taken
/// 20 ms, so that microsecond calls are timed over many calls).
template <class F>
double median_seconds(int repeats, F&& call) {
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    long calls = 0;
    const double start = cpu_seconds();
    double now = start;
    do {
      call();
      ++calls;
      now = cpu_seconds();
    } while (now - start < 0.02);
    t.push_back((now - start) / static_cast<double>(calls));
  }
  std::nth_element(t.begin(), t.begin() + static_cast<long>(t.size() / 2), t.end());
  return t[t.size() / 2];
}

/// The median CPU ms of one solve_ucp call.
/// CPU seconds per call of each of `calls`, timed in `repeats` interleaved rounds (a round times one batch of
/// each in turn, so that a change of machine speed during the run moves them alike): per call its median batch, and
/// the median over rounds of its batch divided by that of calls[0] in the same round (a paired ratio, steadier than
/// the ratio of medians on a shared machine).
struct Interleaved {
  std::vector<double> median, ratio;
};
Interleaved interleaved(int repeats, const std::vector<std::function<void()>>& calls) {
  std::vector<std::vector<double>> t(calls.size()), r(calls.size());
  for (int round = 0; round < repeats; ++round)
    for (std::size_t k = 0; k < calls.size(); ++k) {
      t[k].push_back(median_seconds(1, calls[k]));
      r[k].push_back(t[k].back() / t[0].back());
    }
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  Interleaved out;
  for (std::size_t k = 0; k < calls.size(); ++k) out.median.push_back(median(t[k])), out.ratio.push_back(median(r[k]));
  return out;
}

struct Case {
  std::string name;
  UcpProblem p;
};

/// The paper's Data Sets 1..last (scenes/pang1994_dataset*.json).
std::vector<Case> paper_cases(int last) {
  std::vector<Case> cases;
  for (int k = 1; k <= last; ++k)
    cases.push_back(
        {"Data Set " + std::to_string(k),
         load_ucp_problem(runtime::bundled_scenes_dir() + "/pang1994_dataset" + std::to_string(k) + ".json")});
  return cases;
}

/// The --arith adaptive table of docs/precision.md: float, verified, adaptive, and adaptive on the same UCP as a
/// generic problem (X's and Y's rows only: no physics, and the pair from the rows, not from the velocities and
/// forces), on the paper's data sets and the large problems of `contactcert bench` (family large, nc 40: the
/// section 5 generator, mt19937_64(seed)). Timed in interleaved rounds; the ratios are paired (interleaved()).
void adaptive_table(int repeats, const std::string& filter) {
  std::vector<Case> cases = paper_cases(4);
  for (std::uint64_t s = 1; s <= 5; ++s) {
    std::mt19937_64 rng(s);
    RandomProblemOptions o;
    o.nc = 40;
    cases.push_back({"large nc 40 seed " + std::to_string(s), generate_random_problem(o, rng)});
  }
  std::printf("CPU ms per solve_ucp call, median of %d interleaved rounds; ratios to float paired by round\n", repeats);
  std::printf("%-22s %-9s %9s %9s %9s %9s %-9s %8s %11s %11s %9s\n", "problem", "verdict", "float", "verified",
              "adaptive", "generic", "decided", "repaired", "adapt/float", "gener/float", "rounded");
  for (const Case& c : cases) {
    if (c.name.find(filter) == std::string::npos) continue;
    UcpProblem bare = c.p;
    bare.quasistatic.reset();
    UcpReport f, v, a, an;
    const Interleaved t = interleaved(repeats, {[&] { f = run(c.p, Method::kComplete, Arith::kFloat); },
                                                [&] { v = run(c.p, Method::kComplete, Arith::kVerified); },
                                                [&] { a = run(c.p, Method::kComplete, Arith::kAdaptive); },
                                                [&] { an = run(bare, Method::kComplete, Arith::kAdaptive); }});
    const std::string rounded = std::to_string(a.leaves.rounded) + "/" + std::to_string(a.leaves.total());
    std::printf("%-22s %-9s %9.4f %9.4f %9.4f %9.4f %-9s %8ld %11.2f %11.2f %9s%s\n", c.name.c_str(),
                status_name(a.status), 1e3 * t.median[0], 1e3 * t.median[1], 1e3 * t.median[2], 1e3 * t.median[3],
                a.decided_by.c_str(), a.leaves.repaired, t.ratio[2], t.ratio[3], rounded.c_str(),
                a.status == v.status ? "" : "  VERDICT DIFFERS FROM VERIFIED");
  }
}

/// CPU microseconds of recover and of check_conditions (recovery.h) on the adaptive pair of the paper's
/// solvable data sets and of solvable random problems (section 5 generator), median of `repeats` batches.
void recovery_table(int repeats) {
  std::vector<Case> cases = paper_cases(3);
  for (auto [nc, abar] : {std::pair{10, 3}, std::pair{40, 0}})
    for (std::uint64_t s = 1, found = 0; s < 60 && found < 2; ++s) {
      UcpProblem p = make(nc, 10, abar, s);
      if (run(p, Method::kComplete).status != UcpStatus::kSolvable) continue;
      ++found;
      cases.push_back(
          {"nc " + std::to_string(nc) + " abar " + std::to_string(abar) + " seed " + std::to_string(s), std::move(p)});
    }
  std::printf("CPU us per call, median of %d batches\n", repeats);
  std::printf("%-24s %10s %10s %10s\n", "problem", "recover", "check", "violations");
  for (const Case& c : cases) {
    const UcpReport r = run(c.p, Method::kComplete);
    const QuasistaticProblem& q = *c.p.quasistatic;
    const Vec<Q> x = r.x->to_q(), y = r.y->to_q();
    const PhysicalSolution s = *recover(q, x, y);
    const double tr = 1e6 * median_seconds(repeats, [&] { (void)recover(q, x, y); });
    const double tc = 1e6 * median_seconds(repeats, [&] { (void)check_conditions(q, s); });
    std::printf("%-24s %10.2f %10.2f %10zu\n", c.name.c_str(), tr, tc, check_conditions(q, s).violations.size());
  }
}

}  // namespace

int main(int argc, char** argv) {
  contactcert::runtime::keep_heap_until_exit();
  contactcert::runtime::use_pooled_gmp_memory();
  if (argc > 1 && std::strcmp(argv[1], "--recovery") == 0) {
    recovery_table(argc > 2 ? std::atoi(argv[2]) : 7);
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "--adaptive") == 0) {
    adaptive_table(argc > 2 ? std::atoi(argv[2]) : 7, argc > 3 ? argv[3] : "");
    return 0;
  }
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  std::printf(
      "Table 1 (random problems, section 5 generator, seed 1000 + problem number; verified arithmetic). paper, "
      "modified: CPU s of the solve; complete: CPU s end to end (read the file's text, build X and Y, solve, "
      "recover, check (2)-(10), certificate) and its phases in ms\n");
  std::printf("%3s %3s %7s %5s %5s | %-26s | %-26s | %-34s | %s\n", "No", "nc", "mu<", "|a|", "|ab|",
              "paper: pairs LPs best time", "modified: pairs LPs best", "complete: LPs nodes verdict total",
              "parse build solve recover check cert");
  int solvable = 0, jammed = 0, unknown = 0, paper_undecided = 0;
  for (int k = 0; k < (quick ? 6 : 20); ++k) {
    const Table1Row& row = kTable1[k];
    const UcpProblem p = make(row.nc, row.mu_tenths, row.abar, 1000 + static_cast<std::uint64_t>(k) + 1);
    const UcpReport a = run(p, Method::kPaper), b = run(p, Method::kModified);
    const UcpReport c = run_end_to_end(to_json_text(p), Method::kComplete, Arith::kVerified);
    const UcpPhases& t = c.phases;
    paper_undecided += a.status != UcpStatus::kSolvable && b.status != UcpStatus::kSolvable;
    (c.status == UcpStatus::kSolvable ? solvable : c.status == UcpStatus::kJammed ? jammed : unknown)++;
    std::printf(
        "%3d %3d %7.1f %5d %5d | %4ld %4ld %8.3g %6.3fs | %4ld %4ld %8.3g %6.3fs | %5ld %5ld %-8s %7.3fs | %.2f %.2f "
        "%.2f %.2f %.2f %.2f\n",
        k + 1, row.nc, row.mu_tenths / 10.0, row.alpha, row.abar, a.pairs, a.lps, best(a), a.phases.solve, b.pairs,
        b.lps, best(b), b.phases.solve, c.lps, c.nodes, status_name(c.status), t.total(), 1e3 * t.parse, 1e3 * t.build,
        1e3 * t.solve, 1e3 * t.recover, 1e3 * t.check, 1e3 * t.certificate);
  }
  std::printf("complete search: %d solvable, %d jammed, %d unknown; paper+modified left %d undecided\n\n", solvable,
              jammed, unknown, paper_undecided);

  // Target 1: nc = 40 solvable problems on the verified path.
  std::printf("nc = 40, mu in (0, 1), |abar| = 0, solvable problems (complete; CPU ms end to end, as Table 1):\n");
  int found = 0;
  for (std::uint64_t s = 1; s < 60 && found < (quick ? 2 : 5); ++s) {
    const std::string text = to_json_text(make(40, 10, 0, s));
    const UcpReport r = run_end_to_end(text, Method::kComplete, Arith::kVerified);
    if (r.status != UcpStatus::kSolvable) continue;
    ++found;
    const UcpReport f = run_end_to_end(text, Method::kComplete, Arith::kFloat);
    const UcpReport a = run_end_to_end(text, Method::kComplete, Arith::kAdaptive);
    std::printf("  seed %2llu: verified %6.1f ms (%ld LPs), adaptive %6.1f ms, float %6.2f ms\n",
                static_cast<unsigned long long>(s), 1e3 * r.phases.total(), r.lps, 1e3 * a.phases.total(),
                1e3 * f.phases.total());
  }
  // Target 2: nc = 10 jammed problems proven.
  std::printf("nc = 10, mu in (0, 1.3), |abar| = 5, jammed problems (complete, verified):\n");
  found = 0;
  for (std::uint64_t s = 1; s < 60 && found < (quick ? 2 : 5); ++s) {
    const UcpProblem p = make(10, 13, 5, s);
    const UcpReport r = run(p, Method::kComplete);
    if (r.status != UcpStatus::kJammed) continue;
    ++found;
    std::printf("  seed %2llu: proven jammed in %6.1f CPU ms of the solve (%ld LPs, %ld nodes)\n",
                static_cast<unsigned long long>(s), 1e3 * r.phases.solve, r.lps, r.nodes);
  }
  // Target 3: LPs at nc = 8 against the enumerative baseline (4^8 modes, one LP each).
  std::printf("nc = 8, |alpha| = 16, mu in (0, 1): LPs of the complete search vs the enumerative baseline:\n");
  for (std::uint64_t s = 1; s <= (quick ? 1u : 4u); ++s) {
    const UcpProblem p = make(8, 10, 0, s);
    const UcpReport c = run(p, Method::kComplete), e = run(p, Method::kEnumerate);
    std::printf(
        "  seed %llu: complete %-8s %4ld LPs %7.1f ms | enumerate %-8s %ld LPs (%ld solution modes) %7.1f ms | "
        "ratio %.0fx\n",
        static_cast<unsigned long long>(s), status_name(c.status), c.lps, 1e3 * c.phases.solve, status_name(e.status),
        e.lps, e.solutions, 1e3 * e.phases.solve, static_cast<double>(e.lps) / static_cast<double>(c.lps));
  }
  return 0;
}
