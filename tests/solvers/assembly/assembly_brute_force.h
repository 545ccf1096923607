// A 4^k brute force of assembly stability (the tests' and the benchmark's reference), written apart from the solver:
// one LP per mode in its own formulation (Table 2's letters as rows on (vdot, c_n, c_t), no energy row, no
// relaxation), and the uniqueness argument for n..n (with a resting solution, every all-rolling solution is at rest:
// M vdot - g in range(J) and J^T vdot = 0 fix vdot). Without a resting solution the verdict is unstable whatever the
// modes do, so only stable assemblies enumerate.
#pragma once

#include <string>
#include <vector>

#include "exact/strict_feasibility.h"
#include "geometry/assembly.h"
#include "solvers/assembly/assembly_stability.h"

namespace contactcert::solvers::assembly::testing {

using geometry::Point2;

/// The brute force's model: rows built as A x = b with x = (vdot, per contact c_n, c_t, sigma, rho+, rho-).
struct Brute {
  const geometry::Assembly& a;
  Eigen::Index N3, k, cols;
  Eigen::Index cn(Eigen::Index i) const { return N3 + 5 * i; }

  /// d . (velocity of the contact point on `to` - on `from`) as a row over vdot: the point moves on body b with
  /// (a_x, a_y) + alpha (-r_y, r_x).
  Vec<Q> relative(const geometry::AssemblyContact& c, const Point2& d) const {
    Vec<Q> row = Vec<Q>::Zero(cols);
    for (const auto& [p, s] : {std::pair{c.from, -1}, std::pair{c.to, 1}}) {
      if (!p.movable()) continue;
      const Point2 r = c.point - a.bodies[p.index].com;
      const auto b = static_cast<Eigen::Index>(3 * p.index);
      row(b) += s * d.x;
      row(b + 1) += s * d.y;
      row(b + 2) += s * (d.y * r.x - d.x * r.y);
    }
    return row;
  }

  /// Whether mode (s l r n per contact) has a solution; `rest` adds vdot = 0.
  bool feasible(const std::string& mode, bool rest) const {
    std::vector<Vec<Q>> rows;
    std::vector<Q> rhs;
    struct {
      std::vector<bool> is_free, strict;
    } S;
    S.is_free.assign(static_cast<std::size_t>(cols), false);
    S.strict.assign(static_cast<std::size_t>(cols), false);
    for (Eigen::Index j = 0; j < N3; ++j) S.is_free[static_cast<std::size_t>(j)] = true;
    const auto unit = [&](Eigen::Index j, const Q& v) {
      Vec<Q> r = Vec<Q>::Zero(cols);
      r(j) = v;
      return r;
    };
    for (Eigen::Index i = 0; i < k; ++i) {
      const geometry::AssemblyContact& c = a.contacts[static_cast<std::size_t>(i)];
      const Point2 t{-c.normal.y, c.normal.x};
      const Eigen::Index n_ = cn(i), t_ = n_ + 1, sg = n_ + 2, r1 = n_ + 3, r2 = n_ + 4;
      S.is_free[static_cast<std::size_t>(t_)] = true;
      const char L = mode[static_cast<std::size_t>(i)];
      const Vec<Q> an = relative(c, c.normal), at = relative(c, t);
      if (L == 's') {
        S.strict[static_cast<std::size_t>(sg)] = true;
        rows.push_back(an - unit(sg, 1));
        rows.push_back(unit(n_, 1));
        rows.push_back(unit(t_, 1));
      } else {
        rows.push_back(an);
        if (L == 'n') {
          rows.push_back(at);
          rows.push_back(unit(n_, c.mu_s) - unit(t_, 1) - unit(r1, 1));
          rows.push_back(unit(n_, c.mu_s) + unit(t_, 1) - unit(r2, 1));
        } else {
          S.strict[static_cast<std::size_t>(sg)] = true;
          const int dir = L == 'l' ? 1 : -1;  // l: a_t > 0, c_t = -mu_k c_n; r: a_t < 0, c_t = mu_k c_n
          rows.push_back(Q(dir) * at - unit(sg, 1));
          rows.push_back(unit(t_, 1) + unit(n_, dir * c.mu_k));
        }
      }
      rhs.resize(rows.size(), Q(0));
    }
    // Newton-Euler: m a = load + sum of contact forces (c_n n + c_t t on `to`, minus on `from`), torques about com.
    for (std::size_t b = 0; b < a.bodies.size(); ++b) {
      const geometry::Body& B = a.bodies[b];
      Vec<Q> fx = unit(static_cast<Eigen::Index>(3 * b), B.mass),
             fy = unit(static_cast<Eigen::Index>(3 * b + 1), B.mass),
             tz = unit(static_cast<Eigen::Index>(3 * b + 2), B.inertia);
      for (Eigen::Index i = 0; i < k; ++i) {
        const geometry::AssemblyContact& c = a.contacts[static_cast<std::size_t>(i)];
        const Point2 t{-c.normal.y, c.normal.x};
        for (const auto& [p, s] : {std::pair{c.from, -1}, std::pair{c.to, 1}}) {
          if (!p.movable() || p.index != b) continue;
          const Point2 r = c.point - B.com;
          fx(cn(i)) -= s * c.normal.x, fx(cn(i) + 1) -= s * t.x;
          fy(cn(i)) -= s * c.normal.y, fy(cn(i) + 1) -= s * t.y;
          tz(cn(i)) -= s * geometry::cross(r, c.normal), tz(cn(i) + 1) -= s * geometry::cross(r, t);
        }
      }
      rows.push_back(fx), rhs.push_back(B.load_fx);
      rows.push_back(fy), rhs.push_back(B.load_fy);
      rows.push_back(tz), rhs.push_back(B.load_torque);
    }
    if (rest)
      for (Eigen::Index j = 0; j < N3; ++j) rows.push_back(unit(j, 1)), rhs.push_back(Q(0));
    // The rows by their non-zero entries (the verified LP's fast route), b = rhs.
    exact::SparseStrictSystem<Q> sparse{static_cast<Eigen::Index>(rows.size()), cols, {}, S.is_free, S.strict};
    Vec<Q> b(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      for (Eigen::Index j = 0; j < cols; ++j)
        if (sgn(rows[r](j)) != 0) sparse.entries.push_back({static_cast<Eigen::Index>(r), j, rows[r](j)});
      b(static_cast<Eigen::Index>(r)) = rhs[r];
    }
    return exact::StrictSolver<Q>(sparse).solve(b).status == exact::StrictStatus::kFeasible;
  }

  AssemblyVerdict verdict() const {
    const bool resting = feasible(std::string(static_cast<std::size_t>(k), 'n'), true);
    if (!resting) return AssemblyVerdict::kUnstable;
    std::string mode(static_cast<std::size_t>(k), 's');
    const std::string letters = "slrn";
    for (long m = 0; m < (1L << (2 * k)); ++m) {
      for (Eigen::Index i = 0; i < k; ++i) mode[static_cast<std::size_t>(i)] = letters[(m >> (2 * i)) & 3];
      if (mode == std::string(static_cast<std::size_t>(k), 'n')) continue;  // at rest (uniqueness)
      if (feasible(mode, false)) return AssemblyVerdict::kWeaklyStable;
    }
    return AssemblyVerdict::kStronglyStable;
  }
};

inline AssemblyVerdict brute_force(const geometry::Assembly& a) {
  const auto N3 = static_cast<Eigen::Index>(3 * a.bodies.size());
  const auto k = static_cast<Eigen::Index>(a.contacts.size());
  return Brute{a, N3, k, N3 + 5 * k}.verdict();
}

}  // namespace contactcert::solvers::assembly::testing
