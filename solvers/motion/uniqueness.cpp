#include "solvers/motion/uniqueness.h"

#include <algorithm>

#include "exact/simplex.h"
#include "solvers/ucp/enumerate.h"

namespace contactcert::solvers::motion {
namespace {

using Index = Eigen::Index;
using exact::Mat;
using exact::Vec;

/// The components of x = (v_n, v_t^+, v_t^-) that the mode leaves free, contact by contact: 's' all three, 'r'
/// none, '+' v_t^+, '-' v_t^-.
std::vector<Index> kept_components(Index nc, const std::string& mode) {
  std::vector<Index> kept;
  for (Index i = 0; i < nc; ++i) {
    const char l = mode[static_cast<std::size_t>(i)];
    if (l == 's') kept.insert(kept.end(), {i, nc + i, 2 * nc + i});
    if (l == '+') kept.push_back(nc + i);
    if (l == '-') kept.push_back(2 * nc + i);
  }
  return kept;
}

/// min sign * q_dot_k over the mode's face: variables [u (free, P's columns); x = (v_n, v_t^+, v_t^-) >= 0] with
/// P u - E x = J_alpha theta_alpha, E = [I 0 0; 0 I -I], and the mode's zero components of x dropped.
exact::LpProblem<Q> mode_lp(const ucp::QuasistaticProblem& p, const std::vector<Index>& kept) {
  const Index nc = p.nc, m = p.P.cols();
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
    case UniquenessStatus::kNoMotion:
      return "no_motion";
    case UniquenessStatus::kUnknown:
      return "unknown";
  }
  return "unknown";
}

MotionUniqueness motion_uniqueness(const ucp::UcpProblem& problem, exact::Arith arith, long max_modes, bool evidence) {
  MotionUniqueness out;
  const ucp::QuasistaticProblem& p = *problem.quasistatic;
  UniquenessEvidence ev;
  const ucp::EnumerateResult e =
      ucp::solution_modes_by_prefix(problem, arith, max_modes, {}, evidence ? &ev.tree : nullptr);
  out.lps = e.lps;
  if (e.status == ucp::UcpStatus::kUnknown || !e.complete) return out;
  out.solution_modes = e.solution_modes;
  if (e.solution_modes.empty()) {
    out.status = UniquenessStatus::kNoMotion;
    return out;
  }
  const std::size_t count = e.solution_modes.size();
  std::vector<std::vector<Index>> kept;
  for (const std::string& mode : e.solution_modes) kept.push_back(kept_components(p.nc, mode));
  const auto seen = [&](const Vec<Q>& q) {
    for (const Vec<Q>& m : out.motions)
      if (m == q) return true;
    return false;
  };
  // With evidence: a solution (u, x) of mode i's face, kept if its q_dot is not yet among the witnesses'.
  const auto witness = [&](std::size_t i, const Vec<Q>& z) {
    const Index m = p.P.cols();
    for (const UniquenessEvidence::Witness& w : ev.witnesses)
      if (w.u.head(p.nq) == z.head(p.nq)) return;
    Vec<Q> x = Vec<Q>::Zero(3 * p.nc);
    for (std::size_t k = 0; k < kept[i].size(); ++k) x(kept[i][k]) = z(m + static_cast<Index>(k));
    ev.witnesses.push_back({i, z.head(m), x});
  };
  // min and max of each q_dot_k over mode i's face: the distinct optima are real motions; with evidence the optimal
  // duals of each bound, and an unbounded component's vertex and vertex + ray (two q_dot).
  exact::LpOptions options;
  options.duals = evidence;
  const auto bound = [&](std::size_t i) {
    exact::LpProblem<Q> lp = mode_lp(p, kept[i]);
    UniquenessEvidence::Bound b{i, {}, {}};
    for (Index k = 0; k < p.nq; ++k)
      for (int dir : {1, -1}) {
        lp.c = Vec<Q>::Zero(lp.A.cols());
        lp.c(k) = dir;
        const exact::LpResult<Q> r = exact::solve_lp(lp, options);
        ++out.lps;
        if (r.status == exact::LpStatus::kUnbounded) {
          out.unbounded = true;
          if (evidence) witness(i, r.x), witness(i, Vec<Q>(r.x + r.ray));
          continue;
        }
        if (r.status != exact::LpStatus::kOptimal) continue;  // cannot happen for a solution mode
        const Vec<Q> q = r.x.head(p.nq);
        if (evidence) {
          (dir == 1 ? b.low : b.high).push_back(r.duals);
          witness(i, r.x);
        }
        if (!seen(q)) {
          out.motions.push_back(q);
          out.modes.push_back(e.solution_modes[i]);
        }
      }
    if (evidence) ev.bounds.push_back(std::move(b));
  };
  // First the widest faces (no other solution mode's face of X strictly contains it, the first of equal ones): a
  // mode whose free components are among another's has its face inside the other's, and every face lies in a widest
  // one, so if their bounds all meet at one q_dot, so do all.
  std::vector<std::vector<Index>> sorted = kept;
  for (std::vector<Index>& k : sorted) std::sort(k.begin(), k.end());
  const auto inside = [&](std::size_t i, std::size_t j) {
    return std::includes(sorted[j].begin(), sorted[j].end(), sorted[i].begin(), sorted[i].end()) &&
           (sorted[i] != sorted[j] || j < i);
  };
  for (std::size_t i = 0; i < count; ++i) {
    bool widest = true;
    for (std::size_t j = 0; j < count && widest; ++j) widest = j == i || !inside(i, j);
    if (widest) bound(i);
  }
  // Every LP optimum is the same point iff each component's min equals its max over every solution mode.
  if (!out.unbounded && out.motions.size() <= 1) {
    out.status = UniquenessStatus::kUnique;
    if (!out.motions.empty()) out.modes = {e.solution_modes[0]};  // the one motion is every mode's, the first's too
    if (evidence) ev.witnesses.clear(), out.evidence = std::move(ev);
    return out;
  }
  // Not unique: every solution mode's optima, in the modes' order, as the evidence.
  out.motions.clear(), out.modes.clear(), out.unbounded = false;
  ev.witnesses.clear(), ev.bounds.clear();
  for (std::size_t i = 0; i < count; ++i) bound(i);
  out.status = UniquenessStatus::kNotUnique;
  if (evidence) out.evidence = std::move(ev);
  return out;
}

}  // namespace contactcert::solvers::motion
