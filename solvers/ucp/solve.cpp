#include "solvers/ucp/solve.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "solvers/ucp/enumerate.h"

namespace contactcert::solvers::ucp {

namespace {

/// Budgets of the bilinear phase that precedes the complete search (its Step 3 is the costly part).
constexpr int kCompleteRandomMoves = 2;
constexpr long kCompleteMaxBases = 20;

template <class T>
void fill_pair(UcpReport& rep, const Vec<T>& x, const Vec<T>& y, const UcpProblem& problem) {
  if constexpr (std::is_same_v<T, Q>) {
    rep.x = x, rep.y = y;
    if (problem.quasistatic) {
      rep.physical = recover(*problem.quasistatic, x, y);
      if (rep.physical) rep.conditions = check_conditions(*problem.quasistatic, *rep.physical);
    }
  } else {
    (void)problem;
    rep.x_approx = x, rep.y_approx = y;
  }
}

template <class T>
void set_best(UcpReport& rep, const T& v) {
  if constexpr (std::is_same_v<T, Q>)
    rep.best_xTy = v;
  else
    rep.best_xTy_approx = v;
}

template <class T>
void run(const UcpProblem& problem, const UcpOptions& opts, UcpReport& rep) {
  const UcpInstance<T> u = convert<T>(problem.ucp);
  std::mt19937_64 rng(opts.seed);
  BilinearOptions bo;
  bo.arith = opts.arith;
  bo.max_random_moves = opts.max_random_moves;
  bo.max_bases = opts.max_bases;
  if (opts.method == Method::kPaper || opts.method == Method::kModified) {
    bo.step3 = opts.method == Method::kPaper ? Step3Rule::kPaper : Step3Rule::kModified;
    const BilinearResult<T> b = bilinear(make_face(u.X, {}), make_face(u.Y, {}), bo, rng);
    rep.pairs = b.pairs;
    rep.lps = b.counters.lps;
    rep.incomplete_adjacencies = b.counters.incomplete_adjacencies;
    switch (b.status) {
      case BilinearStatus::kComplementary:
        rep.status = UcpStatus::kSolvable;
        rep.reason = "x^T y = 0 reached by the bilinear algorithm";
        fill_pair(rep, b.x.x, b.y.x, problem);
        set_best(rep, b.xTy);
        break;
      case BilinearStatus::kStopped:
        rep.status = UcpStatus::kUnknown;
        rep.reason = "stationary pair with x^T y > 0 after " + std::to_string(b.random_moves - 1) +
                     " random Step 3 moves (the bilinear algorithm cannot prove that no solution exists)";
        set_best(rep, b.xTy);
        break;
      case BilinearStatus::kXEmpty:
      case BilinearStatus::kYEmpty: {
        const bool x_empty = b.status == BilinearStatus::kXEmpty;
        rep.status = UcpStatus::kJammed;
        rep.reason = x_empty ? "X is empty" : "Y is empty";
        if constexpr (std::is_same_v<T, Q>) {
          SearchResult<Q> proof;
          proof.status = UcpStatus::kJammed;
          proof.reason = rep.reason;
          proof.tree.resize(1);
          proof.tree[0].side = x_empty ? Side::kX : Side::kY;
          proof.tree[0].farkas = b.farkas;
          rep.proof = std::move(proof);
        }
        break;
      }
    }
    return;
  }
  SearchOptions so;
  so.max_nodes = opts.max_nodes;
  so.heuristic = bo;
  so.heuristic.step3 = Step3Rule::kModified;
  // The search decides; the bilinear phase before it only has to find easy solutions quickly.
  so.heuristic.max_random_moves = std::min(opts.max_random_moves, kCompleteRandomMoves);
  so.heuristic.max_bases = std::min(opts.max_bases, kCompleteMaxBases);
  SearchResult<T> s = complete_search(u, so, rng);
  rep.status = s.status;
  rep.reason = s.reason;
  rep.pairs = s.pairs;
  rep.lps = s.counters.lps;
  rep.incomplete_adjacencies = s.counters.incomplete_adjacencies;
  rep.nodes = s.nodes;
  rep.learned_prunes = s.learned_prunes;
  set_best(rep, s.xTy);
  if (s.status == UcpStatus::kSolvable) fill_pair(rep, s.x, s.y, problem);
  if constexpr (std::is_same_v<T, Q>) {
    if (s.status == UcpStatus::kJammed) rep.proof = std::move(s);
  }
}

}  // namespace

Method parse_method(const std::string& name) {
  if (name == "paper") return Method::kPaper;
  if (name == "modified") return Method::kModified;
  if (name == "complete") return Method::kComplete;
  if (name == "enumerate") return Method::kEnumerate;
  throw std::invalid_argument("method must be paper, modified, complete or enumerate, not \"" + name + "\"");
}

const char* method_name(Method m) {
  switch (m) {
    case Method::kPaper:
      return "paper";
    case Method::kModified:
      return "modified";
    case Method::kComplete:
      return "complete";
    case Method::kEnumerate:
      return "enumerate";
  }
  return "?";
}

const char* status_name(UcpStatus s) {
  switch (s) {
    case UcpStatus::kSolvable:
      return "solvable";
    case UcpStatus::kJammed:
      return "jammed";
    case UcpStatus::kUnknown:
      return "unknown";
  }
  return "?";
}

UcpReport solve_ucp(const UcpProblem& problem, const UcpOptions& opts) {
  const auto start = std::chrono::steady_clock::now();
  UcpReport rep;
  rep.method = opts.method;
  rep.arith = opts.arith;
  if (opts.method == Method::kEnumerate) {
    const Arith a = opts.arith == Arith::kFloat ? Arith::kVerified : opts.arith;  // the baseline is exact
    rep.arith = a;
    EnumerateResult e = enumerate_modes(problem, a, opts.max_enumerate_lps);
    rep.status = e.status;
    rep.lps = e.lps;
    rep.solutions = e.solutions;
    rep.solution_modes = e.solution_modes;
    rep.reason = e.status == UcpStatus::kUnknown
                     ? "too many modes for the enumeration budget"
                     : std::to_string(e.solutions) + " of " + std::to_string(e.lps) + " modes have a solution";
    if (e.solutions > 0) fill_pair(rep, e.x, e.y, problem);
  } else if (opts.arith == Arith::kFloat) {
    run<double>(problem, opts, rep);
  } else {
    run<Q>(problem, opts, rep);
  }
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return rep;
}

}  // namespace contactcert::solvers::ucp
