#include "exact/strict_feasibility.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <type_traits>

#include "exact/ladder_numbers.h"
#include "exact/rounded_check.h"
#include "exact/simplex.h"
#include "exact/verified_lp.h"

namespace contactcert::exact {
namespace {

using Index = Eigen::Index;
using i64 = std::int64_t;

bool flag(const std::vector<bool>& v, Index j) { return !v.empty() && v[static_cast<size_t>(j)]; }

// The LP of strict feasibility, b = 0 (set per solve on the first m rows). With x_j = t + sigma_j on S (sigma_j
// >= 0 takes the column of x_j): columns x (n, sigma_j in place of x_j on S), t, u; rows A x + (sum_S A_j) t = b
// and t + u = 1; objective min -t. (m + 1 rows: one row per strict column fewer than x_j - t - sigma_j = 0.)
// With no strict column this is plain feasibility of A x = b.
// A: a matrix or an Eigen expression of one (the integer rows cast to doubles, read once).
template <class T, class Derived>
LpProblem<T> strict_lp(const Eigen::MatrixBase<Derived>& A, const std::vector<bool>& is_free,
                       const std::vector<Index>& S) {
  const Index m = A.rows(), n = A.cols(), s = static_cast<Index>(S.size());
  const Index cols = s ? n + 2 : n, rows = s ? m + 1 : m;
  LpProblem<T> lp;
  lp.A = Mat<T>::Zero(rows, cols);
  lp.b = Vec<T>::Zero(rows);
  lp.A.topLeftCorner(m, n) = A;
  lp.is_free.assign(static_cast<size_t>(cols), false);
  for (Index j = 0; j < n; ++j) lp.is_free[static_cast<size_t>(j)] = flag(is_free, j);
  if (s) {
    const Index t = n, u = n + 1;
    for (Index j : S)
      for (Index i = 0; i < m; ++i) lp.A(i, t) += A(i, j);
    lp.A(m, t) = T(1);
    lp.A(m, u) = T(1);
    lp.b(m) = T(1);
    lp.c = Vec<T>::Zero(cols);
    lp.c(t) = T(-1);
  }
  return lp;
}

// The answer read off the LP's result (m rows and n columns of the system, strict columns S).
/// The options of the strict-feasibility LP: its duals are the Motzkin certificate (read_strict).
LpOptions with_duals() {
  LpOptions o;
  o.duals = true;
  return o;
}

template <class T>
StrictFeasibility<T> read_strict(const LpResult<T>& r, Index m, Index n, const std::vector<Index>& S) {
  StrictFeasibility<T> out;
  out.lps = 1;
  out.decided_by = r.decided_by;
  if (r.status == LpStatus::kInfeasible) {
    // The first m entries of the Farkas vector of the extended system already prove A x = b, x >= 0
    // infeasible (the t and u columns only add non-negative terms), with y^T b < 0.
    out.motzkin = r.farkas.head(m);
    return out;
  }
  if constexpr (!std::is_same_v<T, Q>) {
    // t <= 1 bounds the LP, so only roundoff ends a float simplex "unbounded" (rows nearly dependent): it has
    // neither a point nor duals; the float path reads that as infeasible, with no certificate (a zero vector).
    if (r.status != LpStatus::kOptimal) {
      out.motzkin = Vec<T>::Zero(m);
      return out;
    }
  }
  // Optimal (t <= 1 bounds the LP).
  if (S.empty() || is_positive(T(-r.value))) {
    out.status = StrictStatus::kFeasible;
    out.x = r.x.head(n);
    for (Index j : S) out.x(j) += r.x(n);  // x_j = t + sigma_j
    return out;
  }
  // t* = 0: the duals (y1, y3) have A_j^T y1 <= 0 (== 0 if free), (sum_S A_j)^T y1 + y3 <= -1, y3 <= 0 and
  // b^T y1 + y3 = 0; so w = -y1 has w^T A >= 0 (== 0 on free columns), w^T b = y3 <= 0 and
  // sum_S (w^T A)_j >= 1 + y3: w^T b < 0 or some (w^T A)_j > 0 on S.
  out.motzkin = -r.duals.head(m);
  return out;
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

// The rounded float answer checked in 128-bit integers (throws RingOverflow): x ~ X / D with A_int X = D B
// and the signs, then x / d solves A x = b; or y' ~ Y / E with the Motzkin conditions on (A_int, B), then
// y = L o Y is one for (A, b): y^T A = Y^T A_int and y^T b = Y^T B / d.
std::optional<StrictFeasibility<Q>> check_rounded(const IntegerLp& ilp, const StrictFeasibility<double>& f,
                                                  const std::vector<bool>& is_free, const std::vector<bool>& strict,
                                                  const std::vector<i64>& B, const Z& d) {
  const Index m = ilp.rows(), n = ilp.cols();
  StrictFeasibility<Q> out;
  out.lps = 1;
  out.decided_by = DecidedBy::kFloatBasisCheckedExactly;
  out.rounded_float_checked = true;
  out.status = f.status;
  if (f.status == StrictStatus::kFeasible) {
    std::vector<Index> all(static_cast<size_t>(n));
    std::iota(all.begin(), all.end(), Index(0));
    const std::optional<RoundedVector<Int128>> x =
        rounded_solution<Int128>(ilp, B, all, std::vector<double>(f.x.data(), f.x.data() + n));
    if (!x) return std::nullopt;
    for (Index j = 0; j < n; ++j) {
      const Int128 xj = x->X[static_cast<size_t>(j)];
      if (!flag(is_free, j) && (xj < 0 || (xj == 0 && flag(strict, j)))) return std::nullopt;
    }
    out.x = Vec<Q>(n);
    for (Index j = 0; j < n; ++j) {
      ring::to_rational(x->X[static_cast<size_t>(j)], x->D, out.x(j));
      if (d != 1) out.x(j) /= d;
    }
    return out;
  }
  std::vector<Int128> Y;
  Int128 E;
  if (!reconstruct_vector(std::vector<double>(f.motzkin.data(), f.motzkin.data() + m), Y, E)) return std::nullopt;
  const std::vector<Int128> yA = left_product(ilp, Y);
  bool strict_positive = false;
  for (Index j = 0; j < n; ++j) {
    const Int128 t = yA[static_cast<size_t>(j)];
    if (flag(is_free, j) ? t != 0 : t < 0) return std::nullopt;
    strict_positive = strict_positive || (t > 0 && flag(strict, j));
  }
  Int128 yb = 0;
  for (Index i = 0; i < m; ++i)
    yb = ring::add(yb, ring::mul(Y[static_cast<size_t>(i)], Int128(B[static_cast<size_t>(i)])));
  if (!(yb < 0 || (yb == 0 && strict_positive))) return std::nullopt;
  out.motzkin = Vec<Q>(m);
  for (Index i = 0; i < m; ++i) {
    const Int128 Yi = Y[static_cast<size_t>(i)];
    if (Yi != 0)
      ring::to_rational(ring::mul(Yi, Int128(ilp.row_scale[static_cast<size_t>(i)])), Int128(1), out.motzkin(i));
  }
  return out;
}

// The Motzkin certificate of A x = b from the final basis of the float LP that found it infeasible (phase 1 of
// strict_lp on the integer rows A_int, right-hand side B = d (L o b)): the Farkas vector of that basis computed exactly
// (basis_farkas_certificate on strict_lp in 64-bit integers), its first m entries y' (the t and u columns only add
// non-negative terms, as in read_strict), then y = L o y' as in check_rounded. nullopt if the t column's sums
// overflow 64 bits or the basis proves nothing.
std::optional<StrictFeasibility<Q>> basis_certificate(const IntegerLp& ilp, const std::vector<bool>& is_free,
                                                      const std::vector<Index>& S, const std::vector<i64>& B,
                                                      const std::vector<Index>& basis, const Vec<double>& y_approx) {
  const Index m = ilp.rows(), n = ilp.cols();
  for (Index i = 0; i < m; ++i) {  // strict_lp<i64> sums the strict columns: they must fit
    Int128 sum = 0;
    for (Index j : S) sum += ilp.A(i, j);
    if (sum > Int128(INT64_MAX) || sum < Int128(INT64_MIN)) return std::nullopt;
  }
  Mat<i64> A(m, n);
  for (Index i = 0; i < m; ++i)
    for (Index j = 0; j < n; ++j) A(i, j) = ilp.A(i, j);
  const LpProblem<i64> lp = strict_lp<i64>(A, is_free, S);
  IntegerLp strict;
  strict.A = IntMatrix<i64>(lp.A.rows(), lp.A.cols());
  for (Index i = 0; i < lp.A.rows(); ++i)
    for (Index j = 0; j < lp.A.cols(); ++j) strict.A(i, j) = lp.A(i, j);
  strict.b.assign(static_cast<size_t>(lp.A.rows()), S.empty() ? 0 : 1);  // row m: t + u = 1
  std::copy(B.begin(), B.end(), strict.b.begin());
  strict.row_scale.assign(strict.b.size(), 1);
  strict.c.assign(static_cast<size_t>(lp.A.cols()), 0);
  const std::optional<Vec<Q>> y = basis_farkas_certificate(strict, lp.is_free, basis, y_approx);
  if (!y) return std::nullopt;
  StrictFeasibility<Q> out;
  out.lps = 1;
  out.decided_by = DecidedBy::kFloatBasisCheckedExactly;
  out.motzkin = y->head(m);
  for (Index i = 0; i < m; ++i) out.motzkin(i) *= Q(static_cast<long>(ilp.row_scale[static_cast<size_t>(i)]));
  return out;
}

// The float LP on the integer rows, its point or certificate rounded to fractions and checked exactly;
// nullopt if the check fails, a number outgrows 128 bits or the float LP runs out of pivots. With
// `from_basis`, an infeasible float LP whose rounded certificate fails gets the exact one of its basis
// (basis_certificate). *float_feasible: whether the float LP found the system feasible. `lp`: the float LP of the
// integer rows (StrictSolver's hint_), whose first m entries of b this sets (no copy of its dense matrix per solve).
std::optional<StrictFeasibility<Q>> rounded_solve(const IntegerLp& ilp, LpProblem<double>& lp,
                                                  const std::vector<bool>& is_free, const std::vector<bool>& strict,
                                                  const std::vector<Index>& S, const Vec<Q>& b, bool* float_feasible,
                                                  Vec<double>* float_point, bool from_basis) {
  const Index m = ilp.rows(), n = ilp.cols();
  Z d;
  const std::optional<std::vector<i64>> B = integer_rhs(ilp, b, d);
  if (!B) return std::nullopt;
  for (Index i = 0; i < m; ++i) lp.b(i) = static_cast<double>((*B)[static_cast<size_t>(i)]);
  try {
    LpResult<double> r = solve_lp<double>(lp);  // the duals only where read_strict reads them (t* = 0): a dense solve
    // Out of pivots, or "unbounded" (t <= 1 bounds the LP: roundoff on nearly dependent rows, such as a normal
    // tilted by 1e-9): no point and no duals to read, so the verified LP decides.
    if (r.status != LpStatus::kOptimal && r.status != LpStatus::kInfeasible) return std::nullopt;
    if (r.status == LpStatus::kOptimal && !S.empty() && !is_positive(-r.value)) r.duals = optimal_duals(lp, r.basis);
    const StrictFeasibility<double> f = read_strict(r, m, n, S);
    *float_feasible = f.status == StrictStatus::kFeasible;
    if (float_point && *float_feasible) *float_point = f.x / d.get_d();  // A_int x = d (L o b): x / d solves A x = b
    std::optional<StrictFeasibility<Q>> out;
    try {
      out = check_rounded(ilp, f, is_free, strict, *B, d);
    } catch (const RingOverflow&) {
    }
    if (out || !from_basis || r.status != LpStatus::kInfeasible) return out;
    return basis_certificate(ilp, is_free, S, *B, r.basis, r.farkas);
  } catch (const BudgetExceeded&) {  // the float simplex cycled on a degenerate LP: the verified LP decides
    return std::nullopt;
  }
}

// Row i of A over its common denominator L_i (ring::to_common_denominator) in 64 bits: the rows of integer_lp
// (b = 0, no objective) read straight from A's non-zero entries, which for_each_entry(f) passes as
// f(i, j, a_ij). Nullopt if a number does not fit.
template <class ForEachEntry>
std::optional<IntegerLp> integer_rows(Index m, Index n, ForEachEntry&& for_each_entry) {
  IntegerLp out;
  out.A = IntMatrix<i64>(m, n);
  out.b.assign(static_cast<size_t>(m), 0);
  out.c.assign(static_cast<size_t>(n), 0);
  out.row_scale.assign(static_cast<size_t>(m), 1);
  std::vector<std::vector<std::pair<Index, const Q*>>> rows(static_cast<size_t>(m));
  for_each_entry([&](Index i, Index j, const Q& a) { rows[static_cast<size_t>(i)].emplace_back(j, &a); });
  std::vector<i64> scaled;
  try {
    for (Index i = 0; i < m; ++i) {
      const auto& row = rows[static_cast<size_t>(i)];
      scaled.resize(row.size());
      out.row_scale[static_cast<size_t>(i)] = ring::to_common_denominator<i64>(
          static_cast<Index>(row.size()), [&](Index t) -> const Q& { return *row[static_cast<size_t>(t)].second; },
          scaled.data());
      for (size_t t = 0; t < row.size(); ++t) out.A(i, row[t].first) = scaled[t];
    }
  } catch (const RingOverflow&) {
    return std::nullopt;
  }
  return out;
}

}  // namespace

template <class T>
StrictSystem<T> SparseStrictSystem<T>::dense(const Vec<T>& b) const {
  StrictSystem<T> s{Mat<T>::Zero(rows, cols), b.size() ? b : Vec<T>(Vec<T>::Zero(rows)), is_free, strict};
  for (const Entry<T>& e : entries) s.A(e.row, e.col) = e.value;
  return s;
}

template <class T>
template <class ForEachEntry>
void StrictSolver<T>::prepare(ForEachEntry&& for_each_entry) {
  for (Index j = 0; j < n_; ++j)
    if (flag(strict_, j)) strict_columns_.push_back(j);
  if constexpr (std::is_same_v<T, Q>) {
    if (arith_ != Arith::kExact) integer_ = integer_rows(m_, n_, for_each_entry);
    if (integer_) {
      using IntRows = Eigen::Matrix<i64, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
      const Eigen::Map<const IntRows> rows(integer_->A.row(0), m_, n_);  // (row 0: the entries' start)
      hint_ = strict_lp<double>(rows.cast<double>(), is_free_, strict_columns_);
      return;
    }
  }
  Mat<T> A = Mat<T>::Zero(m_, n_);
  for_each_entry([&A](Index i, Index j, const T& a) { A(i, j) = a; });
  if constexpr (std::is_same_v<T, Q>)
    A_ = std::move(A);
  else
    hint_ = strict_lp<T>(A, is_free_, strict_columns_);
}

template <class T>
StrictSolver<T>::StrictSolver(const StrictSystem<T>& s, Arith arith)
    : m_(s.A.rows()), n_(s.A.cols()), is_free_(s.is_free), strict_(s.strict), arith_(arith) {
  prepare([&s](auto&& f) {
    const T zero(0);  // exact comparison: a float entry below the sign tolerance still enters the LP
    for (Index j = 0; j < s.A.cols(); ++j)
      for (Index i = 0; i < s.A.rows(); ++i)
        if (s.A(i, j) != zero) f(i, j, s.A(i, j));
  });
}

template <class T>
StrictSolver<T>::StrictSolver(const SparseStrictSystem<T>& s, Arith arith)
    : m_(s.rows), n_(s.cols), is_free_(s.is_free), strict_(s.strict), arith_(arith) {
  prepare([&s](auto&& f) {
    for (const Entry<T>& e : s.entries) f(e.row, e.col, e.value);
  });
}

template <class T>
StrictFeasibility<T> StrictSolver<T>::solve(const Vec<T>& b) const {
  if constexpr (std::is_same_v<T, Q>) {
    bool float_feasible = false;
    if (std::optional<StrictFeasibility<Q>> r = solve_rounded(b, &float_feasible)) return std::move(*r);
  }
  return solve_unrounded(b);
}

template <class T>
StrictFeasibility<T> StrictSolver<T>::solve_unrounded(const Vec<T>& b) const {
  if constexpr (std::is_same_v<T, Q>) {
    if (!integer_) {
      LpProblem<Q> lp = strict_lp<Q>(A_, is_free_, strict_columns_);
      lp.b.head(m_) = b;
      return read_strict(arith_ == Arith::kExact ? solve_lp<Q>(lp, with_duals()) : solve_lp_verified(lp, with_duals()),
                         m_, n_, strict_columns_);
    }
    // The verified LP on the integer rows, right-hand side L o b: the same points; a certificate y' of these
    // rows is y = L o y' for A (y^T A = y'^T (L o A), y^T b = y'^T (L o b)).
    const std::vector<i64>& L = integer_->row_scale;
    LpProblem<Q> lp = strict_lp<Q>(integer_->convert<Q>({}, [](i64 v) { return Q(static_cast<long>(v)); }).A, is_free_,
                                   strict_columns_);
    for (Index i = 0; i < m_; ++i) lp.b(i) = b(i) * Q(static_cast<long>(L[static_cast<size_t>(i)]));
    StrictFeasibility<Q> out = read_strict(solve_lp_verified(lp, with_duals()), m_, n_, strict_columns_);
    for (Index i = 0; i < out.motzkin.size(); ++i) out.motzkin(i) *= Q(static_cast<long>(L[static_cast<size_t>(i)]));
    return out;
  } else {
    LpProblem<T> lp = hint_;
    lp.b.head(m_) = b;
    return read_strict(solve_lp<T>(lp, with_duals()), m_, n_, strict_columns_);
  }
}

template <class T>
std::optional<StrictFeasibility<T>> StrictSolver<T>::solve_rounded(const Vec<T>& b, bool* float_feasible,
                                                                   Vec<double>* float_point,
                                                                   FloatInfeasible infeasible) const {
  *float_feasible = false;
  if (float_point) *float_point = Vec<double>();
  if constexpr (std::is_same_v<T, Q>) {
    if (!integer_) return std::nullopt;
    return rounded_solve(*integer_, hint_, is_free_, strict_, strict_columns_, b, float_feasible, float_point,
                         infeasible == FloatInfeasible::kBasisCertificate);
  } else {
    return solve(b);
  }
}

template <class T>
StrictFeasibility<T> strict_feasibility(const StrictSystem<T>& sys, Arith arith) {
  return StrictSolver<T>(sys, arith).solve(sys.b);
}

template <class T>
StrictFeasibility<T> strict_feasibility(const SparseStrictSystem<T>& sys, Arith arith) {
  return StrictSolver<T>(sys, arith).solve(Vec<T>::Zero(sys.rows));
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

namespace {

// Motzkin's conditions on y^T A (by column) and y^T b: (y^T A)_j = 0 on free columns, >= 0 on the others, and
// y^T b < 0, or y^T b = 0 and (y^T A)_j > 0 on a strict column.
bool motzkin_conditions(const std::vector<Q>& yA, const Q& yb, const std::vector<bool>& is_free,
                        const std::vector<bool>& strict) {
  bool strict_positive = false;
  for (Index j = 0; j < static_cast<Index>(yA.size()); ++j) {
    const int s = sgn(yA[static_cast<size_t>(j)]);
    if (flag(is_free, j) ? s != 0 : s < 0) return false;
    strict_positive = strict_positive || (s > 0 && flag(strict, j));
  }
  return sgn(yb) < 0 || (sgn(yb) == 0 && strict_positive);
}

}  // namespace

bool verify_motzkin(const StrictSystem<Q>& sys, const Vec<Q>& y) {
  if (y.size() != sys.A.rows()) return false;
  std::vector<Q> yA(static_cast<size_t>(sys.A.cols()), Q(0));
  for (Index j = 0; j < sys.A.cols(); ++j)
    for (Index i = 0; i < y.size(); ++i) yA[static_cast<size_t>(j)] += y(i) * sys.A(i, j);
  return motzkin_conditions(yA, y.dot(sys.b), sys.is_free, sys.strict);
}

bool verify_motzkin(const SparseStrictSystem<Q>& sys, const Vec<Q>& b, const Vec<Q>& y) {
  if (y.size() != sys.rows || b.size() != sys.rows) return false;
  std::vector<Q> yA(static_cast<size_t>(sys.cols), Q(0));
  for (const Entry<Q>& e : sys.entries)
    if (sgn(y(e.row)) != 0) yA[static_cast<size_t>(e.col)] += y(e.row) * e.value;
  return motzkin_conditions(yA, y.dot(b), sys.is_free, sys.strict);
}

#define CONTACTCERT_STRICT_FEASIBILITY_INSTANTIATE(T)                                 \
  template struct SparseStrictSystem<T>;                                              \
  template class StrictSolver<T>;                                                     \
  template StrictFeasibility<T> strict_feasibility<T>(const StrictSystem<T>&, Arith); \
  template StrictFeasibility<T> strict_feasibility<T>(const SparseStrictSystem<T>&, Arith);
CONTACTCERT_STRICT_FEASIBILITY_INSTANTIATE(double)
CONTACTCERT_STRICT_FEASIBILITY_INSTANTIATE(Q)
CONTACTCERT_STRICT_FEASIBILITY_INSTANTIATE(Mpfr)
CONTACTCERT_STRICT_FEASIBILITY_INSTANTIATE(Interval)
#undef CONTACTCERT_STRICT_FEASIBILITY_INSTANTIATE

}  // namespace contactcert::exact
