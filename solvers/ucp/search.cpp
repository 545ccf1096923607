#include "solvers/ucp/search.h"

#include <optional>

#include "exact/interval_number.h"
#include "exact/mpfr_number.h"

namespace contactcert::solvers::ucp {

namespace {
using Index = Eigen::Index;

/// A Farkas vector learned at a dead node, with the columns where farkas^T A_j < 0: it proves every face
/// that fixes all of those columns to zero empty (the node's own fixings contain them).
template <class T>
struct Learned {
  std::vector<Index> negative;
  Vec<T> farkas;
  std::vector<Index> farkas_basis;
};

template <class T>
class Search {
 public:
  Search(const UcpInstance<T>& ucp, const SearchOptions& opts, SearchResult<T>& out)
      : ucp_(ucp), opts_(opts), out_(out), n_(ucp.n()) {}

  /// Explores the node with fixings (zx, zy); x (y) is a vertex of the X (Y) face if that face is unchanged
  /// from the parent. Returns kSolvable when a complementary pair was found (out.x, out.y), kJammed when every
  /// leaf below is dead, kUnknown when the node or time budget ran out.
  UcpStatus visit(long id, std::vector<bool>& zx, std::vector<bool>& zy, std::optional<FaceVertex<T>> x,
                  std::optional<FaceVertex<T>> y) {
    const Face<T> FX = make_face(ucp_.X, zx), FY = make_face(ucp_.Y, zy);
    if (!x) {
      const FaceLpStatus s = settle(id, Side::kX, FX, zx, y ? y->x : Vec<T>(Vec<T>::Zero(n_)), x);
      if (s != FaceLpStatus::kOptimal) return s == FaceLpStatus::kEmpty ? UcpStatus::kJammed : UcpStatus::kUnknown;
    }
    if (!y) {
      const FaceLpStatus s = settle(id, Side::kY, FY, zy, x->x, y);
      if (s != FaceLpStatus::kOptimal) return s == FaceLpStatus::kEmpty ? UcpStatus::kJammed : UcpStatus::kUnknown;
    }
    if (alternate_lps(FX, FY, *x, *y, opts_.heuristic.arith, opts_.node_rounds, out_.counters, opts_.deadline) ==
        BilinearStatus::kTimeLimit)
      return UcpStatus::kUnknown;
    Index branch = -1;
    T best = T(0), xTy = T(0);
    for (Index i = 0; i < n_; ++i) {
      if (exact::is_zero(x->x(i)) || exact::is_zero(y->x(i))) continue;
      const T p = x->x(i) * y->x(i);
      xTy += p;
      if (branch < 0 || exact::sign(T(p - best)) > 0) branch = i, best = p;
    }
    if (!out_.paired || exact::sign(T(xTy - out_.xTy)) < 0) out_.xTy = xTy, out_.paired = true;
    if (branch < 0) {  // x^T y = 0 exactly
      out_.x = x->x, out_.y = y->x, out_.xTy = T(0);
      return UcpStatus::kSolvable;
    }
    const long cx = new_node();
    if (cx < 0) return UcpStatus::kUnknown;
    const long cy = new_node();
    if (cy < 0) return UcpStatus::kUnknown;
    out_.tree[static_cast<std::size_t>(id)].branch = branch;
    out_.tree[static_cast<std::size_t>(id)].child_x_zero = cx;
    out_.tree[static_cast<std::size_t>(id)].child_y_zero = cy;
    const auto b = static_cast<std::size_t>(branch);
    zx[b] = true;
    const UcpStatus below_x = visit(cx, zx, zy, std::nullopt, y);
    zx[b] = false;
    if (below_x != UcpStatus::kJammed) return below_x;
    zy[b] = true;
    const UcpStatus below_y = visit(cy, zx, zy, x, std::nullopt);
    zy[b] = false;
    return below_y;
  }

 private:
  /// A new node's index, or -1 if the node or time budget has run out.
  long new_node() {
    if (static_cast<long>(out_.tree.size()) >= opts_.max_nodes || opts_.deadline.expired()) return -1;
    if (opts_.progress) opts_.progress(static_cast<long>(out_.tree.size()), out_.counters.lps);
    out_.tree.emplace_back();
    return static_cast<long>(out_.tree.size()) - 1;
  }

  /// Makes node `id` a dead leaf for `side` (kEmpty) if an earlier Farkas vector or the face LP proves the face
  /// empty; otherwise sets v to an optimal vertex of min c^T x over the face (kOptimal), unless the deadline
  /// passed inside the LP (kTimeLimit).
  FaceLpStatus settle(long id, Side side, const Face<T>& F, const std::vector<bool>& zero, const Vec<T>& c,
                      std::optional<FaceVertex<T>>& v) {
    auto& learned = learned_[side == Side::kX ? 0 : 1];
    SearchNode<T>& node = out_.tree[static_cast<std::size_t>(id)];
    for (const Learned<T>& l : learned) {
      bool covers = true;
      for (Index j : l.negative) covers = covers && zero[static_cast<std::size_t>(j)];
      if (covers) {
        node.side = side;
        node.farkas = l.farkas;
        node.farkas_basis = l.farkas_basis;
        ++out_.learned_prunes;
        return FaceLpStatus::kEmpty;
      }
    }
    FaceLpResult<T> r = minimize_on_face(F, c, opts_.heuristic.arith, out_.counters, opts_.deadline);
    if (r.status == FaceLpStatus::kTimeLimit) return FaceLpStatus::kTimeLimit;
    if (r.status == FaceLpStatus::kOptimal) {
      v = std::move(r.vertex);
      return FaceLpStatus::kOptimal;
    }
    const StandardPolyhedron<T>& P = side == Side::kX ? ucp_.X : ucp_.Y;
    Learned<T> l;
    l.farkas = r.farkas;
    l.farkas_basis = r.farkas_basis;
    const Vec<T> g = P.A.transpose() * r.farkas;
    for (Index j = 0; j < n_; ++j)
      if (exact::is_negative(g(j))) l.negative.push_back(j);
    out_.tree[static_cast<std::size_t>(id)].side = side;
    out_.tree[static_cast<std::size_t>(id)].farkas = r.farkas;
    out_.tree[static_cast<std::size_t>(id)].farkas_basis = std::move(r.farkas_basis);
    learned.push_back(std::move(l));
    return FaceLpStatus::kEmpty;
  }

  const UcpInstance<T>& ucp_;
  const SearchOptions& opts_;
  SearchResult<T>& out_;
  Index n_;
  std::vector<Learned<T>> learned_[2];
};

}  // namespace

template <class T>
SearchResult<T> complete_search(const UcpInstance<T>& ucp, const SearchOptions& opts, std::mt19937_64& rng) {
  SearchResult<T> out;
  const Face<T> FX = make_face(ucp.X, {}), FY = make_face(ucp.Y, {});
  std::optional<FaceVertex<T>> x0, y0;
  out.tree.assign(1, SearchNode<T>{});  // the root, which fixes nothing (inside every budget)
  std::vector<bool> zx(static_cast<std::size_t>(ucp.n()), false), zy = zx;
  if (opts.bilinear_first) {
    BilinearResult<T> b = bilinear(FX, FY, opts.heuristic, rng);
    out.counters = b.counters;
    out.pairs = b.pairs;
    if (b.status == BilinearStatus::kXEmpty || b.status == BilinearStatus::kYEmpty) {
      out.status = UcpStatus::kJammed;
      out.reason = b.status == BilinearStatus::kXEmpty ? "X is empty" : "Y is empty";
      out.tree[0].side = b.status == BilinearStatus::kXEmpty ? Side::kX : Side::kY;
      out.tree[0].farkas = b.farkas;
      out.nodes = 1;
      return out;
    }
    out.paired = b.x.x.size() > 0;  // not if the deadline passed inside Step 0
    out.xTy = b.xTy;
    if (b.status == BilinearStatus::kComplementary) {
      out.status = UcpStatus::kSolvable;
      out.reason = "bilinear algorithm";
      out.x = b.x.x, out.y = b.y.x;
      out.nodes = 1;
      out.tree.clear();
      return out;
    }
    if (b.status != BilinearStatus::kTimeLimit) x0 = b.x, y0 = b.y;
  }
  if (opts.deadline.expired())
    out.status = UcpStatus::kUnknown;
  else
    out.status = Search<T>(ucp, opts, out).visit(0, zx, zy, x0, y0);
  out.nodes = static_cast<long>(out.tree.size());
  switch (out.status) {
    case UcpStatus::kSolvable:
      out.reason = "complete search";
      out.tree.clear();
      break;
    case UcpStatus::kJammed:
      out.reason = jammed_reason(out.tree);
      break;
    case UcpStatus::kUnknown:
      out.reason = out.nodes >= opts.max_nodes
                       ? "node budget of " + std::to_string(opts.max_nodes) + " exhausted"
                       : opts.deadline.reached_text() + " after " + std::to_string(out.nodes) + " nodes";
      out.tree.clear();
      break;
  }
  return out;
}

template <class T>
UcpStatus search_subtree(const UcpInstance<T>& ucp, const SearchOptions& opts, SearchResult<T>& out, long id,
                         std::vector<bool>& zx, std::vector<bool>& zy) {
  return Search<T>(ucp, opts, out).visit(id, zx, zy, std::nullopt, std::nullopt);
}

template UcpStatus search_subtree<Q>(const UcpInstance<Q>&, const SearchOptions&, SearchResult<Q>&, long,
                                     std::vector<bool>&, std::vector<bool>&);
template SearchResult<double> complete_search<double>(const UcpInstance<double>&, const SearchOptions&,
                                                      std::mt19937_64&);
template SearchResult<Q> complete_search<Q>(const UcpInstance<Q>&, const SearchOptions&, std::mt19937_64&);
template SearchResult<exact::Mpfr> complete_search<exact::Mpfr>(const UcpInstance<exact::Mpfr>&, const SearchOptions&,
                                                                std::mt19937_64&);
template SearchResult<exact::Interval> complete_search<exact::Interval>(const UcpInstance<exact::Interval>&,
                                                                        const SearchOptions&, std::mt19937_64&);

}  // namespace contactcert::solvers::ucp
