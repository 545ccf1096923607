#include "solvers/ucp/face_lp.h"

#include "exact/adjacent_vertices.h"
#include "exact/interval_number.h"
#include "exact/mpfr_number.h"
#include "exact/simplex.h"
#include "exact/verified_lp.h"

namespace contactcert::solvers::ucp {

namespace {
using Index = Eigen::Index;

template <class T>
Vec<T> expand(const Face<T>& F, const Vec<T>& xr) {
  Vec<T> x = Vec<T>::Zero(F.n);
  for (std::size_t k = 0; k < F.columns.size(); ++k) x(F.columns[k]) = xr(static_cast<Index>(k));
  return x;
}

/// The face LP on the path of `arith`, without duals (the search reads the vertex, its basis, or the Farkas
/// vector).
template <class T>
exact::LpResult<T> run_lp(const exact::LpProblem<T>& lp, Arith arith, const exact::Deadline& deadline) {
  exact::LpOptions options;
  options.deadline = deadline;
  if constexpr (std::is_same_v<T, Q>) {
    if (arith == Arith::kVerified) return exact::solve_lp_verified(lp, options);
    if (arith == Arith::kAdaptive) return exact::solve_lp_ladder(lp, exact::adaptive_ladder(), options);
  }
  (void)arith;
  return exact::solve_lp<T>(lp, options);
}
}  // namespace

template <class T>
Face<T> make_face(const StandardPolyhedron<T>& P, const std::vector<bool>& zero) {
  Face<T> F;
  F.n = P.A.cols();
  for (Index j = 0; j < F.n; ++j)
    if (zero.empty() || !zero[static_cast<std::size_t>(j)]) F.columns.push_back(j);
  F.reduced.A = Mat<T>(P.A.rows(), static_cast<Index>(F.columns.size()));
  for (std::size_t k = 0; k < F.columns.size(); ++k) F.reduced.A.col(static_cast<Index>(k)) = P.A.col(F.columns[k]);
  F.reduced.b = P.b;
  return F;
}

template <class T>
FaceLpResult<T> minimize_on_face(const Face<T>& F, const Vec<T>& c, Arith arith, LpCounters& count,
                                 const exact::Deadline& deadline) {
  ++count.lps;
  FaceLpResult<T> out;
  const Index m = F.reduced.A.rows(), nr = F.reduced.A.cols();
  if (m == 0) {  // the orthant itself: 0 is optimal for c >= 0
    out.status = FaceLpStatus::kOptimal;
    out.vertex.x = Vec<T>::Zero(F.n);
    return out;
  }
  exact::LpProblem<T> lp;
  lp.A = F.reduced.A;
  lp.b = F.reduced.b;
  lp.c = Vec<T>(nr);
  for (Index k = 0; k < nr; ++k) lp.c(k) = c(F.columns[static_cast<std::size_t>(k)]);
  exact::LpResult<T> r = run_lp(lp, arith, deadline);
  if (r.status == exact::LpStatus::kTimeLimit) {
    out.status = FaceLpStatus::kTimeLimit;
    return out;
  }
  if (r.status == exact::LpStatus::kInfeasible) {
    out.status = FaceLpStatus::kEmpty;
    out.farkas = r.farkas;
    for (Index v : r.basis)
      out.farkas_basis.push_back(v < nr ? F.columns[static_cast<std::size_t>(v)] : F.n + (v - nr));
    return out;
  }
  if (r.status != exact::LpStatus::kOptimal)
    throw std::logic_error("minimize_on_face: LP unbounded although c >= 0 and x >= 0");
  out.status = FaceLpStatus::kOptimal;
  out.vertex.x = expand(F, r.x);
  out.vertex.basis = r.basis;
  return out;
}

template <class T>
std::vector<FaceVertex<T>> adjacent_on_face(const Face<T>& F, const FaceVertex<T>& v, long max_bases,
                                            LpCounters& count) {
  ++count.adjacencies;
  std::vector<FaceVertex<T>> out;
  if (F.reduced.A.rows() == 0) return out;  // the orthant: only rays leave its vertex 0
  exact::LpProblem<T> lp;
  lp.A = F.reduced.A;
  lp.b = F.reduced.b;
  exact::AdjacencyOptions ao;
  ao.max_bases = max_bases;
  const exact::AdjacentResult<T> adj = exact::adjacent_vertices<T>(lp, v.basis, ao);
  if (adj.status != exact::AdjacencyStatus::kComplete) ++count.incomplete_adjacencies;
  for (const auto& e : adj.edges)
    if (e.bounded) out.push_back({expand(F, e.neighbour), e.neighbour_basis});
  return out;
}

#define CONTACTCERT_FACE_LP_INSTANTIATE(T)                                                        \
  template Face<T> make_face<T>(const StandardPolyhedron<T>&, const std::vector<bool>&);          \
  template FaceLpResult<T> minimize_on_face<T>(const Face<T>&, const Vec<T>&, Arith, LpCounters&, \
                                               const exact::Deadline&);                           \
  template std::vector<FaceVertex<T>> adjacent_on_face<T>(const Face<T>&, const FaceVertex<T>&, long, LpCounters&);
CONTACTCERT_FACE_LP_INSTANTIATE(double)
CONTACTCERT_FACE_LP_INSTANTIATE(Q)
CONTACTCERT_FACE_LP_INSTANTIATE(exact::Mpfr)
CONTACTCERT_FACE_LP_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_FACE_LP_INSTANTIATE

}  // namespace contactcert::solvers::ucp
