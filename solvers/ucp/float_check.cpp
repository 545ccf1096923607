#include "solvers/ucp/float_check.h"

#include <cassert>
#include <tuple>

#include "exact/integer_system.h"
#include "exact/rounded_check.h"
#include "solvers/ucp/farkas_rounding.h"

namespace contactcert::solvers::ucp {

namespace {

using Index = Eigen::Index;

/// A polyhedron's rows [A | b] as integers (exact::IntegerSystem), built from its integer rows on first use:
/// run(check) runs check(system) in 128-bit integers and, if a number does not fit, again in Z
/// (exact::with_exact_ring); rows that do not fit in 128 bits are built once and go straight to Z afterwards.
class IntegerRows {
 public:
  explicit IntegerRows(const IntegerPolyhedron& P) : P_(P) {}

  template <class F>
  auto run(F&& check) {
    if (too_wide_) return check(system<exact::Z>());
    return exact::with_exact_ring<Q, exact::Int128>([&]<class R>() { return check(system<R>()); });
  }

 private:
  template <class R>
  const exact::IntegerSystem<R>& system() {
    std::optional<exact::IntegerSystem<R>>& s = std::get<std::optional<exact::IntegerSystem<R>>>(systems_);
    if (!s) {
      try {
        s = exact::integer_system<R>(P_);
      } catch (const exact::RingOverflow&) {
        too_wide_ = true;
        throw;
      }
    }
    return *s;
  }

  const IntegerPolyhedron& P_;
  bool too_wide_ = false;  ///< the rows do not fit in 128 bits
  std::tuple<std::optional<exact::IntegerSystem<exact::Int128>>, std::optional<exact::IntegerSystem<exact::Z>>>
      systems_;
};

/// Walks the float tree depth first with the fixings of each node and proves its leaves (prove_leaves).
class LeafProver {
 public:
  LeafProver(const UcpProblem& problem, FloatTree& tree, const std::optional<SearchOptions>& repair, ProvenTree& out)
      : problem_(problem),
        farkas_(tree.farkas),
        repair_(repair),
        out_(out),
        rows_{IntegerRows(problem.rows().X), IntegerRows(problem.rows().Y)} {
    out_.result.tree = std::move(tree.nodes);
  }

  /// Proves the subtree of node `id`, whose fixings are (zx, zy); false stops the walk (out.result.status
  /// then says why).
  bool prove(long id, std::vector<bool>& zx, std::vector<bool>& zy) {
    const auto k = static_cast<std::size_t>(id);
    const SearchNode<Q> node = out_.result.tree[k];  // a copy: a repair appends to the tree
    if (node.is_leaf()) {
      const int s = node.side == Side::kX ? 0 : 1;
      if (std::optional<Vec<Q>> f = leaf_farkas(s, k, s == 0 ? zx : zy)) {
        out_.result.tree[k].farkas = std::move(*f);
        return true;
      }
      if (!repair_) {
        out_.result.status = UcpStatus::kUnknown;
        return false;
      }
      ++out_.leaves.repaired;
      out_.result.status = search_subtree(problem_.ucp(), *repair_, out_.result, id, zx, zy);
      return out_.result.status == UcpStatus::kJammed;
    }
    const auto b = static_cast<std::size_t>(node.branch);
    zx[b] = true;
    const bool ok = prove(node.child_x_zero, zx, zy);
    zx[b] = false;
    if (!ok) return false;
    zy[b] = true;
    const bool ok_y = prove(node.child_y_zero, zx, zy);
    zy[b] = false;
    return ok_y;
  }

 private:
  /// A Farkas vector already proven exactly, with the columns where farkas^T A_j < 0 (they must be fixed).
  struct Proven {
    Vec<Q> farkas;
    std::vector<Index> negative;
  };

  /// An exact Farkas vector for the face of side s (0: X, 1: Y) with the fixings `zero`, or nullopt if the
  /// face is not empty.
  std::optional<Vec<Q>> leaf_farkas(int s, std::size_t k, const std::vector<bool>& zero) {
    for (const Proven& p : proven_[s]) {
      bool covers = true;
      for (Index j : p.negative) covers = covers && zero[static_cast<std::size_t>(j)];
      if (covers) {
        ++out_.leaves.reused;
        return p.farkas;
      }
    }
    const Vec<double>& approx = farkas_[k];
    const std::vector<Index>& basis = out_.result.tree[k].farkas_basis;
    if (approx.size() == (s == 0 ? problem_.rows().X : problem_.rows().Y).rows()) {
      // The float vector rounded to fractions, else recomputed exactly from its LP's basis.
      bool rounded = false;
      std::optional<FarkasVector> f = rows_[s].run([&](const auto& system) {
        std::optional<FarkasVector> r = rounded_farkas(system, approx, zero);
        rounded = r.has_value();
        return r || basis.empty() ? r : basis_farkas(system, approx, basis, zero);
      });
      if (f) {
        ++(rounded ? out_.leaves.rounded : out_.leaves.basis);
        proven_[s].push_back({f->y, std::move(f->negative)});
        return std::move(f->y);
      }
    }
    const StandardPolyhedron<Q>& P = s == 0 ? problem_.ucp().X : problem_.ucp().Y;
    const FaceLpResult<Q> r =
        minimize_on_face(make_face(P, zero), Vec<Q>(Vec<Q>::Zero(P.A.cols())), Arith::kVerified, out_.result.counters);
    if (r.status != FaceLpStatus::kEmpty) return std::nullopt;
    ++out_.leaves.lp;
    Proven p{r.farkas, {}};
    const Vec<Q> g = P.A.transpose() * r.farkas;
    for (Index j = 0; j < g.size(); ++j)
      if (sgn(g(j)) < 0) p.negative.push_back(j);
    proven_[s].push_back(std::move(p));
    return r.farkas;
  }

  const UcpProblem& problem_;
  const std::vector<Vec<double>>& farkas_;
  const std::optional<SearchOptions>& repair_;
  ProvenTree& out_;
  IntegerRows rows_[2];
  std::vector<Proven> proven_[2];
};

}  // namespace

std::optional<std::pair<Vec<Q>, Vec<Q>>> exact_pair(const UcpProblem& problem, const Vec<double>& x_approx,
                                                    const Vec<double>& y_approx, const std::vector<bool>& x_zero,
                                                    const std::vector<bool>& y_zero, LpCounters& count) {
  for (std::size_t i = 0; i < x_zero.size(); ++i) assert(x_zero[i] || y_zero[i]);
  const Index n = problem.n();
  const auto point = [&](int side, const Vec<double>& approx, const std::vector<bool>& zero) -> std::optional<Vec<Q>> {
    const IntegerPolyhedron& P = side == 0 ? problem.rows().X : problem.rows().Y;
    // A vertex (the search's points are): its support columns are independent, so A_S x_S = b has one solution.
    // The rows become integers once, for that solve and for the rounded point below.
    IntegerRows rows(P);
    std::vector<Index> support;
    for (Index j = 0; j < n; ++j)
      if (!zero[static_cast<std::size_t>(j)]) support.push_back(j);
    if (std::optional<Vec<Q>> xs =
            rows.run([&](const auto& system) { return exact::unique_solution(system, support); })) {
      Vec<Q> x(n);  // zeros (a default rational is 0, cheaper than Zero())
      bool nonnegative = true;
      for (std::size_t t = 0; t < support.size(); ++t) {
        nonnegative = nonnegative && sgn((*xs)(static_cast<Index>(t))) >= 0;
        swap(x(support[t]), (*xs)(static_cast<Index>(t)));
      }
      if (nonnegative) return x;
    }
    if (std::optional<Vec<Q>> x =
            rows.run([&](const auto& system) { return exact::rounded_point(system, approx, zero); }))
      return x;
    const FaceLpResult<Q> r = minimize_on_face(make_face(side == 0 ? problem.ucp().X : problem.ucp().Y, zero),
                                               Vec<Q>(Vec<Q>::Zero(n)), Arith::kVerified, count);
    if (r.status != FaceLpStatus::kOptimal) return std::nullopt;
    return r.vertex.x;
  };
  std::optional<Vec<Q>> x = point(0, x_approx, x_zero);
  if (!x) return std::nullopt;
  std::optional<Vec<Q>> y = point(1, y_approx, y_zero);
  if (!y) return std::nullopt;
  return std::make_pair(std::move(*x), std::move(*y));
}

ProvenTree prove_leaves(const UcpProblem& problem, FloatTree tree, const std::optional<SearchOptions>& repair) {
  ProvenTree out;
  if (tree.nodes.empty()) return out;
  std::vector<bool> zx(static_cast<std::size_t>(problem.n()), false), zy = zx;
  out.result.status = UcpStatus::kJammed;
  LeafProver(problem, tree, repair, out).prove(0, zx, zy);
  if (out.result.status != UcpStatus::kJammed) out.result.tree.clear();
  out.result.nodes = static_cast<long>(out.result.tree.size());
  return out;
}

}  // namespace contactcert::solvers::ucp
