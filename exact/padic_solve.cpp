#include "exact/padic_solve.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <utility>

#include "exact/rational_reconstruction.h"

namespace contactcert::exact {
namespace {

using Index = Eigen::Index;
using u64 = std::uint64_t;

/// a^-1 mod p (p prime, a != 0 mod p) by Fermat: a^(p-2).
template <u64 p>
u64 inverse(u64 a) {
  u64 r = 1, e = p - 2;
  for (; e; e >>= 1, a = a * a % p)
    if (e & 1) r = r * a % p;
  return r;
}

/// A = P^-1 L U modulo p (p < 2^32, a compile-time constant so that % is a multiplication): L unit lower triangular
/// below the diagonal of lu, U on and above it, row r of P A is row perm[r] of A.
template <u64 p>
struct LuModP {
  Index k = 0;
  std::vector<u64> lu, inverse_pivot;
  std::vector<Index> perm;

  u64& at(Index i, Index j) { return lu[static_cast<std::size_t>(i * k + j)]; }

  /// False if A is singular modulo p.
  bool factor(const IntMatrix<Z>& M) {
    k = M.rows();
    lu.resize(static_cast<std::size_t>(k * k));
    for (Index i = 0; i < k; ++i)
      for (Index j = 0; j < k; ++j) at(i, j) = mpz_fdiv_ui(M(i, j).get_mpz_t(), p);
    perm.resize(static_cast<std::size_t>(k));
    for (Index i = 0; i < k; ++i) perm[static_cast<std::size_t>(i)] = i;
    inverse_pivot.resize(static_cast<std::size_t>(k));
    std::vector<Index> nz;  // the non-zero columns of the pivot row right of the pivot
    for (Index c = 0; c < k; ++c) {
      Index r = c;
      while (r < k && at(r, c) == 0) ++r;
      if (r == k) return false;
      if (r != c) {
        for (Index j = 0; j < k; ++j) std::swap(at(r, j), at(c, j));
        std::swap(perm[static_cast<std::size_t>(r)], perm[static_cast<std::size_t>(c)]);
      }
      const u64 inv = inverse<p>(at(c, c));
      inverse_pivot[static_cast<std::size_t>(c)] = inv;
      nz.clear();
      for (Index j = c + 1; j < k; ++j)
        if (at(c, j) != 0) nz.push_back(j);
      for (Index i = c + 1; i < k; ++i) {
        if (at(i, c) == 0) continue;
        const u64 f = at(i, c) * inv % p;
        at(i, c) = f;
        const u64 minus_f = p - f;
        for (Index j : nz) at(i, j) = (at(i, j) + minus_f * at(c, j)) % p;
      }
    }
    return true;
  }

  /// x = A^-1 v mod p (v reduced).
  void solve(const std::vector<u64>& v, std::vector<u64>& x) {
    x.resize(static_cast<std::size_t>(k));
    for (Index i = 0; i < k; ++i) {  // L y = P v
      u64 acc = v[static_cast<std::size_t>(perm[static_cast<std::size_t>(i)])];
      for (Index j = 0; j < i; ++j) acc += (p - at(i, j)) * x[static_cast<std::size_t>(j)] % p;
      x[static_cast<std::size_t>(i)] = acc % p;
    }
    for (Index i = k - 1; i >= 0; --i) {  // U x = y
      u64 acc = x[static_cast<std::size_t>(i)];
      for (Index j = i + 1; j < k; ++j) acc += (p - at(i, j)) * x[static_cast<std::size_t>(j)] % p;
      x[static_cast<std::size_t>(i)] = acc % p * inverse_pivot[static_cast<std::size_t>(i)] % p;
    }
  }
};

/// The entries of X mod P over a common denominator (each reconstructed after multiplying by the denominator of
/// those before: once it is the whole denominator, the rest are integers), checked against A n = d b.
std::optional<LiftedSolution> reconstructed(const IntMatrix<Z>& M, const std::vector<Z>& X, const Z& P) {
  const Index k = M.rows();
  Z bound;
  mpz_fdiv_q_2exp(bound.get_mpz_t(), P.get_mpz_t(), 1);
  mpz_sqrt(bound.get_mpz_t(), bound.get_mpz_t());
  LiftedSolution s{std::vector<Z>(static_cast<std::size_t>(k)), Z(1)};
  Z w, n, d;
  for (Index i = 0; i < k; ++i) {
    w = s.D * X[static_cast<std::size_t>(i)];
    mpz_fdiv_r(w.get_mpz_t(), w.get_mpz_t(), P.get_mpz_t());
    if (!reconstruct_modular(w, P, bound, n, d)) return std::nullopt;
    if (d != 1) {
      for (Index j = 0; j < i; ++j) s.U[static_cast<std::size_t>(j)] *= d;
      s.D *= d;
    }
    s.U[static_cast<std::size_t>(i)] = n;
  }
  for (Index i = 0; i < k; ++i) {  // A U = D b, exactly
    w = 0;
    for (Index j = 0; j < k; ++j)
      if (sgn(M(i, j)) != 0) w += M(i, j) * s.U[static_cast<std::size_t>(j)];
    if (w != s.D * M(i, k)) return std::nullopt;
  }
  return s;
}

/// log2 of the Hadamard bound of [A | b], from above, in whole bits: per row, the bits of its largest entry plus
/// half the bits of its count of non-zero entries t (sqrt(t) 2^largest bounds the row's 2-norm).
long hadamard_bits(const IntMatrix<Z>& M) {
  long bits = 0;
  for (Index i = 0; i < M.rows(); ++i) {
    std::size_t largest = 0;
    unsigned long terms = 0;
    for (Index j = 0; j < M.cols(); ++j)
      if (sgn(M(i, j)) != 0) {
        largest = std::max(largest, mpz_sizeinbase(M(i, j).get_mpz_t(), 2));  // |a| < 2^largest
        ++terms;
      }
    bits += static_cast<long>(largest + (std::bit_width(terms) + 1) / 2);  // log2(t) / 2 <= (bit_width(t) + 1) / 2
  }
  return bits;
}

template <u64 p>
std::optional<LiftedSolution> lift(const IntMatrix<Z>& M) {
  static_assert(p > (u64(1) << 30) && p < (u64(1) << 31), "P gains more than 30 bits a step; residue products fit");
  LuModP<p> lu;
  if (!lu.factor(M)) return std::nullopt;
  const Index k = M.rows();
  // Reconstruction is unique once P > 2 N D (|numerators| <= N, denominator <= D, both at most the Hadamard bound H):
  // at most that many steps, trying earlier ones on a schedule growing by half.
  const long needed = 2 * hadamard_bits(M) + 2;
  std::vector<Z> r(static_cast<std::size_t>(k)), X(static_cast<std::size_t>(k), Z(0));
  std::vector<std::vector<std::pair<Index, const Z*>>> rows(static_cast<std::size_t>(k));  // A's non-zero entries
  for (Index i = 0; i < k; ++i) {
    r[static_cast<std::size_t>(i)] = M(i, k);
    for (Index j = 0; j < k; ++j)
      if (sgn(M(i, j)) != 0) rows[static_cast<std::size_t>(i)].emplace_back(j, &M(i, j));
  }
  std::vector<u64> v(static_cast<std::size_t>(k)), x;
  Z P = 1;
  long bits = 0;  // log2 P from below: each p > 2^30
  for (long step = 1, next_try = 2;; ++step) {
    for (Index i = 0; i < k; ++i)
      v[static_cast<std::size_t>(i)] = mpz_fdiv_ui(r[static_cast<std::size_t>(i)].get_mpz_t(), p);
    lu.solve(v, x);
    for (Index i = 0; i < k; ++i) {  // r = (r - A x) / p, exactly (A x = r mod p)
      Z& ri = r[static_cast<std::size_t>(i)];
      for (const auto& [j, a] : rows[static_cast<std::size_t>(i)])
        if (x[static_cast<std::size_t>(j)] != 0)
          mpz_submul_ui(ri.get_mpz_t(), a->get_mpz_t(), x[static_cast<std::size_t>(j)]);
      mpz_divexact_ui(ri.get_mpz_t(), ri.get_mpz_t(), p);
    }
    for (Index j = 0; j < k; ++j)
      if (x[static_cast<std::size_t>(j)] != 0)
        mpz_addmul_ui(X[static_cast<std::size_t>(j)].get_mpz_t(), P.get_mpz_t(), x[static_cast<std::size_t>(j)]);
    P *= static_cast<unsigned long>(p);
    bits += 30;
    const bool last = bits > needed;
    if (step == next_try || last) {
      if (std::optional<LiftedSolution> s = reconstructed(M, X, P)) return s;
      if (last) return std::nullopt;
      next_try = step + (step + 1) / 2;
    }
  }
}

}  // namespace

std::optional<LiftedSolution> padic_solve(const IntMatrix<Z>& M) {
  // Primes below 2^31 (a product of two residues fits in 64 bits); the next is tried where A is singular modulo one.
  if (std::optional<LiftedSolution> s = lift<2147483647>(M)) return s;
  if (std::optional<LiftedSolution> s = lift<2147483629>(M)) return s;
  return lift<2147483587>(M);
}

}  // namespace contactcert::exact
