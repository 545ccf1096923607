#include "solvers/ucp/solve.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "exact/interval_number.h"
#include "exact/mpfr_number.h"
#include "solvers/ucp/certificate.h"
#include "solvers/ucp/enumerate.h"
#include "solvers/ucp/float_check.h"

namespace contactcert::solvers::ucp {

namespace {

/// Budgets of the bilinear phase that precedes the complete search (its Step 3 is the costly part).
constexpr int kCompleteRandomMoves = 2;
constexpr long kCompleteMaxBases = 20;

template <class T>
Vec<double> approx(const Vec<T>& v) {
  return v.unaryExpr([](const T& e) { return exact::NumberTraits<T>::to_double(e); });
}

/// The shape of a verdict found in a float number type, for its exact check (float_check.h): the zero
/// pattern of the complementary pair (every index fixed to 0 on one side), or the search tree with its float
/// Farkas vectors in doubles.
struct FloatEvidence {
  std::vector<bool> x_zero, y_zero;
  FloatTree tree;
};

/// x_i = 0 where T's sign test says so; y_i = 0 wherever x_i is not.
template <class T>
void record_pattern(FloatEvidence* ev, const Vec<T>& x, const Vec<T>& y) {
  if (!ev) return;
  ev->x_zero.assign(static_cast<std::size_t>(x.size()), false);
  ev->y_zero = ev->x_zero;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    ev->x_zero[static_cast<std::size_t>(i)] = exact::is_zero(x(i));
    ev->y_zero[static_cast<std::size_t>(i)] = !ev->x_zero[static_cast<std::size_t>(i)] || exact::is_zero(y(i));
  }
}

template <class T>
void record_tree(FloatEvidence* ev, const std::vector<SearchNode<T>>& tree) {
  if (!ev) return;
  ev->tree.nodes.resize(tree.size());
  ev->tree.farkas.resize(tree.size());
  for (std::size_t k = 0; k < tree.size(); ++k) {
    ev->tree.nodes[k].branch = tree[k].branch;
    ev->tree.nodes[k].child_x_zero = tree[k].child_x_zero;
    ev->tree.nodes[k].child_y_zero = tree[k].child_y_zero;
    ev->tree.nodes[k].side = tree[k].side;
    ev->tree.nodes[k].farkas_basis = tree[k].farkas_basis;
    ev->tree.farkas[k] = approx(tree[k].farkas);
  }
}

template <class T>
void fill_pair(UcpReport& rep, Vec<T> x, Vec<T> y, const UcpProblem& problem) {
  if constexpr (std::is_same_v<T, Q>) {
    if (problem.quasistatic) {
      {
        const PhaseTimer t(rep.phases.recover);
        rep.physical = recover(*problem.quasistatic, x, y);
      }
      const PhaseTimer t(rep.phases.check);
      if (rep.physical) rep.conditions = check_conditions(*problem.quasistatic, *rep.physical);
    }
    const PhaseTimer t(rep.phases.recover);
    rep.x = exact::RationalVector(x), rep.y = exact::RationalVector(y);
  } else {
    (void)problem;
    rep.x_approx = approx(x), rep.y_approx = approx(y);
    if constexpr (!std::is_same_v<T, double>) {
      rep.x_float = x.unaryExpr([](const T& e) { return exact::to_rational(e); });
      rep.y_float = y.unaryExpr([](const T& e) { return exact::to_rational(e); });
    }
  }
}

/// The float pair of rep made exact with the zero pattern of ev (float_check.h), with its physics. A quasistatic
/// problem's pair comes from its velocities and forces (pattern_solution: small systems in P instead of X's and Y's
/// rows, and the physics comes with it), else from X's and Y's rows. False if a side's face is empty in exact
/// arithmetic. Timed as recover (pattern_solution's check of (2)-(10) included).
bool exact_solution(const UcpProblem& problem, const FloatEvidence& ev, UcpReport& rep, LpCounters& count) {
  std::optional<PhaseTimer> t(std::in_place, rep.phases.recover);
  if (problem.quasistatic) {
    if (std::optional<PatternSolution> s = pattern_solution(*problem.quasistatic, ev.x_zero, ev.y_zero)) {
      rep.conditions = std::move(s->conditions);
      rep.x = std::move(s->x);
      rep.y = std::move(s->y);
      rep.physical = std::move(s->physical);
      return true;
    }
  }
  std::optional<std::pair<Vec<Q>, Vec<Q>>> pair =
      exact_pair(problem, rep.x_approx, rep.y_approx, ev.x_zero, ev.y_zero, count);
  if (!pair) return false;
  t.reset();  // fill_pair times its own phases
  fill_pair(rep, std::move(pair->first), std::move(pair->second), problem);
  return true;
}

template <class T>
void set_best(UcpReport& rep, const T& v) {
  if constexpr (std::is_same_v<T, Q>)
    rep.best_xTy = v;
  else
    rep.best_xTy_approx = exact::NumberTraits<T>::to_double(v);
}

/// The options of the bilinear algorithm (Method::kPaper, kModified; the heuristic of the complete search).
BilinearOptions bilinear_options(const UcpOptions& opts, const exact::Deadline& deadline) {
  BilinearOptions bo;
  bo.arith = opts.arith;
  bo.max_random_moves = opts.max_random_moves;
  bo.max_bases = opts.max_bases;
  bo.deadline = deadline;
  return bo;
}

/// The options of the complete search (Method::kComplete).
SearchOptions search_options(const UcpOptions& opts, const exact::Deadline& deadline) {
  SearchOptions so;
  so.max_nodes = opts.max_nodes;
  so.deadline = deadline;
  so.progress = opts.progress;
  so.heuristic = bilinear_options(opts, deadline);
  so.heuristic.step3 = Step3Rule::kModified;
  // The search decides; the bilinear phase before it only has to find easy solutions quickly.
  so.heuristic.max_random_moves = std::min(opts.max_random_moves, kCompleteRandomMoves);
  so.heuristic.max_bases = std::min(opts.max_bases, kCompleteMaxBases);
  return so;
}

/// Runs the method on u (the problem's instance in T). ev (T not Q): receives the shape of the verdict.
template <class T>
void run(const UcpProblem& problem, const UcpInstance<T>& u, const UcpOptions& opts, const exact::Deadline& deadline,
         UcpReport& rep, FloatEvidence* ev = nullptr) {
  std::mt19937_64 rng(opts.seed);
  if (opts.method == Method::kPaper || opts.method == Method::kModified) {
    BilinearOptions bo = bilinear_options(opts, deadline);
    bo.step3 = opts.method == Method::kPaper ? Step3Rule::kPaper : Step3Rule::kModified;
    const BilinearResult<T> b = bilinear(make_face(u.X, {}), make_face(u.Y, {}), bo, rng);
    rep.pairs = b.pairs;
    rep.lps = b.counters.lps;
    rep.incomplete_adjacencies = b.counters.incomplete_adjacencies;
    rep.limited = b.status == BilinearStatus::kTimeLimit;
    switch (b.status) {
      case BilinearStatus::kComplementary:
        rep.status = UcpStatus::kSolvable;
        rep.reason = "x^T y = 0 reached by the bilinear algorithm";
        record_pattern(ev, b.x.x, b.y.x);
        fill_pair(rep, b.x.x, b.y.x, problem);
        set_best(rep, b.xTy);
        break;
      case BilinearStatus::kStopped:
        rep.status = UcpStatus::kUnknown;
        rep.reason = "stationary pair with x^T y > 0 after " + std::to_string(b.random_moves - 1) +
                     " random Step 3 moves (the bilinear algorithm cannot prove that no solution exists)";
        set_best(rep, b.xTy);
        break;
      case BilinearStatus::kTimeLimit:
        rep.status = UcpStatus::kUnknown;
        rep.reason = deadline.reached_text() + " after " + std::to_string(b.pairs) + " pairs";
        if (b.x.x.size() > 0) set_best(rep, b.xTy);  // not if the deadline passed inside Step 0
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
        } else if (ev) {
          ev->tree.nodes.resize(1);
          ev->tree.nodes[0].side = x_empty ? Side::kX : Side::kY;
          ev->tree.farkas = {approx(b.farkas)};
        }
        break;
      }
    }
    return;
  }
  SearchResult<T> s = complete_search(u, search_options(opts, deadline), rng);
  rep.status = s.status;
  rep.reason = s.reason;
  rep.limited = s.status == UcpStatus::kUnknown;  // the node budget or the time limit ran out
  rep.pairs = s.pairs;
  rep.lps = s.counters.lps;
  rep.incomplete_adjacencies = s.counters.incomplete_adjacencies;
  rep.nodes = s.nodes;
  rep.learned_prunes = s.learned_prunes;
  if (s.paired || s.status != UcpStatus::kUnknown) set_best(rep, s.xTy);  // a budget may end it before a pair
  if (s.status == UcpStatus::kSolvable) {
    record_pattern(ev, s.x, s.y);
    fill_pair(rep, std::move(s.x), std::move(s.y), problem);
  }
  if constexpr (std::is_same_v<T, Q>) {
    if (s.status == UcpStatus::kJammed) rep.proof = std::move(s);
  } else if (s.status == UcpStatus::kJammed) {
    record_tree(ev, s.tree);
  }
}

/// One float rung of --arith adaptive: the method in T, then its verdict checked exactly (float_check.h).
/// True if the verdict checked out (rep then holds it with exact evidence); false for `unknown`, a verdict
/// that does not check out, or an uncertain interval sign.
template <class T>
bool decide_at(const UcpProblem& problem, const UcpInstance<T>& u, const RowFactors& factors, const UcpOptions& opts,
               const exact::Deadline& deadline, UcpReport& rep) {
  UcpReport r;
  r.method = rep.method;
  r.arith = rep.arith;
  FloatEvidence ev;
  try {
    run<T>(problem, u, opts, deadline, r, &ev);
  } catch (const exact::UncertainSign&) {
    return false;
  }
  for (std::size_t k = 0; k < ev.tree.farkas.size(); ++k) {  // Farkas vectors of the rows as given
    const std::vector<double>& f = ev.tree.nodes[k].side == Side::kX ? factors.X : factors.Y;
    Vec<double>& y = ev.tree.farkas[k];
    for (Eigen::Index i = 0; i < y.size(); ++i) y(i) *= f[static_cast<std::size_t>(i)];
  }
  LpCounters check;
  if (r.status == UcpStatus::kSolvable) {
    if (!exact_solution(problem, ev, r, check)) return false;
    r.x_approx = r.y_approx = Vec<double>();
    r.best_xTy = Q(0);
  } else if (r.status == UcpStatus::kJammed) {
    // The complete search repairs a leaf whose face is not empty by searching exactly below it (its LPs
    // verified, as the check's); the bilinear methods cannot, so their verdict then fails.
    std::optional<SearchOptions> repair;
    if (opts.method == Method::kComplete) {
      repair = search_options(opts, deadline);
      repair->heuristic.arith = Arith::kVerified;
    }
    ProvenTree proven = prove_leaves(problem, std::move(ev.tree), repair);
    check.lps += proven.result.counters.lps;
    r.leaves = proven.leaves;
    if (proven.result.status == UcpStatus::kSolvable) {
      r.status = UcpStatus::kSolvable;
      r.reason = "complete search (below a leaf of the float search tree whose face is not empty)";
      fill_pair(r, std::move(proven.result.x), std::move(proven.result.y), problem);
      r.best_xTy = Q(0);
    } else if (proven.result.status == UcpStatus::kJammed) {
      // As complete_search names it (a repair may have grown a root leaf into a tree).
      if (proven.leaves.repaired > 0) r.reason = jammed_reason(proven.result.tree);
      proven.result.reason = r.reason;
      r.nodes = proven.result.nodes;
      r.proof = std::move(proven.result);
    } else {
      return false;
    }
  } else {
    return false;
  }
  r.lps += check.lps;
  rep = std::move(r);
  return true;
}

/// Calls f(u, factors) with the problem's instance in the number type of a float rung (double, intervals, or
/// MPFR at the rung's precision, inside its MpfrPrecision scope), made from its integer rows, rows equilibrated.
template <class F>
auto with_float_instance(const UcpProblem& problem, const exact::Rung& rung, F&& f) {
  const auto in = [&](auto u) {
    const RowFactors factors = equilibrate(u);
    return f(u, factors);
  };
  switch (rung.kind) {
    case exact::Rung::Kind::kInterval:
      return in(convert<exact::Interval>(
          problem.rows(), [](const exact::Z& z) { return exact::to_interval(z); },
          [](const Q& q) { return exact::to_interval(q); }));
    case exact::Rung::Kind::kMpfr: {
      const exact::MpfrPrecision precision(rung.bits);  // constants and sign tests at the rung's precision
      return in(convert<exact::Mpfr>(
          problem.rows(), [&rung](const exact::Z& z) { return exact::to_mpfr(z, rung.bits); },
          [&rung](const Q& q) { return exact::to_mpfr(q, rung.bits); }));
    }
    case exact::Rung::Kind::kDouble:
    case exact::Rung::Kind::kExact:
      break;
  }
  return in(to_double(problem.rows()));
}

/// --arith adaptive: the rungs of exact::adaptive_ladder() in order; --arith verified: double, then exact (the float
/// path's search, checked; the exact search, with every LP verified, only if its verdict does not check out). The
/// first float rung whose verdict checks out decides, else the exact rung (rational search, its LPs on the LP
/// ladder or verified) does.
void solve_on_ladder(const UcpProblem& problem, const UcpOptions& opts, const exact::Deadline& deadline,
                     UcpReport& rep) {
  static const std::vector<exact::Rung> verified_ladder = {{exact::Rung::Kind::kDouble}, {exact::Rung::Kind::kExact}};
  const bool adaptive = opts.arith == Arith::kAdaptive;
  for (const exact::Rung& rung : adaptive ? exact::adaptive_ladder() : verified_ladder) {
    bool decided = true;
    if (rung.kind == exact::Rung::Kind::kExact)
      run<Q>(problem, problem.ucp(), opts, deadline, rep);
    else
      decided = with_float_instance(problem, rung, [&](const auto& u, const RowFactors& factors) {
        return decide_at(problem, u, factors, opts, deadline, rep);
      });
    if (decided) {
      if (adaptive) rep.decided_by = exact::rung_name(rung);
      return;
    }
  }
}

/// --arith float: the method unchecked in the number type of opts.float_rung (an uncertain interval sign: unknown).
void run_float(const UcpProblem& problem, const UcpOptions& opts, const exact::Deadline& deadline, UcpReport& rep) {
  try {
    with_float_instance(problem, opts.float_rung,
                        [&](const auto& u, const RowFactors&) { run(problem, u, opts, deadline, rep); });
  } catch (const exact::UncertainSign&) {
    rep.status = UcpStatus::kUnknown;
    rep.reason = "an interval sign is uncertain";
    rep.limited = false;
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
  const double cpu_start = thread_cpu_seconds();
  const exact::Deadline deadline = exact::Deadline::after(opts.time_limit);
  UcpReport rep;
  rep.method = opts.method;
  rep.arith = opts.arith;
  if (opts.method == Method::kEnumerate) {
    const Arith a = opts.arith == Arith::kFloat ? Arith::kVerified : opts.arith;  // the baseline is exact
    rep.arith = a;
    EnumerateResult e = enumerate_modes(problem, a, opts.max_enumerate_lps, deadline, opts.progress);
    rep.status = e.status;
    rep.limited = e.status == UcpStatus::kUnknown;  // the time limit before all modes were tested
    rep.lps = e.lps;
    rep.solutions = e.solutions;
    rep.solution_modes = e.solution_modes;
    if (e.lps == 0 && e.complete)
      rep.reason = "too many modes for the enumeration budget";
    else
      rep.reason = std::to_string(e.solutions) + " of " + std::to_string(e.lps) + " modes have a solution" +
                   (e.complete ? "" : " (" + deadline.reached_text() + " before all modes were tested)");
    if (e.solutions > 0) fill_pair(rep, std::move(e.x), std::move(e.y), problem);
  } else if (opts.arith == Arith::kFloat) {
    run_float(problem, opts, deadline, rep);
  } else if (opts.arith == Arith::kAdaptive || opts.arith == Arith::kVerified) {
    solve_on_ladder(problem, opts, deadline, rep);
  } else {
    run<Q>(problem, problem.ucp(), opts, deadline, rep);
  }
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rep.phases.solve = std::max(0.0, thread_cpu_seconds() - cpu_start - rep.phases.recover - rep.phases.check);
  return rep;
}

std::string certificate_text(const UcpProblem& problem, const UcpReport& r, const std::string& assembly_text) {
  if (r.status == UcpStatus::kJammed && r.proof) return jammed_certificate(problem, *r.proof, assembly_text);
  if (r.status == UcpStatus::kSolvable && r.x)
    return solvable_certificate(problem, r.x->to_q(), r.y->to_q(), assembly_text);
  return "";
}

}  // namespace contactcert::solvers::ucp
