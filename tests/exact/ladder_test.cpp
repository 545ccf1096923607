// The precision ladder: the same templated simplex and linear algebra in MPFR floats (53, 113, 256, 1024
// bits) and double intervals, compared with the exact simplex; and the exact LP that climbs the ladder.
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "exact/fraction_free.h"
#include "exact/interval_number.h"
#include "exact/linalg.h"
#include "exact/mpfr_number.h"
#include "exact/simplex.h"
#include "exact/verified_lp.h"
#include "geometry/double_description.h"
#include "tests/exact/lp_expectations.h"
#include "tests/exact/random_lp.h"

namespace contactcert::exact {
namespace {

constexpr std::array<long, 4> kBits{53, 113, 256, 1024};

/// q in the number type of `zero` (at MPFR's working precision).
Q from_exact(const Q& q, const Q&) { return q; }
template <class T>
T from_exact(const Q& q, const T&) {
  return NumberTraits<T>::from_q(q);
}

/// Near-degenerate LPs: b = A x0 + 2^-e d with x0 >= 0 zero on most columns, so that feasibility and the
/// optimal basis turn on quantities of size 2^-e; e is drawn from [10, 400].
LpProblem<Q> near_degenerate_lp(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> small(-3, 3), rows(2, 5), pct(0, 99), e(10, 400);
  const int m = rows(rng), n = m + 2;
  LpProblem<Q> p;
  p.A = Mat<Q>(m, n);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) p.A(i, j) = small(rng);
  Vec<Q> x0 = Vec<Q>::Zero(n), d(m);
  for (int j = 0; j < n; ++j) x0(j) = pct(rng) < 30 ? Q(1 + pct(rng) % 3) : Q(0);
  Q eps(1);
  mpq_div_2exp(eps.get_mpq_t(), eps.get_mpq_t(), static_cast<mp_bitcnt_t>(e(rng)));
  for (int i = 0; i < m; ++i) d(i) = small(rng);
  p.b = p.A * x0 + eps * d;
  p.c = Vec<Q>(n);
  for (int j = 0; j < n; ++j) {
    // The perturbation is drawn first, as gcc evaluated the two operands of + (right to left).
    const Q perturbation = Q(small(rng)) * eps;
    p.c(j) = Q(small(rng)) + perturbation;
  }
  return p;
}

/// Same verdict as the exact LP, and for optimal LPs the same value to 1e-9 (relative).
template <class T>
bool agrees(const LpResult<T>& r, const LpResult<Q>& e) {
  if (r.status != e.status) return false;
  if (e.status != LpStatus::kOptimal) return true;
  const double v = NumberTraits<T>::to_double(r.value), ve = e.value.get_d();
  return std::abs(v - ve) <= 1e-9 * std::max(1.0, std::abs(ve));
}

struct Agreement {
  int total = 0, double_rung = 0, interval_decided = 0;
  std::array<int, kBits.size()> mpfr{};
};

Agreement count_agreement(LpProblem<Q> (*generate)(std::mt19937_64&), int cases, unsigned long seed) {
  std::mt19937_64 rng(seed);
  Agreement a;
  for (int t = 0; t < cases; ++t) {
    const LpProblem<Q> p = generate(rng);
    const LpResult<Q> e = solve_lp<Q>(p);
    ++a.total;
    a.double_rung += agrees(solve_lp<double>(to_double(p)), e);
    for (size_t k = 0; k < kBits.size(); ++k) a.mpfr[k] += agrees(solve_lp<Mpfr>(to_mpfr(p, kBits[k])), e);
    try {
      const LpResult<Interval> r = solve_lp<Interval>(to_interval(p));
      // No uncertain sign: every decision was the exact simplex's, so the basis and the verdict are too.
      EXPECT_EQ(r.status, e.status) << "case " << t;
      EXPECT_EQ(r.basis, e.basis) << "case " << t;
      ++a.interval_decided;
    } catch (const UncertainSign&) {
    }
  }
  return a;
}

// Well-conditioned LPs (small integers, many degenerate): every rung agrees with exact arithmetic.
TEST(Ladder, EveryRungAgreesOnWellConditionedLps) {
  const Agreement a = count_agreement(testing::random_lp, 400, 9);
  EXPECT_EQ(a.double_rung, a.total);
  for (int agree : a.mpfr) EXPECT_EQ(agree, a.total);
  EXPECT_GT(a.interval_decided, a.total / 2);
}

// Near-degenerate LPs: the higher the precision, the more verdicts agree with exact arithmetic, and 1024
// bits (tolerance 2^-579 against data of size 2^-400) agree on all of them; double and 53 bits do not.
TEST(Ladder, HigherRungsAgreeMoreOftenOnNearDegenerateLps) {
  const Agreement a = count_agreement(near_degenerate_lp, 300, 10);
  for (size_t k = 1; k < kBits.size(); ++k) EXPECT_LE(a.mpfr[k - 1], a.mpfr[k]) << kBits[k] << " bits";
  EXPECT_LT(a.double_rung, a.total);
  EXPECT_LT(a.mpfr[0], a.mpfr[1]);
  EXPECT_EQ(a.mpfr.back(), a.total);
  std::printf("of %d: double %d, mpfr53 %d, mpfr113 %d, mpfr256 %d, mpfr1024 %d, interval decided %d\n", a.total,
              a.double_rung, a.mpfr[0], a.mpfr[1], a.mpfr[2], a.mpfr[3], a.interval_decided);
}

// The linear algebra is the same template: an MPFR inverse of a Hilbert matrix is as accurate as its
// precision allows, and an interval rank is decided when the intervals prove it.
TEST(Ladder, LinearAlgebraInstantiates) {
  const int n = 10;  // cond(H_10) ~ 1.6e13
  Mat<Q> H(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) H(i, j) = Q(1, i + j + 1);
  const Mat<Q> Hinv = *inverse<Q>(H);
  const auto relative_error = [&](long bits) {
    const std::optional<Mat<Mpfr>> M = inverse<Mpfr>(H.unaryExpr([bits](const Q& q) { return to_mpfr(q, bits); }));
    double worst = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double e = Hinv(i, j).get_d();
        worst = std::max(worst, std::abs(M->coeff(i, j).to_double() - e) / std::abs(e));
      }
    return worst;
  };
  EXPECT_GT(relative_error(53), 1e-6);
  EXPECT_LT(relative_error(113), 1e-12);
  EXPECT_LT(relative_error(256), 1e-15);
  const auto to_intervals = [](const Mat<Q>& A) {
    return Mat<Interval>(A.unaryExpr([](const Q& q) { return to_interval(q); }));
  };
  EXPECT_EQ(rank<Interval>(to_intervals(H.topLeftCorner(4, 4))), 4);
  Mat<Q> thirds = Mat<Q>::Constant(2, 2, Q(1, 3));  // rank 1, but 1/3 - 1/3 is an interval around 0
  EXPECT_THROW(rank<Interval>(to_intervals(thirds)), UncertainSign);
  EXPECT_EQ(rank<Mpfr>(thirds.unaryExpr([](const Q& q) { return to_mpfr(q, 113); })), 1);
}

// One ring template for every float type (exact/float_ring.h): a row divided by its max-norm, so that parallel
// rows whose ratio is not a power of two get one representative (scaling by a power of two kept them apart, and
// the double description then found a ray twice); an interval row is divided by a point, so that its entries
// enclose one positive multiple of the exact row.
TEST(Ladder, ParallelRowsHaveOneRepresentativeInEveryFloatType) {
  std::array<double, 3> d{3, 6, -9}, d1{1, 2, -3};
  ring::normalize(d.data(), 3);
  ring::normalize(d1.data(), 3);
  EXPECT_EQ(d, d1);
  std::array<Interval, 3> v{Interval(1), Interval(2), Interval(-3)};
  ring::normalize(v.data(), 3);
  const std::array<Q, 3> exact{Q(1, 3), Q(2, 3), Q(-1)};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_LE(Q(v[i].inf()), exact[i]);
    EXPECT_GE(Q(v[i].sup()), exact[i]);
  }
  EXPECT_TRUE(v[2].is_point());
  // x >= 0, y >= 0, z >= x + y and the redundant x + 3 y >= 0: the ray (0, 0, 1) is tight on three rows, and
  // two row pairs give it at ratio 3.
  Mat<Q> A(4, 3);
  A << -1, 0, 0, 0, -1, 0, 1, 1, -1, -1, -3, 0;
  const auto rays = [&](auto zero) {
    using T = decltype(zero);
    Mat<T> F(4, 3);
    for (Eigen::Index i = 0; i < 4; ++i)
      for (Eigen::Index j = 0; j < 3; ++j) F(i, j) = from_exact(A(i, j), zero);
    return geometry::to_span<T>(geometry::FaceCone<T>::from_rows(3, F, Mat<T>(0, 3), Mat<T>(0, 3))).rays.rows();
  };
  EXPECT_EQ(rays(Q(0)), 3);
  EXPECT_EQ(rays(0.0), 3);
  for (long bits : kBits) {
    const MpfrPrecision precision(bits);
    EXPECT_EQ(rays(Mpfr(0, bits)), 3) << bits << " bits";
  }
  try {  // an interval run finds the exact rays or cannot decide, never a ray twice
    EXPECT_EQ(rays(Interval(0)), 3);
  } catch (const UncertainSign&) {
  }
}

// The adaptive ladder is exact on both families; on the near-degenerate one some LPs are decided above the
// double rung.
TEST(Ladder, AdaptiveLpIsExactAndClimbsWhenNeeded) {
  for (auto generate : {testing::random_lp, near_degenerate_lp}) {
    std::mt19937_64 rng(11);
    int above_double = 0;
    for (int t = 0; t < 300; ++t) {
      const LpProblem<Q> p = generate(rng);
      const LpResult<Q> r = solve_lp_ladder(p, adaptive_ladder(), testing::with_duals());
      testing::expect_certified_like(p, r, solve_lp<Q>(p), t);
      above_double += r.decided_by == DecidedBy::kFloatBasisCheckedExactly && r.proposed_by.kind != Rung::Kind::kDouble;
    }
    if (generate == near_degenerate_lp) {
      EXPECT_GT(above_double, 0);
    }
  }
  // The filter alone in front of exact arithmetic is exact too.
  std::mt19937_64 rng(12);
  const std::vector<Rung> filtered{{Rung::Kind::kInterval, 0}, {Rung::Kind::kExact, 0}};
  for (int t = 0; t < 300; ++t) {
    const LpProblem<Q> p = testing::random_lp(rng);
    testing::expect_certified_like(p, solve_lp_ladder(p, filtered, testing::with_duals()), solve_lp<Q>(p), t);
  }
}

}  // namespace
}  // namespace contactcert::exact
