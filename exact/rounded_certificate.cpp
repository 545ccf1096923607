#include "exact/rounded_certificate.h"

#include <algorithm>
#include <boost/container/small_vector.hpp>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

namespace contactcert::exact {

namespace {

using Index = Eigen::Index;
using i64 = std::int64_t;
using i128 = Int128;

/// Largest denominator tried when rounding a double to a fraction.
constexpr i64 kMaxDenominator = i64(1) << 30;

struct Fraction {
  i64 num, den;
};

/// The first continued-fraction convergent p/q of v with |v - p/q| <= 1e-9 max(1, |v|), q <= kMaxDenominator.
std::optional<Fraction> round_to_fraction(double v) {
  if (!std::isfinite(v) || std::abs(v) > 1e15) return std::nullopt;
  const double tol = 1e-9 * std::max(1.0, std::abs(v));
  i64 h0 = 0, h1 = 1, k0 = 1, k1 = 0;
  double x = v;
  for (int it = 0; it < 64; ++it) {
    const double a = std::floor(x);
    if (std::abs(a) > 1e15) return std::nullopt;
    const i64 ai = static_cast<i64>(a);
    i64 h2, k2, t;
    if (__builtin_mul_overflow(ai, h1, &t) || __builtin_add_overflow(t, h0, &h2)) return std::nullopt;
    if (__builtin_mul_overflow(ai, k1, &t) || __builtin_add_overflow(t, k0, &k2)) return std::nullopt;
    if (k2 > kMaxDenominator) return std::nullopt;
    h0 = h1, h1 = h2, k0 = k1, k1 = k2;
    if (std::abs(v - static_cast<double>(h1) / static_cast<double>(k1)) <= tol) return Fraction{h1, k1};
    const double frac = x - a;
    if (frac <= 0) return std::nullopt;
    x = 1 / frac;
  }
  return std::nullopt;
}

/// z as a 64-bit integer (reads GMP's limbs through the inline mpz_size / mpz_getlimbn: this runs once per
/// matrix entry).
bool to_i64(mpz_srcptr z, i64& out) {
  const std::size_t size = mpz_size(z);
  if (size == 0) {
    out = 0;
    return true;
  }
  if (size > 1 || mpz_getlimbn(z, 0) > static_cast<mp_limb_t>(INT64_MAX)) return false;
  const i64 v = static_cast<i64>(mpz_getlimbn(z, 0));
  out = mpz_sgn(z) > 0 ? v : -v;
  return true;
}

bool is_one(mpz_srcptr z) { return mpz_size(z) == 1 && mpz_getlimbn(z, 0) == 1; }

bool lcm_into(i64& acc, i64 d) {
  const i64 g = std::gcd(acc, d);
  return !__builtin_mul_overflow(acc / g, d, &acc);
}

/// Scales the rationals q(0..count-1) by the lcm of their denominators into integers: q = out / scale.
template <class Get>
bool integer_scale(Index count, Get q, i64* out, i64& scale) {
  scale = 1;
  for (Index i = 0; i < count; ++i) {
    mpz_srcptr den = mpq_denref(q(i).get_mpq_t());
    if (is_one(den)) continue;
    i64 d;
    if (!to_i64(den, d) || !lcm_into(scale, d)) return false;
  }
  for (Index i = 0; i < count; ++i) {
    i64 num, den;
    if (!to_i64(mpq_numref(q(i).get_mpq_t()), num) || !to_i64(mpq_denref(q(i).get_mpq_t()), den)) return false;
    if (scale == 1) {
      out[i] = num;
    } else if (__builtin_mul_overflow(num, scale / den, &out[i])) {
      return false;
    }
  }
  return true;
}

}  // namespace

bool round_vector(const std::vector<double>& v, std::vector<i64>& out, i64& scale) {
  std::vector<Fraction> f;
  f.reserve(v.size());
  scale = 1;
  for (double x : v) {
    const std::optional<Fraction> r = round_to_fraction(x);
    if (!r || !lcm_into(scale, r->den)) return false;
    f.push_back(*r);
  }
  out.resize(v.size());
  for (size_t i = 0; i < v.size(); ++i)
    if (__builtin_mul_overflow(f[i].num, scale / f[i].den, &out[i])) return false;
  return true;
}

namespace {

bool fma128(i128& acc, i64 a, i64 b) {
  return !__builtin_add_overflow(acc, static_cast<i128>(a) * static_cast<i128>(b), &acc);
}

}  // namespace

Q make_q(i64 num, i64 den) {
  Q q;
  if (num == 0) return q;
  const i64 g = std::gcd(num < 0 ? -num : num, den);
  mpq_set_si(q.get_mpq_t(), static_cast<long>(num / g), static_cast<unsigned long>(den / g));
  return q;
}

LpProblem<double> IntegerLp::to_double(const std::vector<bool>& is_free) const {
  return convert<double>(is_free, [](i64 v) { return static_cast<double>(v); });
}

std::optional<IntegerLp> integer_lp(const LpProblem<Q>& problem) {
  IntegerLp out;
  const Index m = problem.rows(), n = problem.cols();
  out.m = m;
  out.n = n;
  out.A.resize(static_cast<size_t>(m * n));
  out.b.resize(static_cast<size_t>(m));
  out.c.assign(static_cast<size_t>(n), 0);
  out.row_scale.resize(static_cast<size_t>(m));
  std::vector<i64> row(static_cast<size_t>(n + 1));
  for (Index i = 0; i < m; ++i) {
    auto get = [&](Index j) -> const Q& { return j < n ? problem.A(i, j) : problem.b(i); };
    if (!integer_scale(n + 1, get, row.data(), out.row_scale[static_cast<size_t>(i)])) return std::nullopt;
    std::copy(row.begin(), row.begin() + n, out.A.begin() + i * n);
    out.b[static_cast<size_t>(i)] = row[static_cast<size_t>(n)];
  }
  if (problem.c.size() > 0 &&
      !integer_scale(
          n, [&](Index j) -> const Q& { return problem.c(j); }, out.c.data(), out.objective_scale))
    return std::nullopt;
  return out;
}

std::optional<OptimalCertificate> round_and_check_optimal(const LpProblem<Q>& problem, const IntegerLp& ilp,
                                                          const std::vector<Index>& basis, const Vec<double>& x_approx,
                                                          const Vec<double>& y_approx) {
  const Index m = problem.rows(), n = problem.cols();
  const size_t k = basis.size();
  if (x_approx.size() != n || y_approx.size() != m || ilp.m != m || ilp.n != n) return std::nullopt;
  const std::vector<i64>& Aint = ilp.A;
  const std::vector<i64>& bint = ilp.b;
  const std::vector<i64>& cint = ilp.c;

  // x_B ~ X / D.
  std::vector<double> xb(k);
  for (size_t t = 0; t < k; ++t) {
    if (basis[t] < 0 || basis[t] >= n) return std::nullopt;
    xb[t] = x_approx(basis[t]);
  }
  std::vector<i64> X;
  i64 D;
  if (!round_vector(xb, X, D)) return std::nullopt;
  for (size_t t = 0; t < k; ++t)
    if (X[t] < 0 && !problem.free(basis[t])) return std::nullopt;
  // A_B X = D b, row by row in the integer rows.
  for (Index i = 0; i < m; ++i) {
    i128 acc = 0;
    for (size_t t = 0; t < k; ++t)
      if (!fma128(acc, Aint[static_cast<size_t>(i * n + basis[t])], X[t])) return std::nullopt;
    if (acc != static_cast<i128>(D) * bint[static_cast<size_t>(i)]) return std::nullopt;
  }

  // Duals of the integer LP ~ Y / E; those of the problem are y_i = row_scale_i Y_i / (E objective_scale).
  std::vector<double> yhat(y_approx.data(), y_approx.data() + m);
  std::vector<i64> Y;
  i64 E;
  if (!round_vector(yhat, Y, E)) return std::nullopt;
  // (Aint^T Y)_j <= E cint_j; equality on basic and free columns.
  std::vector<bool> in_basis(static_cast<size_t>(n), false);
  for (Index j : basis) in_basis[static_cast<size_t>(j)] = true;
  std::vector<i128> t(static_cast<size_t>(n), 0);
  for (Index i = 0; i < m; ++i) {
    const i64 yi = Y[static_cast<size_t>(i)];
    if (yi == 0) continue;
    for (Index j = 0; j < n; ++j)
      if (!fma128(t[static_cast<size_t>(j)], Aint[static_cast<size_t>(i * n + j)], yi)) return std::nullopt;
  }
  for (Index j = 0; j < n; ++j) {
    const i128 lhs = t[static_cast<size_t>(j)];
    const i128 rhs = static_cast<i128>(E) * cint[static_cast<size_t>(j)];
    const bool tight = in_basis[static_cast<size_t>(j)] || problem.free(j);
    if (tight ? lhs != rhs : lhs > rhs) return std::nullopt;
  }

  OptimalCertificate cert;
  cert.x = Vec<Q>::Zero(n);
  for (size_t s = 0; s < k; ++s) cert.x(basis[s]) = make_q(X[s], D);
  cert.y = Vec<Q>(m);
  for (Index i = 0; i < m; ++i) {
    cert.y(i) = make_q(Y[static_cast<size_t>(i)], E);
    const i64 L = ilp.row_scale[static_cast<size_t>(i)];
    if (L != 1 || ilp.objective_scale != 1) cert.y(i) *= make_q(L, ilp.objective_scale);
  }
  cert.value = 0;
  if (problem.c.size() > 0)
    for (Index j : basis) cert.value += problem.c(j) * cert.x(j);
  return cert;
}

namespace {

// The ring operations of the integer checks, for R = Int128 (every operation overflow-checked: throws
// RingOverflow) and R = Z: those of fraction_free.h.
using ring::add;
using ring::divexact;
using ring::gcd;
using ring::mul;
using ring::sign;
using ring::sub;
double to_double(Int128 v) { return static_cast<double>(v); }
double to_double(const Z& v) { return v.get_d(); }

/// v rounded entry by entry to fractions over their common denominator D: v ~ out / D. False if an entry has
/// no convergent with a denominator <= kMaxDenominator.
template <class R>
bool over_common_denominator(const std::vector<double>& v, std::vector<R>& out, R& D) {
  std::vector<Fraction> f;
  f.reserve(v.size());
  D = 1;
  for (double x : v) {
    const std::optional<Fraction> r = round_to_fraction(x);
    if (!r) return false;
    D = ring::lcm(D, R(r->den));
    f.push_back(*r);
  }
  out.resize(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[i] = mul(R(f[i].num), divexact(D, R(f[i].den)));
  return true;
}

}  // namespace

namespace {

/// The rows of [A_S | b] for the columns S = column(0 .. n-1) of A, each multiplied by the lcm of its
/// denominators.
template <class R, class Column>
IntegerSystem<R> scaled_rows(const Mat<Q>& A, const Vec<Q>& b, Index n, Column column) {
  IntegerSystem<R> s;
  s.m = A.rows(), s.n = n;
  s.A.resize(static_cast<std::size_t>(s.m * s.n));
  s.b.resize(static_cast<std::size_t>(s.m));
  s.row_scale.resize(static_cast<std::size_t>(s.m));
  std::vector<R> row(static_cast<std::size_t>(s.n + 1));
  for (Index i = 0; i < s.m; ++i) {
    s.row_scale[static_cast<std::size_t>(i)] = ring::to_common_denominator<R>(
        s.n + 1, [&](Index j) -> const Q& { return j < s.n ? A(i, column(j)) : b(i); }, row.data());
    std::move(row.begin(), row.begin() + s.n, s.A.begin() + i * s.n);
    s.b[static_cast<std::size_t>(i)] = std::move(row[static_cast<std::size_t>(s.n)]);
  }
  return s;
}

}  // namespace

template <class R>
IntegerSystem<R> integer_system(const Mat<Q>& A, const Vec<Q>& b) {
  return scaled_rows<R>(A, b, A.cols(), [](Index j) { return j; });
}

template <class R>
IntegerSystem<R> integer_system(const Mat<Q>& A, const Vec<Q>& b, const std::vector<Index>& columns) {
  return scaled_rows<R>(A, b, static_cast<Index>(columns.size()),
                        [&columns](Index j) { return columns[static_cast<std::size_t>(j)]; });
}

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

/// Y as a Farkas vector of the rows of s if it is one: Y^T b < 0 and Y^T A_j >= 0 unless j is in `zero`; the
/// result is y_i = row_scale_i Y_i (for the rows before scaling) with its negative columns.
template <class R>
std::optional<FarkasVector> checked_farkas(const IntegerSystem<R>& s, const std::vector<R>& Y,
                                           const std::vector<bool>& zero) {
  R acc(0);
  for (Index i = 0; i < s.m; ++i) acc = add(acc, mul(s.b[static_cast<std::size_t>(i)], Y[static_cast<std::size_t>(i)]));
  if (sign(acc) >= 0) return std::nullopt;
  FarkasVector f;
  for (Index j = 0; j < s.n; ++j) {  // column by column over the rows with Y_i != 0
    acc = 0;
    for (Index i = 0; i < s.m; ++i)
      if (sign(Y[static_cast<std::size_t>(i)]) != 0)
        acc = add(acc, mul(s.A[static_cast<std::size_t>(i * s.n + j)], Y[static_cast<std::size_t>(i)]));
    if (sign(acc) >= 0) continue;
    if (!zero[static_cast<std::size_t>(j)]) return std::nullopt;
    f.negative.push_back(j);
  }
  f.y = Vec<Q>(s.m);
  for (Index i = 0; i < s.m; ++i)
    f.y(i) = ring::to_field<Q>(mul(s.row_scale[static_cast<std::size_t>(i)], Y[static_cast<std::size_t>(i)]));
  return f;
}

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

template <class R>
std::optional<FarkasVector> basis_farkas(const IntegerSystem<R>& s, const Vec<double>& y_approx,
                                         const std::vector<Index>& basis, const std::vector<bool>& zero) {
  // Phase 1 ends with duals y, B^T y = c_B (cost 1 on artificials), and reports f = -y: f^T A_v = 0 for every
  // structural v of the basis, and f_i = -sign(b_i) w_i for the artificial n + i of row i, where w_i = 1, or
  // the power of two the float simplex scaled row i by. Those entries are taken from y_approx, rounded to
  // signed powers of two; in the rows of s (row i times L_i) they read L_i f'_i = f_i.
  const Index m = s.m;
  if (y_approx.size() != m) return std::nullopt;
  if (static_cast<Index>(basis.size()) != m) return std::nullopt;
  // M = [B^T-rows | rhs], row-major m x (m + 1): one equation per basis column, unknowns f'.
  const Index w = m + 1;
  std::vector<R> M(static_cast<std::size_t>(m * w), R(0)), F(static_cast<std::size_t>(m));
  for (Index r = 0; r < m; ++r) {
    R* row = &M[static_cast<std::size_t>(r * w)];
    const Index v = basis[static_cast<std::size_t>(r)];
    if (v < 0 || v >= s.n + m) return std::nullopt;
    if (v < s.n) {
      for (Index i = 0; i < m; ++i) row[i] = s.A[static_cast<std::size_t>(i * s.n + v)];
    } else {
      const Index i = v - s.n;
      const double f = y_approx(i);
      if (f == 0 || !std::isfinite(f)) return std::nullopt;
      const int e = static_cast<int>(std::lround(std::log2(std::abs(f))));  // |f_i| = 2^e
      if (e < -62 || e > 62) return std::nullopt;
      const R power(std::int64_t(1) << (e < 0 ? -e : e));
      const R& L = s.row_scale[static_cast<std::size_t>(i)];
      row[i] = e < 0 ? mul(L, power) : L;
      row[m] = e < 0 ? R(f < 0 ? -1 : 1) : (f < 0 ? sub(R(0), power) : power);
    }
  }
  R d;
  if (unique_solution(M.data(), m, m, F.data(), d) != SolutionKind::kUnique) return std::nullopt;
  return checked_farkas(s, F, zero);  // f' = F / d with d > 0: F is a positive multiple of f'
}

template <class R>
std::optional<Vec<Q>> rounded_point(const IntegerSystem<R>& s, const Vec<double>& x_approx,
                                    const std::vector<bool>& zero) {
  std::vector<Index> support;
  std::vector<double> xs;
  for (Index j = 0; j < s.n; ++j)
    if (!zero[static_cast<std::size_t>(j)]) support.push_back(j), xs.push_back(x_approx(j));
  std::vector<R> X;
  R D;
  if (!over_common_denominator(xs, X, D)) return std::nullopt;
  for (const R& v : X)
    if (sign(v) < 0) return std::nullopt;
  // A X = D b, row by row.
  for (Index i = 0; i < s.m; ++i) {
    R acc(0);
    for (std::size_t t = 0; t < support.size(); ++t)
      acc = add(acc, mul(s.A[static_cast<std::size_t>(i * s.n + support[t])], X[t]));
    if (acc != mul(D, s.b[static_cast<std::size_t>(i)])) return std::nullopt;
  }
  Vec<Q> x = Vec<Q>::Zero(s.n);
  for (std::size_t t = 0; t < support.size(); ++t)
    if (sign(X[t]) != 0) ring::to_rational(X[t], D, x(support[t]));
  return x;
}

template <class R>
std::optional<FarkasVector> rounded_farkas(const IntegerSystem<R>& s, const Vec<double>& y_approx,
                                           const std::vector<bool>& zero) {
  // A positive multiple of a Farkas vector is one: scaled to max-norm 1 before rounding, so that a float
  // vector of tiny entries (rows equilibrated by the float simplex) does not round to 0.
  std::vector<double> ys(static_cast<std::size_t>(s.m));
  double norm = 0;
  for (Index i = 0; i < s.m; ++i) {
    ys[static_cast<std::size_t>(i)] = y_approx(i) / to_double(s.row_scale[static_cast<std::size_t>(i)]);
    norm = std::max(norm, std::abs(ys[static_cast<std::size_t>(i)]));
  }
  if (!(norm > 0) || !std::isfinite(norm)) return std::nullopt;
  for (double& v : ys) v /= norm;
  std::vector<R> Y;
  R E;
  if (!over_common_denominator(ys, Y, E)) return std::nullopt;
  return checked_farkas(s, Y, zero);
}

#define CONTACTCERT_INTEGER_SYSTEM_INSTANTIATE(R)                                                            \
  template IntegerSystem<R> integer_system<R>(const Mat<Q>&, const Vec<Q>&);                                 \
  template IntegerSystem<R> integer_system<R>(const Mat<Q>&, const Vec<Q>&, const std::vector<Index>&);      \
  template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&);                                \
  template std::optional<Vec<Q>> unique_solution<R>(const IntegerSystem<R>&, const std::vector<Index>&);     \
  template SolutionKind unique_solution<R>(R*, Index, Index, R*, R&);                                        \
  template std::optional<Vec<Q>> rounded_point<R>(const IntegerSystem<R>&, const Vec<double>&,               \
                                                  const std::vector<bool>&);                                 \
  template std::optional<FarkasVector> basis_farkas<R>(const IntegerSystem<R>&, const Vec<double>&,          \
                                                       const std::vector<Index>&, const std::vector<bool>&); \
  template std::optional<FarkasVector> rounded_farkas<R>(const IntegerSystem<R>&, const Vec<double>&,        \
                                                         const std::vector<bool>&);
CONTACTCERT_INTEGER_SYSTEM_INSTANTIATE(i128)
CONTACTCERT_INTEGER_SYSTEM_INSTANTIATE(Z)
#undef CONTACTCERT_INTEGER_SYSTEM_INSTANTIATE

}  // namespace contactcert::exact
