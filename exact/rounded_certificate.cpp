#include "exact/rounded_certificate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

namespace contactcert::exact {

namespace {

using Index = Eigen::Index;
using i64 = std::int64_t;
using i128 = Int128;
__extension__ typedef unsigned __int128 u128;

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

/// z as a 64-bit integer (reads GMP's limbs directly: this runs once per matrix entry).
bool to_i64(mpz_srcptr z, i64& out) {
  const int size = z->_mp_size;
  if (size == 0) {
    out = 0;
    return true;
  }
  if (size > 1 || size < -1 || z->_mp_d[0] > static_cast<mp_limb_t>(INT64_MAX)) return false;
  const i64 v = static_cast<i64>(z->_mp_d[0]);
  out = size > 0 ? v : -v;
  return true;
}

bool is_one(mpz_srcptr z) { return z->_mp_size == 1 && z->_mp_d[0] == 1; }

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

// The ring operations the integer checks need, for R = Int128 (every operation overflow-checked: throws
// RingOverflow) and R = Z.
bool fits_64(i128 v) { return v == static_cast<i64>(v); }
i128 times(i128 a, i128 b) {
  if (fits_64(a) && fits_64(b)) return a * b;  // |a b| < 2^126: no check needed (the common case)
  i128 r;
  if (__builtin_mul_overflow(a, b, &r)) throw RingOverflow{};
  return r;
}
Z times(const Z& a, const Z& b) { return a * b; }
i128 plus(i128 a, i128 b) {
  i128 r;
  if (__builtin_add_overflow(a, b, &r)) throw RingOverflow{};
  return r;
}
Z plus(const Z& a, const Z& b) { return a + b; }
i128 minus(i128 a, i128 b) {
  i128 r;
  if (__builtin_sub_overflow(a, b, &r)) throw RingOverflow{};
  return r;
}
Z minus(const Z& a, const Z& b) { return a - b; }
/// a / b, known to be exact (b != 0).
i128 divide_exact(i128 a, i128 b) {
  if (b == -1) return minus(0, a);
  return fits_64(a) && fits_64(b) ? static_cast<i64>(a) / static_cast<i64>(b) : a / b;  // 64-bit division is cheaper
}
/// gcd(x, y): Euclid while a number needs more than 64 bits, then std::gcd (binary) in 64 bits.
u128 gcd_u128(u128 x, u128 y) {
  while ((x | y) >> 64 != 0) {
    if (y == 0) return x;
    x = std::exchange(y, x % y);
  }
  return std::gcd(static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y));
}
u128 magnitude(i128 v) { return v < 0 ? -static_cast<u128>(v) : static_cast<u128>(v); }
Z divide_exact(const Z& a, const Z& b) {
  Z q;
  mpz_divexact(q.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return q;
}
int sign_of(i128 v) { return (v > 0) - (v < 0); }
int sign_of(const Z& v) { return sgn(v); }
/// z as an Int128 (throws RingOverflow if it does not fit).
void from_mpz(mpz_srcptr z, i128& out) {
  const int size = z->_mp_size, limbs = size < 0 ? -size : size;
  static_assert(sizeof(mp_limb_t) == 8);
  if (limbs > 2 || (limbs == 2 && z->_mp_d[1] >> 63 != 0)) throw RingOverflow{};
  u128 u = 0;
  for (int k = limbs - 1; k >= 0; --k) u = (u << 64) | z->_mp_d[k];
  out = size < 0 ? -static_cast<i128>(u) : static_cast<i128>(u);
}
void from_mpz(mpz_srcptr z, Z& out) { mpz_set(out.get_mpz_t(), z); }
void lcm_with(i128& acc, i128 d) {
  acc = times(divide_exact(acc, static_cast<i128>(gcd_u128(magnitude(acc), magnitude(d)))), d);
}
void lcm_with(i128& acc, mpz_srcptr d) {
  i128 v;
  from_mpz(d, v);
  lcm_with(acc, v);
}
void lcm_with(Z& acc, i64 d) { mpz_lcm_ui(acc.get_mpz_t(), acc.get_mpz_t(), static_cast<unsigned long>(d)); }
void lcm_with(Z& acc, mpz_srcptr d) { mpz_lcm(acc.get_mpz_t(), acc.get_mpz_t(), d); }
double to_double(i128 v) { return static_cast<double>(v); }
double to_double(const Z& v) { return v.get_d(); }
Q to_q(const Z& v) { return Q(v); }
Q to_q(i128 v) {
  const u128 u = v < 0 ? -static_cast<u128>(v) : static_cast<u128>(v);
  Z z = static_cast<unsigned long>(u >> 64);
  mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), 64);
  z += static_cast<unsigned long>(u);
  return v < 0 ? Q(-z) : Q(z);
}

/// gcd(|a|, |b|) (0 if both are 0).
i128 gcd_of(i128 a, i128 b) {
  const u128 x = gcd_u128(magnitude(a), magnitude(b));
  if (x >> 127 != 0) throw RingOverflow{};
  return static_cast<i128>(x);
}
Z gcd_of(const Z& a, const Z& b) {
  Z r;
  mpz_gcd(r.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return r;
}

/// num / den in lowest terms (den != 0).
Q quotient(const Z& num, const Z& den) {
  Q q(num, den);
  q.canonicalize();
  return q;
}
Q quotient(i128 num, i128 den) {
  if (num == 0) return Q(0);
  if (den < 0) num = minus(0, num), den = minus(0, den);
  const auto g = static_cast<i128>(gcd_u128(magnitude(num), magnitude(den)));
  num = divide_exact(num, g), den = divide_exact(den, g);
  Q q;
  if (num >= INT64_MIN && num <= INT64_MAX && den <= INT64_MAX) {
    mpq_set_si(q.get_mpq_t(), static_cast<long>(num), static_cast<unsigned long>(den));
  } else {
    mpq_set_num(q.get_mpq_t(), to_q(num).get_num_mpz_t());
    mpq_set_den(q.get_mpq_t(), to_q(den).get_num_mpz_t());
  }
  return q;
}

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
    lcm_with(D, r->den);
    f.push_back(*r);
  }
  out.resize(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[i] = times(R(f[i].num), R(D / R(f[i].den)));
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
  s.row_scale.assign(static_cast<std::size_t>(s.m), R(1));
  R den;
  for (Index i = 0; i < s.m; ++i) {
    auto entry = [&](Index j) -> const Q& { return j < s.n ? A(i, column(j)) : b(i); };
    R& L = s.row_scale[static_cast<std::size_t>(i)];
    for (Index j = 0; j <= s.n; ++j)
      if (!is_one(mpq_denref(entry(j).get_mpq_t()))) lcm_with(L, mpq_denref(entry(j).get_mpq_t()));
    for (Index j = 0; j <= s.n; ++j) {
      R& out = j < s.n ? s.A[static_cast<std::size_t>(i * s.n + j)] : s.b[static_cast<std::size_t>(i)];
      from_mpz(mpq_numref(entry(j).get_mpq_t()), out);
      if (L == 1) continue;
      from_mpz(mpq_denref(entry(j).get_mpq_t()), den);
      out = times(out, R(L / den));
    }
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

namespace {

/// The unique solution of A_S x_S = b as fractions x_c = num_c / den_c (see unique_solution); false if there
/// is none or more than one.
template <class R>
bool solve_fraction_free(const IntegerSystem<R>& s, const std::vector<Index>& columns, std::vector<R>& num,
                         std::vector<R>& den) {
  const auto k = static_cast<Index>(columns.size()), w = k + 1;
  if (k > s.m) return false;
  // M = [A_S | b], row-major m x (k + 1).
  std::vector<R> M(static_cast<std::size_t>(s.m * w));
  auto at = [&](Index i, Index j) -> R& { return M[static_cast<std::size_t>(i * w + j)]; };
  for (Index i = 0; i < s.m; ++i) {
    for (Index c = 0; c < k; ++c)
      at(i, c) = s.A[static_cast<std::size_t>(i * s.n + columns[static_cast<std::size_t>(c)])];
    at(i, k) = s.b[static_cast<std::size_t>(i)];
  }
  // Columns of A_S divided by their contents g_c (x_c = x'_c / g_c), then rows of [A_S | b] by theirs: the
  // minors below shrink by those factors (X's rows from the left null space of P share large ones).
  std::vector<R> g(static_cast<std::size_t>(k));
  for (Index c = 0; c < k; ++c) {
    R& gc = g[static_cast<std::size_t>(c)];
    for (Index i = 0; i < s.m; ++i) gc = gcd_of(gc, at(i, c));
    if (sign_of(gc) == 0) return false;  // a zero column: A_S is rank deficient
    for (Index i = 0; i < s.m; ++i) at(i, c) = divide_exact(at(i, c), gc);
  }
  for (Index i = 0; i < s.m; ++i) {
    R gi(0);
    for (Index j = 0; j < w; ++j) gi = gcd_of(gi, at(i, j));
    if (gi > R(1))
      for (Index j = 0; j < w; ++j) at(i, j) = divide_exact(at(i, j), gi);
  }
  // Fraction-free Gauss-Jordan (Bareiss applied above the pivot too): after step c every entry of the
  // eliminated rows is a (c+1) x (c+1) minor of M, so the division by the previous pivot is exact and no
  // intermediate exceeds a product of two minors (back substitution would multiply a k x k minor by another).
  R prev(1);
  for (Index c = 0; c < k; ++c) {
    Index p = c;
    while (p < s.m && sign_of(at(p, c)) == 0) ++p;
    if (p == s.m) return false;  // A_S is rank deficient
    if (p != c)
      for (Index j = c; j < w; ++j) std::swap(at(p, j), at(c, j));
    for (Index i = 0; i < s.m; ++i) {
      if (i == c) continue;
      if (i < c) at(i, i) = at(c, c);  // (a_cc a_ii - a_ic a_ci) / prev with a_ci = 0, a_ii = prev
      for (Index j = c + 1; j < w; ++j)
        at(i, j) = divide_exact(minus(times(at(c, c), at(i, j)), times(at(i, c), at(c, j))), prev);
      at(i, c) = 0;
    }
    prev = at(c, c);
  }
  for (Index i = k; i < s.m; ++i)
    if (sign_of(at(i, k)) != 0) return false;  // inconsistent
  // Now M = [d I | d x'_S] on its first k rows, d = prev a k x k minor (Cramer's rule); x_c = x'_c / g_c.
  num.resize(static_cast<std::size_t>(k));
  den.resize(static_cast<std::size_t>(k));
  for (Index i = 0; i < k; ++i) {
    num[static_cast<std::size_t>(i)] = at(i, k);
    den[static_cast<std::size_t>(i)] = times(prev, g[static_cast<std::size_t>(i)]);
  }
  return true;
}

/// Y as a Farkas vector of the rows of s if it is one: Y^T b < 0 and Y^T A_j >= 0 unless j is in `zero`; the
/// result is y_i = row_scale_i Y_i (for the rows before scaling) with its negative columns.
template <class R>
std::optional<FarkasVector> checked_farkas(const IntegerSystem<R>& s, const std::vector<R>& Y,
                                           const std::vector<bool>& zero) {
  R acc(0);
  for (Index i = 0; i < s.m; ++i)
    acc = plus(acc, times(s.b[static_cast<std::size_t>(i)], Y[static_cast<std::size_t>(i)]));
  if (sign_of(acc) >= 0) return std::nullopt;
  FarkasVector f;
  for (Index j = 0; j < s.n; ++j) {  // column by column over the rows with Y_i != 0
    acc = 0;
    for (Index i = 0; i < s.m; ++i)
      if (sign_of(Y[static_cast<std::size_t>(i)]) != 0)
        acc = plus(acc, times(s.A[static_cast<std::size_t>(i * s.n + j)], Y[static_cast<std::size_t>(i)]));
    if (sign_of(acc) >= 0) continue;
    if (!zero[static_cast<std::size_t>(j)]) return std::nullopt;
    f.negative.push_back(j);
  }
  f.y = Vec<Q>(s.m);
  for (Index i = 0; i < s.m; ++i)
    f.y(i) = to_q(times(s.row_scale[static_cast<std::size_t>(i)], Y[static_cast<std::size_t>(i)]));
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
  std::vector<R> num, den;
  if (!solve_fraction_free(s, columns, num, den)) return std::nullopt;
  Vec<Q> x(static_cast<Index>(num.size()));
  for (std::size_t i = 0; i < num.size(); ++i) x(static_cast<Index>(i)) = quotient(num[i], den[i]);
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
  IntegerSystem<R> t;
  t.m = t.n = m;
  t.A.assign(static_cast<std::size_t>(m * m), R(0));
  t.b.assign(static_cast<std::size_t>(m), R(0));
  for (Index r = 0; r < m; ++r) {
    const Index v = basis[static_cast<std::size_t>(r)];
    if (v < 0 || v >= s.n + m) return std::nullopt;
    if (v < s.n) {
      for (Index i = 0; i < m; ++i)
        t.A[static_cast<std::size_t>(r * m + i)] = s.A[static_cast<std::size_t>(i * s.n + v)];
    } else {
      const Index i = v - s.n;
      const double f = y_approx(i);
      if (f == 0 || !std::isfinite(f)) return std::nullopt;
      const int e = static_cast<int>(std::lround(std::log2(std::abs(f))));  // |f_i| = 2^e
      if (e < -62 || e > 62) return std::nullopt;
      const R power(std::int64_t(1) << (e < 0 ? -e : e));
      const R& L = s.row_scale[static_cast<std::size_t>(i)];
      t.A[static_cast<std::size_t>(r * m + i)] = e < 0 ? times(L, power) : L;
      t.b[static_cast<std::size_t>(r)] = R(f < 0 ? -1 : 1) * (e < 0 ? R(1) : power);
    }
  }
  std::vector<R> num, den;
  if (!solve_fraction_free(t, all_columns(m), num, den)) return std::nullopt;
  // f = F / G over the positive common denominator G.
  R G(1);
  for (std::size_t i = 0; i < num.size(); ++i) {
    if (sign_of(den[i]) < 0) num[i] = minus(R(0), num[i]), den[i] = minus(R(0), den[i]);
    G = times(divide_exact(G, gcd_of(G, den[i])), den[i]);
  }
  std::vector<R> F(num.size());
  for (std::size_t i = 0; i < num.size(); ++i) F[i] = times(num[i], divide_exact(G, den[i]));
  return checked_farkas(s, F, zero);
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
    if (sign_of(v) < 0) return std::nullopt;
  // A X = D b, row by row.
  for (Index i = 0; i < s.m; ++i) {
    R acc(0);
    for (std::size_t t = 0; t < support.size(); ++t)
      acc = plus(acc, times(s.A[static_cast<std::size_t>(i * s.n + support[t])], X[t]));
    if (acc != times(D, s.b[static_cast<std::size_t>(i)])) return std::nullopt;
  }
  Vec<Q> x = Vec<Q>::Zero(s.n);
  for (std::size_t t = 0; t < support.size(); ++t)
    if (sign_of(X[t]) != 0) x(support[t]) = quotient(X[t], D);
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
