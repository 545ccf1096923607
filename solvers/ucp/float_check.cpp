#include "solvers/ucp/float_check.h"

#include <cassert>

#include "exact/rounded_certificate.h"

namespace contactcert::solvers::ucp {

namespace {

using Index = Eigen::Index;

/// A Farkas vector already proven exactly, with the columns where farkas^T A_j < 0 (they must be fixed).
struct Proven {
  Vec<Q> farkas;
  std::vector<Index> negative;
};

class LeafProver {
 public:
  LeafProver(const UcpInstance<Q>& ucp, std::vector<SearchNode<Q>>& tree, LpCounters& count)
      : ucp_(ucp), tree_(tree), count_(count) {}

  bool prove(long id, std::vector<bool>& zx, std::vector<bool>& zy) {
    SearchNode<Q>& node = tree_[static_cast<std::size_t>(id)];
    if (node.is_leaf()) {
      const bool x_side = node.side == Side::kX;
      return prove_leaf(node, x_side ? ucp_.X : ucp_.Y, x_side ? zx : zy, proven_[x_side ? 0 : 1]);
    }
    const auto b = static_cast<std::size_t>(node.branch);
    const long cx = node.child_x_zero, cy = node.child_y_zero;
    zx[b] = true;
    const bool ok = prove(cx, zx, zy);
    zx[b] = false;
    if (!ok) return false;
    zy[b] = true;
    const bool ok_y = prove(cy, zx, zy);
    zy[b] = false;
    return ok_y;
  }

 private:
  bool prove_leaf(SearchNode<Q>& node, const StandardPolyhedron<Q>& P, const std::vector<bool>& zero,
                  std::vector<Proven>& proven) {
    for (const Proven& p : proven) {
      bool covers = true;
      for (Index j : p.negative) covers = covers && zero[static_cast<std::size_t>(j)];
      if (covers) {
        node.farkas = p.farkas;
        return true;
      }
    }
    const FaceLpResult<Q> r =
        minimize_on_face(make_face(P, zero), Vec<Q>(Vec<Q>::Zero(P.A.cols())), Arith::kVerified, count_);
    if (r.status != FaceLpStatus::kEmpty) return false;
    Proven p{r.farkas, {}};
    const Vec<Q> g = P.A.transpose() * r.farkas;
    for (Index j = 0; j < g.size(); ++j)
      if (sgn(g(j)) < 0) p.negative.push_back(j);
    node.farkas = r.farkas;
    proven.push_back(std::move(p));
    return true;
  }

  const UcpInstance<Q>& ucp_;
  std::vector<SearchNode<Q>>& tree_;
  LpCounters& count_;
  std::vector<Proven> proven_[2];
};

}  // namespace

std::optional<std::pair<Vec<Q>, Vec<Q>>> exact_pair(const UcpInstance<Q>& ucp, const Vec<double>& x_approx,
                                                    const Vec<double>& y_approx, const std::vector<bool>& x_zero,
                                                    const std::vector<bool>& y_zero, LpCounters& count) {
  for (std::size_t i = 0; i < x_zero.size(); ++i) assert(x_zero[i] || y_zero[i]);
  const auto point = [&](const StandardPolyhedron<Q>& P, const Vec<double>& approx,
                         const std::vector<bool>& zero) -> std::optional<Vec<Q>> {
    if (std::optional<Vec<Q>> x = exact::round_and_check_point({P.A, P.b, {}, {}}, approx, zero)) return x;
    const FaceLpResult<Q> r =
        minimize_on_face(make_face(P, zero), Vec<Q>(Vec<Q>::Zero(ucp.n())), Arith::kVerified, count);
    if (r.status != FaceLpStatus::kOptimal) return std::nullopt;
    return r.vertex.x;
  };
  std::optional<Vec<Q>> x = point(ucp.X, x_approx, x_zero);
  if (!x) return std::nullopt;
  std::optional<Vec<Q>> y = point(ucp.Y, y_approx, y_zero);
  if (!y) return std::nullopt;
  return std::make_pair(std::move(*x), std::move(*y));
}

bool prove_leaves(const UcpInstance<Q>& ucp, std::vector<SearchNode<Q>>& tree, LpCounters& count) {
  if (tree.empty()) return false;
  std::vector<bool> zx(static_cast<std::size_t>(ucp.n()), false), zy = zx;
  return LeafProver(ucp, tree, count).prove(0, zx, zy);
}

}  // namespace contactcert::solvers::ucp
