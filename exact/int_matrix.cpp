#include "exact/int_matrix.h"

#include <algorithm>
#include <type_traits>
#include <utility>

#include "exact/interval_number.h"
#include "exact/mpfr_number.h"
#include "exact/padic_solve.h"

namespace contactcert::exact {

namespace {

using Index = Eigen::Index;

/// A float ring (double, MPFR floats, intervals): not one of the exact integer rings.
template <class R>
constexpr bool is_float_ring = !(std::is_same_v<R, std::int64_t> || std::is_same_v<R, Int128> || std::is_same_v<R, Z>);

/// Divides v[0..k) by the positive gcd of its entries (all zero: unchanged); a float ring: ring::normalize. Z: also
/// ring::normalize (the same division, in place, without a GMP temporary per entry).
template <class R>
void make_row_primitive(R* v, Index k) {
  if constexpr (is_float_ring<R> || std::is_same_v<R, Z>) {
    ring::normalize(v, k);
  } else {
    R g(0);
    for (Index i = 0; i < k && !(g == R(1)); ++i)
      if (ring::sign(v[i]) != 0) g = ring::gcd(g, v[i]);
    if (ring::sign(g) == 0 || g == R(1)) return;
    for (Index i = 0; i < k; ++i) v[i] = ring::divexact(v[i], g);
  }
}

/// row <- a row - f pivot_row over w entries with a / f = pivot_row[c] / row[c], so that row[c] = 0; then primitive.
/// The exact rings divide a and f by their gcd first (smaller products, the same primitive row).
template <class R>
void eliminate(const R* pivot_row, R* row, Index c, Index w, std::vector<R>& tmp) {
  if constexpr (is_float_ring<R>) {
    ring::combine(pivot_row, pivot_row[c], row, row[c], tmp.data(), w);
    std::copy(tmp.begin(), tmp.end(), row);
  } else {
    const R g = ring::gcd(pivot_row[c], row[c]);
    const R a = ring::divexact(pivot_row[c], g), f = ring::divexact(row[c], g);
    for (Index j = 0; j < w; ++j) ring::mul_sub(a, row[j], f, pivot_row[j], row[j]);
  }
  row[c] = R(0);
  make_row_primitive(row, w);
}

/// Pivot choice: the first non-zero entry in an exact ring, the float ring's choice (the largest) otherwise.
template <class R>
bool better_pivot(const R& candidate, const R& best) {
  if constexpr (is_float_ring<R>)
    return ring::better_pivot(candidate, best);
  else
    return false;
}

template <class R>
R magnitude(const R& x) {
  return ring::sign(x) < 0 ? ring::sub(R(0), x) : x;
}

}  // namespace

template <class R>
void IntMatrix<R>::make_primitive() {
  for (Index i = 0; i < rows_; ++i) make_row_primitive(row(i), cols_);
}

template <class R>
std::vector<Index> IntMatrix<R>::echelon(Index top, Index first, Index last) {
  if (last < 0) last = cols_;
  std::vector<Index> pivots;
  std::vector<R> tmp(static_cast<std::size_t>(is_float_ring<R> ? cols_ : 0));
  for (Index c = first, r = top; c < last && r < rows_; ++c) {
    Index p = -1;
    for (Index i = r; i < rows_; ++i)
      if (ring::sign((*this)(i, c)) != 0 && (p < 0 || better_pivot((*this)(i, c), (*this)(p, c)))) p = i;
    if (p < 0) continue;
    if (p != r) swap_rows(p, r);
    for (Index i = top; i < rows_; ++i)
      if (i != r && ring::sign((*this)(i, c)) != 0) eliminate(row(r), row(i), c, cols_, tmp);
    pivots.push_back(c);
    ++r;
  }
  return pivots;
}

template <class R>
Index IntMatrix<R>::rank() const {
  IntMatrix copy = *this;
  return static_cast<Index>(copy.echelon().size());
}

template <class R>
IntMatrix<R> IntMatrix<R>::kernel() const {
  IntMatrix E = *this;
  const std::vector<Index> pivots = E.echelon();
  std::vector<bool> is_pivot(static_cast<std::size_t>(cols_), false);
  for (Index c : pivots) is_pivot[static_cast<std::size_t>(c)] = true;
  IntMatrix K(cols_ - static_cast<Index>(pivots.size()), cols_);
  Index k = 0;
  for (Index f = 0; f < cols_; ++f) {
    if (is_pivot[static_cast<std::size_t>(f)]) continue;
    // Reduced row echelon form gives x_f = 1, x_pivot(r) = -E_rf / E_r,pivot(r); here times the lcm L of the pivots
    // that divide.
    R L(1);
    for (std::size_t r = 0; r < pivots.size(); ++r)
      if (ring::sign(E(static_cast<Index>(r), f)) != 0)
        L = ring::lcm(L, magnitude(E(static_cast<Index>(r), pivots[r])));
    K(k, f) = L;
    for (std::size_t r = 0; r < pivots.size(); ++r) {
      const R& e = E(static_cast<Index>(r), f);
      if (ring::sign(e) != 0)
        K(k, pivots[r]) = ring::sub(R(0), ring::mul(e, ring::divexact(L, E(static_cast<Index>(r), pivots[r]))));
    }
    make_row_primitive(K.row(k), cols_);
    ++k;
  }
  return K;
}

template <class R>
SolutionKind IntMatrix<R>::solve(R* N, R& d) {
  using ring::divexact;
  using ring::gcd;
  using ring::mul;
  using ring::sign;
  using ring::sub;
  const Index m = rows_, w = cols_, k = w - 1;
  if (k > m) return SolutionKind::kRankDeficient;
  IntMatrix& at = *this;
  // Columns of A divided by their contents g_c (x_c = x'_c / g_c), then rows of [A | b] by theirs: the minors below
  // shrink by those factors (X's rows from the left null space of P share large ones). g (zeros, as the gcds below
  // start from): on the stack for the small systems of the UCP's pairs (a heap allocation costs as much as their
  // elimination). Column contents only in the fixed-width rings, where they keep the products within their bits (the
  // vertex of Data Set 1 solves in Int128 thanks to them); in Z their gcds cost more than the smaller minors save (the
  // motion step's recoveries, 3 x 4 systems of ~200-bit entries: 8.1 M -> 5.0 M instructions per 200 steps).
  constexpr bool column_contents = !std::is_same_v<R, Z>;
  boost::container::small_vector<R, 16> g(static_cast<std::size_t>(column_contents ? k : 0));
  const R one(1);
  for (Index c = 0; c < k && column_contents; ++c) {
    R& gc = g[static_cast<std::size_t>(c)];
    for (Index i = 0; i < m && !(gc == one); ++i)
      if (sign(at(i, c)) != 0) gc = gcd(gc, at(i, c));
    if (sign(gc) == 0) return SolutionKind::kRankDeficient;  // a zero column
    if (gc == one) continue;
    for (Index i = 0; i < m; ++i) ring::divexact_by(at(i, c), gc);
  }
  make_primitive();
  // Fraction-free Gauss-Jordan (Bareiss applied above the pivot too): after step c every entry of the eliminated
  // rows is a (c+1) x (c+1) minor of M, so the division by the previous pivot is exact and no intermediate exceeds a
  // product of two minors (back substitution would multiply a k x k minor by another).
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
      for (Index j = c + 1; j < w; ++j) {
        ring::mul_sub(at(c, c), at(i, j), at(i, c), at(c, j), at(i, j));
        if (c > 0) ring::divexact_by(at(i, j), prev);  // prev = 1 at the first pivot
      }
      at(i, c) = 0;
    }
    prev = at(c, c);
  }
  for (Index i = k; i < m; ++i)
    if (sign(at(i, k)) != 0) return SolutionKind::kInconsistent;
  // Now M = [prev I | prev x'] on its first k rows (Cramer's rule) and x_c = x'_c / g_c: over the common denominator
  // d = prev G, G = lcm(g), N_c = at(c, k) G / g_c (in Z: d = prev, N_c = at(c, k)).
  R G(1);
  if constexpr (column_contents)
    for (const R& gc : g) G = mul(divexact(G, gcd(G, gc)), gc);
  for (Index c = 0; c < k; ++c)
    N[c] = column_contents ? mul(at(c, k), divexact(G, g[static_cast<std::size_t>(c)])) : std::move(at(c, k));
  d = column_contents ? mul(prev, G) : std::move(prev);
  if (sign(d) < 0) {  // the same solution over a positive denominator
    d = sub(R(0), d);
    for (Index c = 0; c < k; ++c) N[c] = sub(R(0), N[c]);
  }
  return SolutionKind::kUnique;
}

template <class R>
SolutionKind solve_sparse_square(const std::vector<SparseEquation<R>>& eqs, Index m, std::vector<R>& U, R& D,
                                 CoreSolve core) {
  using ring::mul;
  using ring::sign;
  using ring::sub;
  const std::size_t ne = eqs.size();
  std::vector<std::vector<std::size_t>> occurs(static_cast<std::size_t>(m));
  std::vector<std::size_t> open(ne), ready;
  for (std::size_t e = 0; e < ne; ++e) {
    open[e] = eqs[e].terms.size();
    for (const auto& [j, a] : eqs[e].terms) occurs[static_cast<std::size_t>(j)].push_back(e);
    if (open[e] == 1) ready.push_back(e);
  }
  std::vector<bool> known(static_cast<std::size_t>(m), false), used(ne, false);
  U.assign(static_cast<std::size_t>(m), R(0));
  D = R(1);
  // D (rhs - sum of the known terms of e): the right-hand side of e over D once its known unknowns are moved.
  const auto residual = [&](std::size_t e) {
    R t = mul(eqs[e].rhs, D);
    for (const auto& [j, a] : eqs[e].terms)
      if (known[static_cast<std::size_t>(j)]) t = sub(t, mul(a, U[static_cast<std::size_t>(j)]));
    return t;
  };
  while (!ready.empty()) {
    const std::size_t e = ready.back();
    ready.pop_back();
    if (used[e] || open[e] != 1) continue;
    const auto& [i, coef] = *std::find_if(eqs[e].terms.begin(), eqs[e].terms.end(),
                                          [&](const auto& t) { return !known[static_cast<std::size_t>(t.first)]; });
    // coef u_i = t / D: u_i = t / (coef D); with coef = g a, t = g t', a > 0: U_i = t' over the denominator D a.
    R t = residual(e);
    used[e] = true;
    known[static_cast<std::size_t>(i)] = true;
    if (sign(t) != 0) {
      const R g = ring::gcd(coef, t);
      R a = ring::divexact(coef, g);
      t = ring::divexact(t, g);
      if (sign(a) < 0) a = sub(R(0), a), t = sub(R(0), t);
      if (!(a == R(1))) {
        for (Index j = 0; j < m; ++j)
          if (known[static_cast<std::size_t>(j)])
            U[static_cast<std::size_t>(j)] = mul(U[static_cast<std::size_t>(j)], a);
        D = mul(D, a);
      }
      U[static_cast<std::size_t>(i)] = t;
    }
    for (std::size_t e2 : occurs[static_cast<std::size_t>(i)])
      if (!used[e2] && --open[e2] == 1) ready.push_back(e2);
  }
  // The core: the open unknowns (column c of M) and the unused equations (rows of M = [A_core | residual]).
  std::vector<Index> column(static_cast<std::size_t>(m), -1);
  Index k = 0;
  for (Index j = 0; j < m; ++j)
    if (!known[static_cast<std::size_t>(j)]) column[static_cast<std::size_t>(j)] = k++;
  if (k == 0) return SolutionKind::kUnique;  // every equation was used (as many as unknowns)
  Index rows = 0;
  for (std::size_t e = 0; e < ne; ++e) rows += used[e] ? 0 : 1;
  if (rows != k) return SolutionKind::kRankDeficient;
  IntMatrix<R> M(k, k + 1);
  Index r = 0;
  for (std::size_t e = 0; e < ne; ++e) {
    if (used[e]) continue;
    R* row = M.row(r++);
    for (const auto& [j, a] : eqs[e].terms)
      if (!known[static_cast<std::size_t>(j)]) row[column[static_cast<std::size_t>(j)]] = a;
    row[k] = residual(e);
  }
  std::vector<R> N(static_cast<std::size_t>(k));
  R d;
  bool lifted = false;
  if constexpr (std::is_same_v<R, Z>)
    if (core == CoreSolve::kLifted && k >= kLiftedCoreFrom)
      if (std::optional<LiftedSolution> s = padic_solve(M)) {
        N = std::move(s->U);
        d = std::move(s->D);
        lifted = true;
      }
  if (!lifted && M.solve(N.data(), d) != SolutionKind::kUnique) return SolutionKind::kRankDeficient;
  // D u = N / d on the core (d > 0): U d over the common denominator D d.
  for (Index j = 0; j < m; ++j) {
    R& u = U[static_cast<std::size_t>(j)];
    u = known[static_cast<std::size_t>(j)] ? mul(u, d)
                                           : N[static_cast<std::size_t>(column[static_cast<std::size_t>(j)])];
  }
  D = mul(D, d);
  return SolutionKind::kUnique;
}

template class IntMatrix<std::int64_t>;
template class IntMatrix<Int128>;
template class IntMatrix<Z>;
template class SparseIntMatrix<std::int64_t>;
template class SparseIntMatrix<Int128>;
template class SparseIntMatrix<Z>;
#define CONTACTCERT_SOLVE_SPARSE_INSTANTIATE(R)                                                                   \
  template SolutionKind solve_sparse_square<R>(const std::vector<SparseEquation<R>>&, Index, std::vector<R>&, R&, \
                                               CoreSolve);
CONTACTCERT_SOLVE_SPARSE_INSTANTIATE(std::int64_t)
CONTACTCERT_SOLVE_SPARSE_INSTANTIATE(Int128)
CONTACTCERT_SOLVE_SPARSE_INSTANTIATE(Z)
#undef CONTACTCERT_SOLVE_SPARSE_INSTANTIATE
#define CONTACTCERT_INT_MATRIX_FLOAT_INSTANTIATE(R) \
  template void IntMatrix<R>::make_primitive();     \
  template std::vector<Index> IntMatrix<R>::echelon(Index, Index, Index);
CONTACTCERT_INT_MATRIX_FLOAT_INSTANTIATE(double)
CONTACTCERT_INT_MATRIX_FLOAT_INSTANTIATE(Mpfr)
CONTACTCERT_INT_MATRIX_FLOAT_INSTANTIATE(Interval)
#undef CONTACTCERT_INT_MATRIX_FLOAT_INSTANTIATE

}  // namespace contactcert::exact
