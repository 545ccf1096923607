// A run stopped before an answer: by one of its budgets (time, nodes, modes, rays, placements), or on the float
// path by rounded numbers that contradict themselves. Every run_* returns its answer or its Limit (Limited<A>):
// what ran out and what the run covered until then. The CLI prints it and exits 3 (cli/command.h report_limit);
// Python raises contactcert.BudgetExceeded with its text (python/bindings.h answer).
//
// The solvers stop a deep computation by throwing exact::BudgetExceeded; with_limits, around a query's work, is the
// one place that turns it (and the float path's contradiction) into a Limit.
#pragma once

#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "exact/arith.h"
#include "exact/input_error.h"

namespace contactcert::queries {

struct Limit {
  enum class Kind {
    kBudget,     ///< a budget inside a computation (exact::BudgetExceeded): "budget exceeded: WHAT (covered: ...)"
    kStopped,    ///< the query's own loop stopped between units of work; WHAT names the command and its file
    kUndecided,  ///< the float path's rounded numbers contradict themselves; WHAT says how (nothing covered)
  };
  std::string what;     ///< e.g. "design scene.json: time limit of 10 s reached"
  std::string covered;  ///< e.g. "12 of 120 placements in 12 of 120 chunks"
  Kind kind = Kind::kBudget;
  /// "WHAT (covered: COVERED)".
  std::string text() const { return what + " (covered: " + covered + ")"; }
};

/// A query's answer, or the Limit that stopped it first.
template <class A>
class Limited {
 public:
  // Implicit: a query's work returns its answer or its Limit as it would return either alone.
  Limited(A answer) : v_(std::move(answer)) {}
  Limited(Limit limit) : v_(std::move(limit)) {}
  /// An answer (no limit).
  explicit operator bool() const { return v_.index() == 0; }
  const A& operator*() const& { return std::get<0>(v_); }
  A&& operator*() && { return std::get<0>(std::move(v_)); }
  const A* operator->() const { return &std::get<0>(v_); }
  const Limit& limit() const { return std::get<1>(v_); }

 private:
  std::variant<A, Limit> v_;
};

/// Limited<A> for a work returning A, and for one returning Limited<A> (a limit of its own).
template <class T>
struct LimitedOf {
  using type = Limited<T>;
};
template <class A>
struct LimitedOf<Limited<A>> {
  using type = Limited<A>;
};

/// `work()` (a query's orchestration) as Limited: exact::BudgetExceeded thrown inside becomes a kBudget Limit and,
/// with `arith` float, a std::logic_error a kUndecided one (the rounded numbers broke a promise of the algorithm,
/// e.g. the double description finds the rank it was given lacking: no answer in floating point, not a bug).
template <class F>
auto with_limits(exact::Arith arith, F&& work) -> typename LimitedOf<std::invoke_result_t<F>>::type {
  try {
    return std::forward<F>(work)();
  } catch (const exact::BudgetExceeded& e) {
    return Limit{e.what(), e.covered, Limit::Kind::kBudget};
  } catch (const std::logic_error& e) {
    if (arith != exact::Arith::kFloat) throw;
    return Limit{std::string("the float computation is inconsistent after rounding (") + e.what() + ")", "",
                 Limit::Kind::kUndecided};
  }
}

}  // namespace contactcert::queries
