#include "exact/integer_system.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace contactcert::exact {

using Index = Eigen::Index;

LpProblem<double> IntegerLp::to_double(const std::vector<bool>& is_free) const {
  return convert<double>(is_free, [](std::int64_t v) { return static_cast<double>(v); });
}

namespace {

/// The rows of A in the ring S (std::int64_t: throws RingOverflow if a number does not fit; Z): row i over its least
/// common denominator den[i], its non-zero entries.
template <class S>
void integer_rows(const Mat<Q>& A, SparseIntMatrix<S>& rows, std::vector<S>& den) {
  rows = SparseIntMatrix<S>(A.cols());
  den.resize(static_cast<std::size_t>(A.rows()));
  std::vector<S> row(static_cast<std::size_t>(A.cols()));
  for (Index i = 0; i < A.rows(); ++i) {
    den[static_cast<std::size_t>(i)] = ring::to_common_denominator<S>(
        A.cols(), [&](Index j) -> const Q& { return A(i, j); }, row.data());
    rows.add_row();
    for (Index j = 0; j < A.cols(); ++j)
      if (ring::sign(row[static_cast<std::size_t>(j)]) != 0) rows.push(j, std::move(row[static_cast<std::size_t>(j)]));
  }
}

/// The one scaling, from integer rows in S to R: row i of [A | b] is [A[i] | L_b b_i] / den_i over den_i and L_b the
/// denominator of b_i: over L = lcm(den_i, L_b), A[i] (L / den_i) and num(b_i) (L / L_b), as
/// ring::to_common_denominator makes the rational row.
template <class R, class S>
IntegerSystem<R> scaled(const SparseIntMatrix<S>& A, const std::vector<S>& den_of, const Vec<Q>& b) {
  IntegerSystem<R> s;
  s.A = IntMatrix<R>(A.rows(), A.cols());
  s.b.resize(static_cast<std::size_t>(A.rows()));
  s.row_scale.resize(static_cast<std::size_t>(A.rows()));
  R den, den_b, f;
  for (Index i = 0; i < A.rows(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    ring::from_integer(den_of[k], den);
    ring::from_integer(b(i).get_den(), den_b);
    R& L = s.row_scale[k];
    L = ring::lcm(den, den_b);
    f = ring::divexact(L, den);
    for (Index t = A.begin(i); t < A.end(i); ++t) {
      R& a = s.A(i, A.col(t));
      ring::from_integer(A.value(t), a);
      if (f != 1) a = ring::mul(a, f);
    }
    ring::from_integer(b(i).get_num(), s.b[k]);
    if (L != den_b) s.b[k] = ring::mul(s.b[k], ring::divexact(L, den_b));
  }
  return s;
}

}  // namespace

RationalRows rational_rows(const Mat<Q>& A, const Vec<Q>& b) {
  RationalRows P{{}, {}, b};
  integer_rows<Z>(A, P.A, P.den);
  return P;
}

template <class R>
IntegerSystem<R> integer_system(const RationalRows& P) {
  return scaled<R>(P.A, P.den, P.b);
}

// The LP's rows in 64 bits from the start (no GMP integer on the way: the verified LP builds one per LP).
std::optional<IntegerLp> integer_lp(const LpProblem<Q>& problem) {
  IntegerLp out;
  const Index n = problem.cols();
  out.c.assign(static_cast<size_t>(n), 0);
  try {
    SparseIntMatrix<std::int64_t> rows;
    std::vector<std::int64_t> den;
    integer_rows(problem.A, rows, den);
    static_cast<IntegerSystem<std::int64_t>&>(out) = scaled<std::int64_t>(rows, den, problem.b);
    if (problem.c.size() > 0)
      out.objective_scale = ring::to_common_denominator<std::int64_t>(
          n, [&](Index j) -> const Q& { return problem.c(j); }, out.c.data());
  } catch (const RingOverflow&) {
    return std::nullopt;
  }
  return out;
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
  template IntegerSystem<R> integer_system<R>(const RationalRows&);                                      \
  template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&, const std::vector<Index>&); \
  template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&);
template IntegerSystem<std::int64_t> integer_system<std::int64_t>(const RationalRows&);
CONTACTCERT_INTEGER_SYSTEM_INSTANTIATE(Int128)
CONTACTCERT_INTEGER_SYSTEM_INSTANTIATE(Z)
#undef CONTACTCERT_INTEGER_SYSTEM_INSTANTIATE

}  // namespace contactcert::exact
