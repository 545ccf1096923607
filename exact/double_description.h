// The double description method (Motzkin et al.; the Fukuda-Prodon variant with the combinatorial adjacency
// test), the one engine of every cone conversion: the generators of { y : A y <= 0, E y = 0 } for integer
// rows (or float rows) in a ring of exact/fraction_free.h. The iteration starts from the whole space (lines
// only) and removes a line per independent row, so equalities, lineality and a lower dimension are found
// exactly on the way, in the original coordinates. Used by geometry/double_description.h (span and face
// forms of cones) and by the tangent cone of adjacent_vertices.h (tangent_cone.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "exact/deadline.h"
#include "exact/input_error.h"
#include "exact/int_matrix.h"
#include "exact/number.h"

namespace contactcert::exact {

/// The order in which the double description adds the inequality rows that leave the lineality space
/// as it is (cddlib's and PPL's options). Every order gives the same cone and the same rays; only the
/// intermediate ray counts, so the work, differ.
enum class RowOrder {
  kLexMin,     ///< lexicographically increasing primitive rows
  kLexMax,     ///< lexicographically decreasing
  kMinCutoff,  ///< next the row that cuts off the fewest current rays (ties: the lexicographically least)
  kMaxCutoff,  ///< next the row that cuts off the most current rays (ties: the lexicographically least)
};

/// Work limits of one conversion, checked inside the iteration where rays and work grow; exceeding
/// one throws exact::BudgetExceeded (exit 3), saying how many rows were processed. Also the row order.
struct DdBudget {
  /// The largest number of rays held at once (the current ones and those a step creates).
  std::size_t max_rays = 2'000'000;
  /// The largest adjacency work: candidate (plus, minus) pairs tested plus rays scanned by the
  /// combinatorial test, summed over the run (some 10^8 per second: 2^33 is about half a minute).
  std::uint64_t max_work = std::uint64_t{1} << 33;
  /// Wall clock (--time-limit).
  Deadline deadline;
  /// The insertion order of the rows.
  RowOrder order = RowOrder::kLexMin;
};

/// The adjacency work of a conversion against DdBudget::max_work and its deadline, checked every 2^20
/// units; `covered()` says how far the run got when a limit is hit.
class WorkMeter {
 public:
  explicit WorkMeter(const DdBudget& budget) : budget_(budget) {}
  template <class Covered>
  void charge(std::uint64_t units, Covered covered) {
    work_ += units;
    if (work_ < next_check_) return;
    next_check_ = work_ + (std::uint64_t{1} << 20);
    if (work_ > budget_.max_work)
      throw BudgetExceeded(
          "double description: more than " + std::to_string(budget_.max_work) + " units of adjacency work", covered());
    if (budget_.deadline.expired())
      throw BudgetExceeded("double description: " + budget_.deadline.reached_text(), covered());
  }

 private:
  const DdBudget& budget_;
  std::uint64_t work_ = 0, next_check_ = 0;
};

/// Extreme rays (one per ray modulo the lineality space) and a basis of the lineality space of a cone,
/// as the rows of integer matrices (int_matrix.h) in a ring R of exact/fraction_free.h (std::int64_t, Z or
/// a float type): primitive integers (unit max-norm in double).
template <class R>
struct RingGenerators {
  IntMatrix<R> rays;
  IntMatrix<R> lines;
};

/// The generators of { y in R^k : a . y <= 0 for every row a of A, e . y = 0 for every row e of E } for
/// rows in R (k = A's columns; E has k columns or no rows), by one double description run in R (no change
/// of coordinates, no rationals). The rows are sorted and deduplicated first; in R^3 without equalities the
/// rays come from pairs of rows instead. std::int64_t throws RingOverflow.
template <class R>
RingGenerators<R> cone_generators(IntMatrix<R> A, IntMatrix<R> E, const DdBudget& budget = {});

/// The extreme rays of { y in R^k : a . y <= 0 for every row a } (k = the rows' columns; cone_generators
/// without equalities); nullopt when the rows have rank < k (the cone is not pointed).
template <class R>
std::optional<IntMatrix<R>> pointed_cone_rays(IntMatrix<R> rows, const DdBudget& budget = {});

/// The extreme rays of { y in R^k : y >= 0, a . y <= 0 for every row a of A } (k = A's columns): the double
/// description started from the orthant's rays e_1, ..., e_k, the rows added in the order given (not sorted;
/// budget.order is not used), so that the rays come in the order of that iteration. std::int64_t throws
/// RingOverflow.
template <class R>
IntMatrix<R> orthant_rays(const IntMatrix<R>& A, const DdBudget& budget = {});

/// The rows without zero rows and duplicates, in lexicographic order (the fixed processing order of
/// cone_generators).
template <class R>
void sort_rows(IntMatrix<R>& rows);

#define CONTACTCERT_DD_RING_EXTERN(R)                                                                \
  extern template RingGenerators<R> cone_generators<R>(IntMatrix<R>, IntMatrix<R>, const DdBudget&); \
  extern template std::optional<IntMatrix<R>> pointed_cone_rays<R>(IntMatrix<R>, const DdBudget&);   \
  extern template void sort_rows<R>(IntMatrix<R>&);                                                  \
  extern template IntMatrix<R> orthant_rays<R>(const IntMatrix<R>&, const DdBudget&);
CONTACTCERT_DD_RING_EXTERN(double)
CONTACTCERT_DD_RING_EXTERN(std::int64_t)
CONTACTCERT_DD_RING_EXTERN(Z)

}  // namespace contactcert::exact
