#include "solvers/ucp/enumerate.h"

#include <algorithm>

namespace contactcert::solvers::ucp {

namespace {
using Index = Eigen::Index;

/// X x Y as one block-diagonal polyhedron in R^{2n}.
StandardPolyhedron<Q> product_polyhedron(const UcpInstance<Q>& u) {
  const Index n = u.n(), mx = u.X.A.rows(), my = u.Y.A.rows();
  StandardPolyhedron<Q> XY;
  XY.A = Mat<Q>::Zero(mx + my, 2 * n);
  XY.A.block(0, 0, mx, n) = u.X.A;
  XY.A.block(mx, n, my, n) = u.Y.A;
  XY.b = Vec<Q>(mx + my);
  XY.b << u.X.b, u.Y.b;
  return XY;
}

/// The units of a mode (the contacts of a quasistatic problem, else the n complementary indices) and their letters.
struct ModeLetters {
  bool modes;
  Index n, units;
  int choices;
  explicit ModeLetters(const UcpProblem& problem)
      : modes(problem.quasistatic.has_value()),
        n(problem.ucp().n()),
        units(modes ? problem.quasistatic->nc : n),
        choices(modes ? 4 : 2) {}

  /// Sets unit k's components of (x, y) in R^{2n} that its letter number c makes zero; returns the letter.
  char fix(Index k, int c, std::vector<bool>& zero) const {
    auto fix_x = [&](Index j) { zero[static_cast<std::size_t>(j)] = true; };
    auto fix_y = [&](Index j) { zero[static_cast<std::size_t>(n + j)] = true; };
    if (!modes) {
      c == 0 ? fix_x(k) : fix_y(k);
      return c == 0 ? 'x' : 'y';
    }
    const Index nc = units, vn = k, vp = nc + k, vm = 2 * nc + k;  // (v_n, v_t^+, v_t^-) and (c_n, s_t^+, s_t^-)
    switch (c) {
      case 0:
        fix_y(vn), fix_y(vp), fix_y(vm);
        return 's';  // separate: c = 0
      case 1:
        fix_x(vn), fix_x(vp), fix_x(vm);
        return 'r';  // roll: v = 0
      case 2:
        fix_x(vn), fix_x(vm), fix_y(vp);
        return '+';  // slide +: c_t = -mu c_n
      default:
        fix_x(vn), fix_x(vp), fix_y(vm);
        return '-';  // slide -: c_t = mu c_n
    }
  }
};

void finish(EnumerateResult& out, const LpCounters& count) {
  out.lps = count.lps;
  out.status = out.solutions > 0 ? UcpStatus::kSolvable : out.complete ? UcpStatus::kJammed : UcpStatus::kUnknown;
}

}  // namespace

EnumerateResult enumerate_modes(const UcpProblem& problem, Arith arith, long max_lps, const exact::Deadline& deadline,
                                const std::function<void(long, long)>& progress) {
  const UcpInstance<Q>& u = problem.ucp();
  const Index n = u.n();
  const StandardPolyhedron<Q> XY = product_polyhedron(u);
  const ModeLetters letters(problem);
  double total = 1;
  for (Index k = 0; k < letters.units; ++k) total *= letters.choices;
  EnumerateResult out;
  if (total > static_cast<double>(max_lps)) return out;
  std::vector<int> code(static_cast<std::size_t>(letters.units), 0);
  LpCounters count;
  for (;;) {
    std::vector<bool> zero(static_cast<std::size_t>(2 * n), false);
    std::string name;
    for (Index k = 0; k < letters.units; ++k) name += letters.fix(k, code[static_cast<std::size_t>(k)], zero);
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
    while (k < letters.units && ++code[static_cast<std::size_t>(k)] == letters.choices)
      code[static_cast<std::size_t>(k++)] = 0;
    if (k == letters.units) break;
  }
  finish(out, count);
  return out;
}

EnumerateResult solution_modes_by_prefix(const UcpProblem& problem, Arith arith, long max_lps,
                                         const exact::Deadline& deadline, PrefixEvidence* evidence) {
  const UcpInstance<Q>& u = problem.ucp();
  const Index n = u.n();
  const ModeLetters letters(problem);
  EnumerateResult out;
  LpCounters count;
  std::string name(static_cast<std::size_t>(letters.units), '?');
  // Whether the face of X (x_side) or Y with the zeros zero[offset, offset + n) is non-empty (false also when the
  // budget or the deadline stops the walk). With evidence: a point of it in `point`, or the Farkas vector of the
  // dead prefix whose letters are those of the units from k on.
  const auto non_empty = [&](bool x_side, const std::vector<bool>& zero, Index k, Vec<Q>& point) {
    if (!out.complete) return false;
    if (count.lps >= max_lps || deadline.expired()) return out.complete = false;
    const Index offset = x_side ? 0 : n;
    const auto from = zero.begin() + offset;
    const FaceLpResult<Q> r = minimize_on_face(make_face(x_side ? u.X : u.Y, std::vector<bool>(from, from + n)),
                                               Vec<Q>(Vec<Q>::Zero(n)), arith, count, deadline);
    if (r.status == FaceLpStatus::kTimeLimit) return out.complete = false;
    if (evidence && r.status == FaceLpStatus::kOptimal) point = r.vertex.x;
    if (evidence && r.status == FaceLpStatus::kEmpty)
      evidence->dead.push_back(
          {std::string(static_cast<std::size_t>(k), '?') + name.substr(static_cast<std::size_t>(k)), x_side, r.farkas});
    return r.status == FaceLpStatus::kOptimal;
  };
  // Depth first over the units, the last one decided first, so that the modes come in enumerate_modes's order.
  // A node with k units undecided has their complementarity relaxed: its face of X x Y contains the faces of all
  // its completions, so an empty one prunes them all. X and Y are uncoupled: the face is (face of X) x (face of
  // Y), each side decided by its own LP, and a side whose zeros a letter leaves as the parent's is non-empty (its
  // parent's point, px or py, is in it).
  const auto walk = [&](const auto& self, Index k, const std::vector<bool>& zero, const Vec<Q>& px,
                        const Vec<Q>& py) -> void {
    if (k == 0) {
      ++out.solutions;
      out.solution_modes.push_back(name);
      if (evidence) evidence->x.push_back(px), evidence->y.push_back(py);
      return;
    }
    for (int c = 0; c < letters.choices && out.complete; ++c) {
      std::vector<bool> child = zero;
      name[static_cast<std::size_t>(k - 1)] = letters.fix(k - 1, c, child);
      const bool same_x = std::equal(zero.begin(), zero.begin() + n, child.begin());
      const bool same_y = std::equal(zero.begin() + n, zero.end(), child.begin() + n);
      Vec<Q> cx = px, cy = py;
      if ((same_x || non_empty(true, child, k - 1, cx)) && (same_y || non_empty(false, child, k - 1, cy)))
        self(self, k - 1, child, cx, cy);
    }
  };
  const std::vector<bool> none(static_cast<std::size_t>(2 * n), false);
  Vec<Q> px, py;
  if (non_empty(true, none, letters.units, px) && non_empty(false, none, letters.units, py))
    walk(walk, letters.units, none, px, py);
  finish(out, count);
  return out;
}

}  // namespace contactcert::solvers::ucp
