#include "exact/strict_feasibility.h"

#include <type_traits>

#include "exact/simplex.h"
#include "exact/verified_lp.h"

namespace contactcert::exact {
namespace {

using Index = Eigen::Index;

bool flag(const std::vector<bool>& v, Index j) { return !v.empty() && v[static_cast<size_t>(j)]; }

template <class T>
LpResult<T> solve(const LpProblem<T>& lp, Arith arith) {
  if constexpr (std::is_same_v<T, Q>) {
    return arith == Arith::kExact ? solve_lp<Q>(lp) : solve_lp_verified(lp);
  } else {
    (void)arith;
    return solve_lp<double>(lp);
  }
}

}  // namespace

template <class T>
StrictFeasibility<T> strict_feasibility(const StrictSystem<T>& sys, Arith arith) {
  const Index m = sys.A.rows(), n = sys.A.cols();
  std::vector<Index> S;
  for (Index j = 0; j < n; ++j)
    if (flag(sys.strict, j)) S.push_back(j);
  const Index s = static_cast<Index>(S.size());

  // Columns: x (n), then t, sigma_1..sigma_s, u.  Rows: A x = b;  x_j - t - sigma_j = 0 (j in S);  t + u = 1.
  // Objective: min -t.  With no strict column this is plain feasibility of A x = b.
  const Index cols = s ? n + s + 2 : n, rows = s ? m + s + 1 : m;
  LpProblem<T> lp;
  lp.A = Mat<T>::Zero(rows, cols);
  lp.b = Vec<T>::Zero(rows);
  lp.A.topLeftCorner(m, n) = sys.A;
  lp.b.head(m) = sys.b;
  lp.is_free.assign(static_cast<size_t>(cols), false);
  for (Index j = 0; j < n; ++j) lp.is_free[static_cast<size_t>(j)] = flag(sys.is_free, j);
  const Index t = n, u = n + s + 1;
  if (s) {
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

  StrictFeasibility<T> out;
  out.lps = 1;
  const LpResult<T> r = solve(lp, arith);
  if (r.status == LpStatus::kInfeasible) {
    // The first m entries of the Farkas vector of the extended system already prove A x = b, x >= 0
    // infeasible (the extra rows only add non-negative terms), with y^T b < 0.
    out.motzkin = r.farkas.head(m);
    return out;
  }
  // Optimal (t <= 1 bounds the LP).
  if (!s || is_positive(T(-r.value))) {
    out.status = StrictStatus::kFeasible;
    out.x = r.x.head(n);
    return out;
  }
  // t* = 0: the duals (y1, y2, y3) give w = -y1 with w^T A >= y2 >= 0 on S, w^T b = y3 <= 0 and
  // sum(y2) >= 1 + y3, so w^T b < 0 or some (w^T A)_j > 0 on S.
  out.motzkin = -r.duals.head(m);
  return out;
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

template StrictFeasibility<double> strict_feasibility<double>(const StrictSystem<double>&, Arith);
template StrictFeasibility<Q> strict_feasibility<Q>(const StrictSystem<Q>&, Arith);

}  // namespace contactcert::exact
