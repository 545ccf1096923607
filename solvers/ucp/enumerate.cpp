#include "solvers/ucp/enumerate.h"

namespace contactcert::solvers::ucp {

namespace {
using Index = Eigen::Index;
}

EnumerateResult enumerate_modes(const UcpProblem& problem, Arith arith, long max_lps, const exact::Deadline& deadline,
                                const std::function<void(long, long)>& progress) {
  const UcpInstance<Q>& u = problem.ucp();
  const Index n = u.n(), mx = u.X.A.rows(), my = u.Y.A.rows();
  // X x Y as one block-diagonal polyhedron in R^{2n}.
  StandardPolyhedron<Q> XY;
  XY.A = Mat<Q>::Zero(mx + my, 2 * n);
  XY.A.block(0, 0, mx, n) = u.X.A;
  XY.A.block(mx, n, my, n) = u.Y.A;
  XY.b = Vec<Q>(mx + my);
  XY.b << u.X.b, u.Y.b;
  const bool modes = problem.quasistatic.has_value();
  const Index units = modes ? problem.quasistatic->nc : n;
  const int choices = modes ? 4 : 2;
  double total = 1;
  for (Index k = 0; k < units; ++k) total *= choices;
  EnumerateResult out;
  if (total > static_cast<double>(max_lps)) return out;
  std::vector<int> code(static_cast<std::size_t>(units), 0);
  LpCounters count;
  for (;;) {
    std::vector<bool> zero(static_cast<std::size_t>(2 * n), false);
    std::string name;
    auto fix_x = [&](Index j) { zero[static_cast<std::size_t>(j)] = true; };
    auto fix_y = [&](Index j) { zero[static_cast<std::size_t>(n + j)] = true; };
    for (Index k = 0; k < units; ++k) {
      const int c = code[static_cast<std::size_t>(k)];
      if (!modes) {
        c == 0 ? fix_x(k) : fix_y(k);
        name += c == 0 ? 'x' : 'y';
        continue;
      }
      const Index nc = units, vn = k, vp = nc + k, vm = 2 * nc + k;  // (v_n, v_t^+, v_t^-) and (c_n, s_t^+, s_t^-)
      switch (c) {
        case 0:
          fix_y(vn), fix_y(vp), fix_y(vm), name += 's';
          break;  // separate: c = 0
        case 1:
          fix_x(vn), fix_x(vp), fix_x(vm), name += 'r';
          break;  // roll: v = 0
        case 2:
          fix_x(vn), fix_x(vm), fix_y(vp), name += '+';
          break;  // slide +: c_t = -mu c_n
        default:
          fix_x(vn), fix_x(vp), fix_y(vm), name += '-';
          break;  // slide -: c_t = mu c_n
      }
    }
    const FaceLpResult<Q> r =
        minimize_on_face(make_face(XY, zero), Vec<Q>(Vec<Q>::Zero(2 * n)), arith, count, deadline);
    if (r.status == FaceLpStatus::kTimeLimit) {  // this mode is not tested
      --count.lps;
      out.complete = false;
      break;
    }
    if (r.status == FaceLpStatus::kOptimal) {
      if (out.solutions++ == 0) out.x = r.vertex.x.head(n), out.y = r.vertex.x.tail(n);
      out.solution_modes.push_back(name);
    }
    if (progress) progress(count.lps, count.lps);
    if (deadline.expired()) {
      out.complete = false;
      break;
    }
    Index k = 0;
    while (k < units && ++code[static_cast<std::size_t>(k)] == choices) code[static_cast<std::size_t>(k++)] = 0;
    if (k == units) break;
  }
  out.lps = count.lps;
  out.status = out.solutions > 0 ? UcpStatus::kSolvable : out.complete ? UcpStatus::kJammed : UcpStatus::kUnknown;
  return out;
}

}  // namespace contactcert::solvers::ucp
