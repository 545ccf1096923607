#include "exact/integer_system.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace contactcert::exact {

namespace {

using Index = Eigen::Index;

/// The rows of [A_S | b] for the columns S = column(0 .. n-1) of A in the ring R, each multiplied by the lcm
/// of its denominators (throws RingOverflow if a number does not fit R).
template <class R, class Column>
void scale_rows(const Mat<Q>& A, const Vec<Q>& b, Index n, Column column, IntegerSystem<R>& s) {
  const Index m = A.rows();
  s.A = IntMatrix<R>(m, n);
  s.b.resize(static_cast<std::size_t>(m));
  s.row_scale.resize(static_cast<std::size_t>(m));
  std::vector<R> row(static_cast<std::size_t>(n + 1));
  for (Index i = 0; i < m; ++i) {
    s.row_scale[static_cast<std::size_t>(i)] = ring::to_common_denominator<R>(
        n + 1, [&](Index j) -> const Q& { return j < n ? A(i, column(j)) : b(i); }, row.data());
    std::move(row.begin(), row.begin() + n, s.A.row(i));
    s.b[static_cast<std::size_t>(i)] = std::move(row[static_cast<std::size_t>(n)]);
  }
}

}  // namespace

LpProblem<double> IntegerLp::to_double(const std::vector<bool>& is_free) const {
  return convert<double>(is_free, [](std::int64_t v) { return static_cast<double>(v); });
}

std::optional<IntegerLp> integer_lp(const LpProblem<Q>& problem) {
  IntegerLp out;
  const Index n = problem.cols();
  out.c.assign(static_cast<size_t>(n), 0);
  try {
    scale_rows(
        problem.A, problem.b, n, [](Index j) { return j; }, out);
    if (problem.c.size() > 0)
      out.objective_scale = ring::to_common_denominator<std::int64_t>(
          n, [&](Index j) -> const Q& { return problem.c(j); }, out.c.data());
  } catch (const RingOverflow&) {
    return std::nullopt;
  }
  return out;
}

template <class R>
IntegerSystem<R> integer_system(const Mat<Q>& A, const Vec<Q>& b) {
  IntegerSystem<R> s;
  scale_rows(
      A, b, A.cols(), [](Index j) { return j; }, s);
  return s;
}

template <class R>
IntegerSystem<R> integer_system(const Mat<Q>& A, const Vec<Q>& b, const std::vector<Index>& columns) {
  IntegerSystem<R> s;
  scale_rows(
      A, b, static_cast<Index>(columns.size()), [&columns](Index j) { return columns[static_cast<std::size_t>(j)]; },
      s);
  return s;
}

template <class R>
std::optional<Vec<Q>> unique_solution(const IntegerSystem<R>& s, const std::vector<Index>& columns) {
  const auto k = static_cast<Index>(columns.size());
  IntMatrix<R> M(s.rows(), k + 1);  // [A_S | b]
  for (Index i = 0; i < s.rows(); ++i) {
    for (Index c = 0; c < k; ++c) M(i, c) = s.A(i, columns[static_cast<std::size_t>(c)]);
    M(i, k) = s.b[static_cast<std::size_t>(i)];
  }
  std::vector<R> N(static_cast<std::size_t>(k));
  R d;
  if (M.solve(N.data(), d) != SolutionKind::kUnique) return std::nullopt;
  Vec<Q> x(k);
  for (Index i = 0; i < k; ++i) ring::to_rational(N[static_cast<std::size_t>(i)], d, x(i));
  return x;
}

template <class R>
std::optional<Vec<Q>> unique_solution(const IntegerSystem<R>& s) {
  std::vector<Index> all(static_cast<std::size_t>(s.cols()));
  std::iota(all.begin(), all.end(), Index(0));
  return unique_solution(s, all);
}

#define CONTACTCERT_INTEGER_SYSTEM_INSTANTIATE(R)                                                        \
  template IntegerSystem<R> integer_system<R>(const Mat<Q>&, const Vec<Q>&);                             \
  template IntegerSystem<R> integer_system<R>(const Mat<Q>&, const Vec<Q>&, const std::vector<Index>&);  \
  template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&, const std::vector<Index>&); \
  template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&);
CONTACTCERT_INTEGER_SYSTEM_INSTANTIATE(Int128)
CONTACTCERT_INTEGER_SYSTEM_INSTANTIATE(Z)
#undef CONTACTCERT_INTEGER_SYSTEM_INSTANTIATE

}  // namespace contactcert::exact
