#include "solvers/motion/uniqueness.h"

#include "exact/simplex.h"
#include "solvers/ucp/enumerate.h"

namespace contactcert::solvers::motion {
namespace {

using Index = Eigen::Index;
using exact::Mat;
using exact::Vec;

/// min sign * q_dot_k over the mode's face: variables [u (free, P's columns); x = (v_n, v_t^+, v_t^-) >= 0] with
/// P u - E x = J_alpha theta_alpha, E = [I 0 0; 0 I -I], and the mode's zero components of x dropped.
exact::LpProblem<Q> mode_lp(const ucp::QuasistaticProblem& p, const std::string& mode) {
  const Index nc = p.nc, m = p.P.cols();
  std::vector<Index> kept;
  for (Index i = 0; i < nc; ++i) {
    const char l = mode[static_cast<std::size_t>(i)];
    // 's' leaves x free; 'r' fixes all three; '+' keeps v_t^+; '-' keeps v_t^-.
    if (l == 's') kept.insert(kept.end(), {i, nc + i, 2 * nc + i});
    if (l == '+') kept.push_back(nc + i);
    if (l == '-') kept.push_back(2 * nc + i);
  }
  exact::LpProblem<Q> lp;
  lp.A = Mat<Q>::Zero(2 * nc, m + static_cast<Index>(kept.size()));
  lp.A.leftCols(m) = p.P;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const Index j = kept[k], col = m + static_cast<Index>(k);
    if (j < nc)
      lp.A(j, col) = -1;  // v_n
    else if (j < 2 * nc)
      lp.A(j, col) = -1;  // v_t^+ in row nc + i
    else
      lp.A(j - nc, col) = 1;  // v_t^- in row nc + i
  }
  lp.b = p.J_alpha_theta_alpha();
  lp.is_free.assign(static_cast<std::size_t>(lp.A.cols()), false);
  for (Index j = 0; j < m; ++j) lp.is_free[static_cast<std::size_t>(j)] = true;
  return lp;
}

}  // namespace

const char* uniqueness_name(UniquenessStatus s) {
  switch (s) {
    case UniquenessStatus::kUnique:
      return "unique";
    case UniquenessStatus::kNotUnique:
      return "not_unique";
    case UniquenessStatus::kUnknown:
      return "unknown";
  }
  return "unknown";
}

MotionUniqueness motion_uniqueness(const ucp::UcpProblem& problem, exact::Arith arith, long max_modes) {
  MotionUniqueness out;
  const ucp::QuasistaticProblem& p = *problem.quasistatic;
  const ucp::EnumerateResult e = ucp::solution_modes_by_prefix(problem, arith, max_modes);
  out.lps = e.lps;
  if (e.status == ucp::UcpStatus::kUnknown || !e.complete) return out;
  out.solution_modes = e.solution_modes;
  const auto seen = [&](const Vec<Q>& q) {
    for (const Vec<Q>& m : out.motions)
      if (m == q) return true;
    return false;
  };
  for (const std::string& mode : e.solution_modes) {
    exact::LpProblem<Q> lp = mode_lp(p, mode);
    for (Index k = 0; k < p.nq; ++k)
      for (int dir : {1, -1}) {
        lp.c = Vec<Q>::Zero(lp.A.cols());
        lp.c(k) = dir;
        const exact::LpResult<Q> r = exact::solve_lp(lp);
        ++out.lps;
        if (r.status == exact::LpStatus::kUnbounded) {
          out.unbounded = true;
          continue;
        }
        if (r.status != exact::LpStatus::kOptimal) continue;  // cannot happen for a solution mode
        const Vec<Q> q = r.x.head(p.nq);
        if (!seen(q)) {
          out.motions.push_back(q);
          out.modes.push_back(mode);
        }
      }
  }
  // Every LP optimum is the same point iff each component's min equals its max over every solution mode.
  out.status = out.unbounded || out.motions.size() > 1 ? UniquenessStatus::kNotUnique : UniquenessStatus::kUnique;
  return out;
}

}  // namespace contactcert::solvers::motion
