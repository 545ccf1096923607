#include "exact/bareiss.h"

#include <boost/container/small_vector.hpp>
#include <numeric>
#include <utility>

namespace contactcert::exact {

namespace {

using Index = Eigen::Index;
using ring::divexact;
using ring::gcd;
using ring::mul;
using ring::sign;
using ring::sub;

}  // namespace

template <class R>
SolutionKind unique_solution(R* M, Index m, Index k, R* N, R& d) {
  const Index w = k + 1;
  if (k > m) return SolutionKind::kRankDeficient;
  auto at = [&](Index i, Index j) -> R& { return M[i * w + j]; };
  // Columns of A_S divided by their contents g_c (x_c = x'_c / g_c), then rows of [A_S | b] by theirs: the
  // minors below shrink by those factors (X's rows from the left null space of P share large ones).
  // g (zeros, as the gcds below start from): on the stack for the small systems of the UCP's pairs (a heap
  // allocation costs as much as their elimination).
  boost::container::small_vector<R, 16> g(static_cast<std::size_t>(k));
  for (Index c = 0; c < k; ++c) {
    R& gc = g[static_cast<std::size_t>(c)];
    for (Index i = 0; i < m && !(gc == R(1)); ++i)
      if (sign(at(i, c)) != 0) gc = gcd(gc, at(i, c));
    if (sign(gc) == 0) return SolutionKind::kRankDeficient;  // a zero column
    if (gc == R(1)) continue;
    for (Index i = 0; i < m; ++i) at(i, c) = divexact(at(i, c), gc);
  }
  for (Index i = 0; i < m; ++i) {
    R gi(0);
    for (Index j = 0; j < w && !(gi == R(1)); ++j)
      if (sign(at(i, j)) != 0) gi = gcd(gi, at(i, j));
    if (gi > R(1))
      for (Index j = 0; j < w; ++j) at(i, j) = divexact(at(i, j), gi);
  }
  // Fraction-free Gauss-Jordan (Bareiss applied above the pivot too): after step c every entry of the
  // eliminated rows is a (c+1) x (c+1) minor of M, so the division by the previous pivot is exact and no
  // intermediate exceeds a product of two minors (back substitution would multiply a k x k minor by another).
  R prev(1);
  for (Index c = 0; c < k; ++c) {
    Index p = c;
    while (p < m && sign(at(p, c)) == 0) ++p;
    if (p == m) return SolutionKind::kRankDeficient;
    if (p != c)
      for (Index j = c; j < w; ++j) std::swap(at(p, j), at(c, j));
    for (Index i = 0; i < m; ++i) {
      if (i == c) continue;
      if (i < c) at(i, i) = at(c, c);  // (a_cc a_ii - a_ic a_ci) / prev with a_ci = 0, a_ii = prev
      for (Index j = c + 1; j < w; ++j)
        at(i, j) = divexact(sub(mul(at(c, c), at(i, j)), mul(at(i, c), at(c, j))), prev);
      at(i, c) = 0;
    }
    prev = at(c, c);
  }
  for (Index i = k; i < m; ++i)
    if (sign(at(i, k)) != 0) return SolutionKind::kInconsistent;
  // Now M = [prev I | prev x'_S] on its first k rows (Cramer's rule) and x_c = x'_c / g_c: over the common
  // denominator d = prev G, G = lcm(g), N_c = at(c, k) G / g_c.
  R G(1);
  for (const R& gc : g) G = mul(divexact(G, gcd(G, gc)), gc);
  for (Index c = 0; c < k; ++c) N[c] = mul(at(c, k), divexact(G, g[static_cast<std::size_t>(c)]));
  d = mul(prev, G);
  if (sign(d) < 0) {  // the same solution over a positive denominator
    d = sub(R(0), d);
    for (Index c = 0; c < k; ++c) N[c] = sub(R(0), N[c]);
  }
  return SolutionKind::kUnique;
}

namespace {

std::vector<Index> all_columns(Index n) {
  std::vector<Index> all(static_cast<std::size_t>(n));
  std::iota(all.begin(), all.end(), Index(0));
  return all;
}

}  // namespace

template <class R>
std::optional<Vec<Q>> unique_solution(const IntegerSystem<R>& s) {
  return unique_solution(s, all_columns(s.n));
}

template <class R>
std::optional<Vec<Q>> unique_solution(const IntegerSystem<R>& s, const std::vector<Index>& columns) {
  const auto k = static_cast<Index>(columns.size()), w = k + 1;
  // M = [A_S | b], row-major m x (k + 1).
  std::vector<R> M(static_cast<std::size_t>(s.m * w)), N(static_cast<std::size_t>(k));
  for (Index i = 0; i < s.m; ++i) {
    for (Index c = 0; c < k; ++c)
      M[static_cast<std::size_t>(i * w + c)] =
          s.A[static_cast<std::size_t>(i * s.n + columns[static_cast<std::size_t>(c)])];
    M[static_cast<std::size_t>(i * w + k)] = s.b[static_cast<std::size_t>(i)];
  }
  R d;
  if (unique_solution(M.data(), s.m, k, N.data(), d) != SolutionKind::kUnique) return std::nullopt;
  Vec<Q> x(k);
  for (Index i = 0; i < k; ++i) ring::to_rational(N[static_cast<std::size_t>(i)], d, x(i));
  return x;
}

#define CONTACTCERT_BAREISS_INSTANTIATE(R)                                                               \
  template SolutionKind unique_solution<R>(R*, Index, Index, R*, R&);                                    \
  template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&, const std::vector<Index>&); \
  template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&);
CONTACTCERT_BAREISS_INSTANTIATE(Int128)
CONTACTCERT_BAREISS_INSTANTIATE(Z)
#undef CONTACTCERT_BAREISS_INSTANTIATE

}  // namespace contactcert::exact
