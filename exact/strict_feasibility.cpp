#include "exact/strict_feasibility.h"

#include <type_traits>

#include "exact/ladder_numbers.h"
#include "exact/simplex.h"
#include "exact/verified_lp.h"

namespace contactcert::exact {
namespace {

using Index = Eigen::Index;
using i64 = std::int64_t;
__extension__ typedef __int128 i128;

bool flag(const std::vector<bool>& v, Index j) { return !v.empty() && v[static_cast<size_t>(j)]; }

// The LP of strict feasibility, b = 0 (set per solve on the first m rows). Columns: x (n), then t,
// sigma_1..sigma_s, u.  Rows: A x = b;  x_j - t - sigma_j = 0 (j in S);  t + u = 1.  Objective: min -t.
// With no strict column this is plain feasibility of A x = b.
template <class T>
LpProblem<T> strict_lp(const Mat<T>& A, const std::vector<bool>& is_free, const std::vector<Index>& S) {
  const Index m = A.rows(), n = A.cols(), s = static_cast<Index>(S.size());
  const Index cols = s ? n + s + 2 : n, rows = s ? m + s + 1 : m;
  LpProblem<T> lp;
  lp.A = Mat<T>::Zero(rows, cols);
  lp.b = Vec<T>::Zero(rows);
  lp.A.topLeftCorner(m, n) = A;
  lp.is_free.assign(static_cast<size_t>(cols), false);
  for (Index j = 0; j < n; ++j) lp.is_free[static_cast<size_t>(j)] = flag(is_free, j);
  if (s) {
    const Index t = n, u = n + s + 1;
    for (Index k = 0; k < s; ++k) {
      lp.A(m + k, S[static_cast<size_t>(k)]) = T(1);
      lp.A(m + k, t) = T(-1);
      lp.A(m + k, n + 1 + k) = T(-1);
    }
    lp.A(m + s, t) = T(1);
    lp.A(m + s, u) = T(1);
    lp.b(m + s) = T(1);
    lp.c = Vec<T>::Zero(cols);
    lp.c(t) = T(-1);
  }
  return lp;
}

// The answer read off the LP's result (m rows and n columns of the system).
template <class T>
StrictFeasibility<T> read_strict(const LpResult<T>& r, Index m, Index n, bool has_strict) {
  StrictFeasibility<T> out;
  out.lps = 1;
  out.decided_by = r.decided_by;
  if (r.status == LpStatus::kInfeasible) {
    // The first m entries of the Farkas vector of the extended system already prove A x = b, x >= 0
    // infeasible (the extra rows only add non-negative terms), with y^T b < 0.
    out.motzkin = r.farkas.head(m);
    return out;
  }
  // Optimal (t <= 1 bounds the LP).
  if (!has_strict || is_positive(T(-r.value))) {
    out.status = StrictStatus::kFeasible;
    out.x = r.x.head(n);
    return out;
  }
  // t* = 0: the duals (y1, y2, y3) give w = -y1 with w^T A >= y2 >= 0 on S, w^T b = y3 <= 0 and
  // sum(y2) >= 1 + y3, so w^T b < 0 or some (w^T A)_j > 0 on S.
  out.motzkin = -r.duals.head(m);
  return out;
}

bool fma128(i128& acc, i64 a, i64 b) {
  return !__builtin_add_overflow(acc, static_cast<i128>(a) * static_cast<i128>(b), &acc);
}

// B = d (L o b) in 64-bit integers, L the row scales and d > 0 the least common denominator, so that
// A_int x = B  <=>  A (x / d) = b.  Nullopt if an entry does not fit.
std::optional<std::vector<i64>> integer_rhs(const IntegerLp& ilp, const Vec<Q>& b, Z& d) {
  std::vector<std::pair<Index, Q>> q;  // the non-zero L_i b_i (b is mostly zero)
  d = 1;
  for (Index i = 0; i < b.size(); ++i) {
    if (sgn(b(i)) == 0) continue;
    q.emplace_back(i, b(i) * Q(static_cast<long>(ilp.row_scale[static_cast<size_t>(i)])));
    mpz_lcm(d.get_mpz_t(), d.get_mpz_t(), q.back().second.get_den_mpz_t());
  }
  std::vector<i64> B(static_cast<size_t>(b.size()), 0);
  for (const auto& [i, qi] : q) {
    const Z v = qi.get_num() * (d / qi.get_den());
    if (!v.fits_slong_p()) return std::nullopt;
    B[static_cast<size_t>(i)] = v.get_si();
  }
  return B;
}

// The float LP on the integer rows, its point or certificate rounded to fractions and checked exactly;
// nullopt if the check fails.
std::optional<StrictFeasibility<Q>> rounded_solve(const IntegerLp& ilp, const LpProblem<double>& hint,
                                                  const StrictSystem<Q>& sys, const std::vector<Index>& S,
                                                  const Vec<Q>& b) {
  const Index m = ilp.m, n = ilp.n;
  Z d;
  const std::optional<std::vector<i64>> B = integer_rhs(ilp, b, d);
  if (!B) return std::nullopt;
  LpProblem<double> lp = hint;
  for (Index i = 0; i < m; ++i) lp.b(i) = static_cast<double>((*B)[static_cast<size_t>(i)]);
  const StrictFeasibility<double> f = read_strict(solve_lp<double>(lp), m, n, !S.empty());
  auto A = [&](Index i, Index j) { return ilp.A[static_cast<size_t>(i * n + j)]; };

  StrictFeasibility<Q> out;
  out.lps = 1;
  out.decided_by = DecidedBy::kFloatBasisCheckedExactly;
  out.rounded_float_checked = true;
  out.status = f.status;
  if (f.status == StrictStatus::kFeasible) {
    // x ~ X / D: check A_int X = D B and the signs; then x / d solves A x = b.
    std::vector<i64> X;
    i64 D;
    if (!round_vector(std::vector<double>(f.x.data(), f.x.data() + n), X, D)) return std::nullopt;
    for (Index j = 0; j < n; ++j) {
      const i64 xj = X[static_cast<size_t>(j)];
      if (!flag(sys.is_free, j) && (xj < 0 || (xj == 0 && flag(sys.strict, j)))) return std::nullopt;
    }
    for (Index i = 0; i < m; ++i) {
      i128 acc = 0;
      for (Index j = 0; j < n; ++j)
        if (!fma128(acc, A(i, j), X[static_cast<size_t>(j)])) return std::nullopt;
      if (acc != static_cast<i128>(D) * (*B)[static_cast<size_t>(i)]) return std::nullopt;
    }
    out.x = Vec<Q>(n);
    for (Index j = 0; j < n; ++j) out.x(j) = make_q(X[static_cast<size_t>(j)], D) / d;
    return out;
  }
  // y' ~ Y / E for the integer rows: check the Motzkin conditions on (A_int, B); then y = L o Y is one for
  // (A, b): y^T A = Y^T A_int and y^T b = Y^T B / d.
  std::vector<i64> Y;
  i64 E;
  if (!round_vector(std::vector<double>(f.motzkin.data(), f.motzkin.data() + m), Y, E)) return std::nullopt;
  bool strict_positive = false;
  for (Index j = 0; j < n; ++j) {
    i128 t = 0;
    for (Index i = 0; i < m; ++i)
      if (!fma128(t, Y[static_cast<size_t>(i)], A(i, j))) return std::nullopt;
    if (flag(sys.is_free, j) ? t != 0 : t < 0) return std::nullopt;
    strict_positive = strict_positive || (t > 0 && flag(sys.strict, j));
  }
  i128 yb = 0;
  for (Index i = 0; i < m; ++i)
    if (!fma128(yb, Y[static_cast<size_t>(i)], (*B)[static_cast<size_t>(i)])) return std::nullopt;
  if (!(yb < 0 || (yb == 0 && strict_positive))) return std::nullopt;
  out.motzkin = Vec<Q>(m);
  for (Index i = 0; i < m; ++i)
    out.motzkin(i) = Q(Z(static_cast<long>(ilp.row_scale[static_cast<size_t>(i)])) *
                       Z(static_cast<long>(Y[static_cast<size_t>(i)])));
  return out;
}

}  // namespace

template <class T>
StrictSolver<T>::StrictSolver(const StrictSystem<T>& system, Arith arith) : system_(system), arith_(arith) {
  for (Index j = 0; j < system.A.cols(); ++j)
    if (flag(system.strict, j)) strict_columns_.push_back(j);
  if constexpr (std::is_same_v<T, Q>) {
    if (arith == Arith::kExact) return;
    // A is lent to the LP for the scaling and taken back (no copy of a rational matrix).
    LpProblem<Q> lp{std::move(system_.A), Vec<Q>::Zero(system.A.rows()), {}, {}};
    integer_ = integer_lp(lp);
    system_.A = std::move(lp.A);
    if (integer_) hint_ = strict_lp<double>(integer_->to_double({}).A, system.is_free, strict_columns_);
  } else {
    hint_ = strict_lp<T>(system.A, system.is_free, strict_columns_);
  }
}

template <class T>
StrictFeasibility<T> StrictSolver<T>::solve(const Vec<T>& b) const {
  const Index m = system_.A.rows(), n = system_.A.cols();
  const bool has_strict = !strict_columns_.empty();
  if constexpr (std::is_same_v<T, Q>) {
    if (integer_)
      if (std::optional<StrictFeasibility<Q>> r = rounded_solve(*integer_, hint_, system_, strict_columns_, b))
        return std::move(*r);
    LpProblem<Q> lp = strict_lp<Q>(system_.A, system_.is_free, strict_columns_);
    lp.b.head(m) = b;
    return read_strict(arith_ == Arith::kExact ? solve_lp<Q>(lp) : solve_lp_verified(lp), m, n, has_strict);
  } else {
    LpProblem<T> lp = hint_;
    lp.b.head(m) = b;
    return read_strict(solve_lp<T>(lp), m, n, has_strict);
  }
}

template <class T>
StrictFeasibility<T> strict_feasibility(const StrictSystem<T>& sys, Arith arith) {
  return StrictSolver<T>(sys, arith).solve(sys.b);
}

bool verify_strict_point(const StrictSystem<Q>& sys, const Vec<Q>& x) {
  if (x.size() != sys.A.cols()) return false;
  Vec<Q> r = sys.A * x - sys.b;
  for (Index i = 0; i < r.size(); ++i)
    if (sgn(r(i)) != 0) return false;
  for (Index j = 0; j < x.size(); ++j) {
    if (flag(sys.is_free, j)) continue;
    if (sgn(x(j)) < 0 || (flag(sys.strict, j) && sgn(x(j)) == 0)) return false;
  }
  return true;
}

bool verify_motzkin(const StrictSystem<Q>& sys, const Vec<Q>& y) {
  if (y.size() != sys.A.rows()) return false;
  bool strict_positive = false;
  for (Index j = 0; j < sys.A.cols(); ++j) {
    Q v = 0;
    for (Index i = 0; i < y.size(); ++i) v += y(i) * sys.A(i, j);
    if (flag(sys.is_free, j)) {
      if (sgn(v) != 0) return false;
    } else if (sgn(v) < 0) {
      return false;
    } else if (sgn(v) > 0 && flag(sys.strict, j)) {
      strict_positive = true;
    }
  }
  Q yb = 0;
  for (Index i = 0; i < y.size(); ++i) yb += y(i) * sys.b(i);
  return sgn(yb) < 0 || (sgn(yb) == 0 && strict_positive);
}

template class StrictSolver<double>;
template class StrictSolver<Q>;
template StrictFeasibility<double> strict_feasibility<double>(const StrictSystem<double>&, Arith);
template StrictFeasibility<Q> strict_feasibility<Q>(const StrictSystem<Q>&, Arith);
template class StrictSolver<Mpfr>;
template class StrictSolver<Interval>;
template StrictFeasibility<Mpfr> strict_feasibility<Mpfr>(const StrictSystem<Mpfr>&, Arith);
template StrictFeasibility<Interval> strict_feasibility<Interval>(const StrictSystem<Interval>&, Arith);

}  // namespace contactcert::exact
