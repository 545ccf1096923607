#include "exact/rounded_check.h"

#include <cmath>
#include <tuple>
#include <type_traits>

namespace contactcert::exact {

namespace {

using Index = Eigen::Index;

/// An entry of the data ring S in the ring R of the check (a reference when they agree).
template <class R, class S>
decltype(auto) widen(const S& v) {
  if constexpr (std::is_same_v<R, S>)
    return (v);
  else
    return R(v);
}

}  // namespace

template <class R, class S>
std::optional<RoundedVector<R>> rounded_solution(const IntegerSystem<S>& s, const std::vector<S>& rhs,
                                                 const std::vector<Index>& columns, const std::vector<double>& values) {
  RoundedVector<R> r;
  if (!reconstruct_vector(values, r.X, r.D)) return std::nullopt;
  // The rows, X and the columns through pointers and the sizes in locals: the inner loop reads no member.
  const std::size_t k = columns.size();
  const Index* col = columns.data();
  const R* X = r.X.data();
  for (Index i = 0; i < s.rows(); ++i) {
    const S* a = s.A.row(i);
    R acc(0);
    for (std::size_t t = 0; t < k; ++t)
      if (X[t] != 0) acc = ring::add(acc, ring::mul(widen<R>(a[col[t]]), X[t]));
    if (acc != ring::mul(r.D, widen<R>(rhs[static_cast<std::size_t>(i)]))) return std::nullopt;
  }
  return r;
}

template <class R, class S>
std::vector<R> left_product(const IntegerSystem<S>& s, const std::vector<R>& Y) {
  const Index m = s.rows(), n = s.cols();
  std::vector<R> t(static_cast<std::size_t>(n), R(0));
  R* out = t.data();
  for (Index i = 0; i < m; ++i) {
    // A copy of a fixed-width y_i (so that the writes to t cannot alias it), a reference to a GMP one.
    std::conditional_t<std::is_trivially_copyable_v<R>, const R, const R&> yi = Y[static_cast<std::size_t>(i)];
    if (yi == 0) continue;
    const S* a = s.A.row(i);
    for (Index j = 0; j < n; ++j) out[j] = ring::add(out[j], ring::mul(widen<R>(a[j]), yi));
  }
  return t;
}

namespace {

/// round_and_check_optimal in 128-bit integers (throws RingOverflow).
std::optional<OptimalCertificate> check_optimal(const LpProblem<Q>& problem, const IntegerLp& ilp,
                                                const std::vector<Index>& basis, const Vec<double>& x_approx,
                                                const Vec<double>& y_approx) {
  const Index m = problem.rows(), n = problem.cols();
  // x_B ~ X / D with A_B X = D b in the integer rows.
  std::vector<double> xb(basis.size());
  for (std::size_t t = 0; t < basis.size(); ++t) xb[t] = x_approx(basis[t]);
  const std::optional<RoundedVector<Int128>> x = rounded_solution<Int128>(ilp, ilp.b, basis, xb);
  if (!x) return std::nullopt;
  for (std::size_t t = 0; t < basis.size(); ++t)
    if (x->X[t] < 0 && !problem.free(basis[t])) return std::nullopt;
  // Duals of the integer LP ~ Y / E: (A_int^T Y)_j <= E c_int_j, equality on basic and free columns.
  std::vector<Int128> Y;
  Int128 E;
  if (!reconstruct_vector(std::vector<double>(y_approx.data(), y_approx.data() + m), Y, E)) return std::nullopt;
  const std::vector<Int128> t = left_product(ilp, Y);
  std::vector<bool> in_basis(static_cast<std::size_t>(n), false);
  for (Index j : basis) in_basis[static_cast<std::size_t>(j)] = true;
  for (Index j = 0; j < n; ++j) {
    const Int128 lhs = t[static_cast<std::size_t>(j)], rhs = ring::mul(E, Int128(ilp.c[static_cast<std::size_t>(j)]));
    const bool tight = in_basis[static_cast<std::size_t>(j)] || problem.free(j);
    if (tight ? lhs != rhs : lhs > rhs) return std::nullopt;
  }
  // Those of the problem: y_i = row_scale_i Y_i / (E objective_scale).
  OptimalCertificate cert;
  cert.x = Vec<Q>::Zero(n);
  for (std::size_t s = 0; s < basis.size(); ++s) ring::to_rational(x->X[s], x->D, cert.x(basis[s]));
  cert.y = Vec<Q>(m);
  for (Index i = 0; i < m; ++i) {
    ring::to_rational(Y[static_cast<std::size_t>(i)], E, cert.y(i));
    const std::int64_t L = ilp.row_scale[static_cast<std::size_t>(i)];
    if (L != 1 || ilp.objective_scale != 1) {
      Q f;
      ring::to_rational(Int128(L), Int128(ilp.objective_scale), f);
      cert.y(i) *= f;
    }
  }
  cert.value = 0;
  if (problem.c.size() > 0)
    for (Index j : basis) cert.value += problem.c(j) * cert.x(j);
  return cert;
}

/// Column v of the integer LP's phase-1 matrix [A_int | S_int], S_int = diag(row_scale o sign b) (the rows of
/// problem's [A | S] times row_scale), as the terms of the equation (B^T u)_k = rhs for v = basis[k].
template <class R>
SparseEquation<R> basis_column(const IntegerLp& ilp, Index v) {
  SparseEquation<R> eq;
  if (v < ilp.cols()) {
    for (Index i = 0; i < ilp.rows(); ++i)
      if (ilp.A(i, v) != 0) eq.terms.emplace_back(i, R(ilp.A(i, v)));
  } else {
    const auto i = static_cast<std::size_t>(v - ilp.cols());
    eq.terms.emplace_back(v - ilp.cols(), R(ilp.b[i] < 0 ? -ilp.row_scale[i] : ilp.row_scale[i]));
  }
  return eq;
}

/// The solution U / D (D > 0) of B^T u = rhs, B the basis columns of [A_int | S_int]; nullopt if B is singular or
/// not square.
template <class R>
std::optional<RoundedVector<R>> basis_dual_solve(const IntegerLp& ilp, const std::vector<Index>& basis,
                                                 const std::vector<R>& rhs) {
  const Index m = ilp.rows();
  if (static_cast<Index>(basis.size()) != m) return std::nullopt;
  std::vector<SparseEquation<R>> eqs;
  for (std::size_t k = 0; k < basis.size(); ++k) {
    eqs.push_back(basis_column<R>(ilp, basis[k]));
    eqs.back().rhs = rhs[k];
  }
  RoundedVector<R> u;
  if (solve_sparse_square(eqs, m, u.X, u.D, CoreSolve::kLifted) != SolutionKind::kUnique) return std::nullopt;
  return u;
}

/// basis_dual_solve on the rows `support` alone (u_i = 0 elsewhere): its |support| basis equations chosen by Gaussian
/// elimination in doubles (the largest pivot per unknown), solved exactly, and the solution kept only if it meets
/// every basis equation, so that it is the solution of basis_dual_solve (u = B^-T rhs is unique). nullopt if no
/// square choice is regular in doubles or the solution is not B^-T rhs (its support is larger).
template <class R>
std::optional<RoundedVector<R>> support_dual_solve(const IntegerLp& ilp, const std::vector<Index>& basis,
                                                   const std::vector<R>& rhs, const std::vector<Index>& support) {
  const Index m = ilp.rows(), s = static_cast<Index>(support.size());
  std::vector<Index> unknown(static_cast<std::size_t>(m), -1);
  for (Index t = 0; t < s; ++t) unknown[static_cast<std::size_t>(support[static_cast<std::size_t>(t)])] = t;
  // Every basis equation on the support; one with no term there must have a zero right-hand side.
  std::vector<SparseEquation<R>> eqs;
  std::vector<std::tuple<Index, Index, double>> entries;  // (equation, unknown, coefficient) in doubles
  for (std::size_t k = 0; k < basis.size(); ++k) {
    SparseEquation<R> eq;
    for (const auto& [i, a] : basis_column<std::int64_t>(ilp, basis[k]).terms) {
      const Index t = unknown[static_cast<std::size_t>(i)];
      if (t < 0) continue;
      eq.terms.emplace_back(t, R(a));
      entries.emplace_back(static_cast<Index>(eqs.size()), t, static_cast<double>(a));
    }
    eq.rhs = rhs[k];
    if (!eq.terms.empty()) {
      eqs.push_back(std::move(eq));
    } else if (ring::sign(rhs[k]) != 0) {
      return std::nullopt;
    }
  }
  const Index ne = static_cast<Index>(eqs.size());
  if (ne < s) return std::nullopt;
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(ne, s);
  for (const auto& [e, t, a] : entries) E(e, t) = a;
  std::vector<bool> chosen(static_cast<std::size_t>(ne), false);
  std::vector<SparseEquation<R>> square;
  for (Index c = 0; c < s; ++c) {
    Index p = -1;
    for (Index e = 0; e < ne; ++e)
      if (!chosen[static_cast<std::size_t>(e)] && (p < 0 || std::abs(E(e, c)) > std::abs(E(p, c)))) p = e;
    if (p < 0 || std::abs(E(p, c)) < 1e-9 * (1 + E.row(p).cwiseAbs().maxCoeff())) return std::nullopt;
    chosen[static_cast<std::size_t>(p)] = true;
    square.push_back(eqs[static_cast<std::size_t>(p)]);
    for (Index e = 0; e < ne; ++e)
      if (!chosen[static_cast<std::size_t>(e)] && E(e, c) != 0) E.row(e) -= (E(e, c) / E(p, c)) * E.row(p);
  }
  RoundedVector<R> v;
  if (solve_sparse_square(square, s, v.X, v.D, CoreSolve::kLifted) != SolutionKind::kUnique) return std::nullopt;
  RoundedVector<R> u{std::vector<R>(static_cast<std::size_t>(m), R(0)), v.D};
  for (Index t = 0; t < s; ++t)
    u.X[static_cast<std::size_t>(support[static_cast<std::size_t>(t)])] = v.X[static_cast<std::size_t>(t)];
  for (std::size_t e = 0; e < eqs.size(); ++e) {  // the equations not chosen hold too: u is B^-T rhs
    R sum(0);
    for (const auto& [t, a] : eqs[e].terms) sum = ring::add(sum, ring::mul(a, v.X[static_cast<std::size_t>(t)]));
    if (!(sum == ring::mul(eqs[e].rhs, v.D))) return std::nullopt;
  }
  return u;
}

}  // namespace

std::optional<Vec<Q>> basis_farkas_certificate(const LpProblem<Q>& problem, const IntegerLp& ilp,
                                               const std::vector<Index>& basis) {
  if (ilp.rows() != problem.rows() || ilp.cols() != problem.cols()) return std::nullopt;
  return basis_farkas_certificate(ilp, problem.is_free, basis, {});
}

std::optional<Vec<Q>> basis_farkas_certificate(const IntegerLp& ilp, const std::vector<bool>& is_free,
                                               const std::vector<Index>& basis, const Vec<double>& y_approx) {
  const Index m = ilp.rows(), n = ilp.cols();
  const auto free_column = [&is_free](Index j) { return !is_free.empty() && is_free[static_cast<std::size_t>(j)]; };
  for (Index v : basis)
    if (v < 0 || v >= n + m) return std::nullopt;
  return with_exact_ring<Q, Int128>([&]<class R>() -> std::optional<Vec<Q>> {
    std::vector<R> cB;
    for (Index v : basis) cB.push_back(R(v >= n ? 1 : 0));
    std::optional<RoundedVector<R>> u;
    if (y_approx.size() == m) {  // first on the rows where the float Farkas vector is not zero
      const double tol = 1e-9 * y_approx.cwiseAbs().maxCoeff();
      std::vector<Index> support;
      for (Index i = 0; i < m; ++i)
        if (std::abs(y_approx(i)) > tol) support.push_back(i);
      if (static_cast<Index>(support.size()) < m) u = support_dual_solve<R>(ilp, basis, cB, support);
    }
    if (!u) u = basis_dual_solve<R>(ilp, basis, cB);
    if (!u) return std::nullopt;
    // farkas = -(row_scale o U) / D: farkas^T A = -U^T A_int / D >= 0 (== 0 on free columns), farkas^T b < 0.
    const std::vector<R> t = left_product(ilp, u->X);
    for (Index j = 0; j < n; ++j) {
      const int s = -ring::sign(t[static_cast<std::size_t>(j)]);
      if (free_column(j) ? s != 0 : s < 0) return std::nullopt;
    }
    R ub(0);
    for (Index i = 0; i < m; ++i)
      ub = ring::add(ub, ring::mul(u->X[static_cast<std::size_t>(i)], R(ilp.b[static_cast<std::size_t>(i)])));
    if (ring::sign(ub) <= 0) return std::nullopt;
    Vec<Q> farkas(m);
    for (Index i = 0; i < m; ++i)
      ring::to_rational(ring::mul(u->X[static_cast<std::size_t>(i)], R(-ilp.row_scale[static_cast<std::size_t>(i)])),
                        u->D, farkas(i));
    return farkas;
  });
}

std::optional<OptimalCertificate> round_and_check_optimal(const LpProblem<Q>& problem, const IntegerLp& ilp,
                                                          const std::vector<Index>& basis, const Vec<double>& x_approx,
                                                          const Vec<double>& y_approx) {
  const Index m = problem.rows(), n = problem.cols();
  if (x_approx.size() != n || y_approx.size() != m || ilp.rows() != m || ilp.cols() != n) return std::nullopt;
  for (Index j : basis)
    if (j < 0 || j >= n) return std::nullopt;
  try {
    return check_optimal(problem, ilp, basis, x_approx, y_approx);
  } catch (const RingOverflow&) {  // too large for the fast check: the caller pivots exactly
    return std::nullopt;
  }
}

template <class R>
std::optional<Vec<Q>> rounded_point(const IntegerSystem<R>& s, const Vec<double>& x_approx,
                                    const std::vector<bool>& zero) {
  std::vector<Index> support;
  std::vector<double> xs;
  for (Index j = 0; j < s.cols(); ++j)
    if (!zero[static_cast<std::size_t>(j)]) support.push_back(j), xs.push_back(x_approx(j));
  const std::optional<RoundedVector<R>> x = rounded_solution<R>(s, s.b, support, xs);
  if (!x) return std::nullopt;
  for (const R& v : x->X)
    if (ring::sign(v) < 0) return std::nullopt;
  Vec<Q> out = Vec<Q>::Zero(s.cols());
  for (std::size_t t = 0; t < support.size(); ++t)
    if (ring::sign(x->X[t]) != 0) ring::to_rational(x->X[t], x->D, out(support[t]));
  return out;
}

#define CONTACTCERT_ROUNDED_CHECK_INSTANTIATE(R, S)                                                           \
  template std::optional<RoundedVector<R>> rounded_solution<R, S>(                                            \
      const IntegerSystem<S>&, const std::vector<S>&, const std::vector<Index>&, const std::vector<double>&); \
  template std::vector<R> left_product<R, S>(const IntegerSystem<S>&, const std::vector<R>&);
CONTACTCERT_ROUNDED_CHECK_INSTANTIATE(Int128, std::int64_t)
CONTACTCERT_ROUNDED_CHECK_INSTANTIATE(Int128, Int128)
CONTACTCERT_ROUNDED_CHECK_INSTANTIATE(Z, Z)
CONTACTCERT_ROUNDED_CHECK_INSTANTIATE(Z, std::int64_t)
#undef CONTACTCERT_ROUNDED_CHECK_INSTANTIATE

template std::optional<Vec<Q>> rounded_point<Int128>(const IntegerSystem<Int128>&, const Vec<double>&,
                                                     const std::vector<bool>&);
template std::optional<Vec<Q>> rounded_point<Z>(const IntegerSystem<Z>&, const Vec<double>&, const std::vector<bool>&);

}  // namespace contactcert::exact
