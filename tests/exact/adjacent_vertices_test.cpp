#include "exact/adjacent_vertices.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "exact/linalg.h"
#include "exact/simplex_tableau.h"

namespace contactcert::exact {
namespace {

using Index = Eigen::Index;

Vec<Q> normalised(Vec<Q> d) {
  for (Index i = 0; i < d.size(); ++i)
    if (d(i) != 0) return d / Q(abs(d(i)));
  return d;
}

std::vector<std::string> keys(const std::vector<Vec<Q>>& vs) {
  std::vector<std::string> out;
  for (const Vec<Q>& v : vs) {
    std::string s;
    for (Index i = 0; i < v.size(); ++i) s += v(i).get_str() + " ";
    out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string key(const Vec<Q>& v) { return keys({v})[0]; }

/// dim {x : A x = 0, x_j = 0 off the union of the supports} = |S| - rank A_S.
Index face_dimension(const Mat<Q>& A, const Vec<Q>& u, const Vec<Q>& v) {
  std::vector<Index> S;
  for (Index i = 0; i < u.size(); ++i)
    if (u(i) != 0 || v(i) != 0) S.push_back(i);
  Mat<Q> AS(A.rows(), static_cast<Index>(S.size()));
  for (size_t k = 0; k < S.size(); ++k) AS.col(static_cast<Index>(k)) = A.col(S[k]);
  return static_cast<Index>(S.size()) - (S.empty() ? 0 : rank<Q>(AS));
}

/// Brute force: every subset of rank A columns that is a feasible basis; its vertex; all bases per vertex.
struct Vertices {
  std::map<std::string, Vec<Q>> vertex;
  std::map<std::string, std::vector<std::vector<Index>>> bases;
};

Vertices enumerate_vertices(const Mat<Q>& A, const Vec<Q>& b) {
  Vertices out;
  const Index n = A.cols(), r = rank<Q>(A);
  std::vector<bool> pick(static_cast<size_t>(n), false);
  std::fill(pick.begin(), pick.begin() + r, true);
  do {
    std::vector<Index> basis;
    for (Index j = 0; j < n; ++j)
      if (pick[static_cast<size_t>(j)]) basis.push_back(j);
    const std::optional<SimplexTableau<Q>> tab = SimplexTableau<Q>::from_basis(A, b, basis);
    if (!tab) continue;
    bool feasible = true;
    for (Index i = 0; i < tab->rows(); ++i) feasible = feasible && tab->rhs(i) >= 0;
    if (!feasible) continue;
    const Vec<Q> x = tab->primal();
    out.vertex[key(x)] = x;
    out.bases[key(x)].push_back(basis);
  } while (std::prev_permutation(pick.begin(), pick.end()));
  return out;
}

/// Checks adjacent_vertices at every vertex against brute force: neighbours = vertices u with a
/// one-dimensional minimal face containing u and v; rays = extreme rays d of {d >= 0 : A d = 0} with a
/// one-dimensional minimal face containing v + d. The same edges from every basis of the vertex.
void check_polyhedron(const Mat<Q>& A, const Vec<Q>& b, int* degenerate_vertices = nullptr) {
  const Vertices P = enumerate_vertices(A, b);
  Mat<Q> A1(A.rows() + 1, A.cols());
  A1 << A, Mat<Q>::Ones(1, A.cols());
  Vec<Q> b1 = Vec<Q>::Zero(A.rows() + 1);
  b1(A.rows()) = 1;
  const Vertices R = enumerate_vertices(A1, b1);  // extreme rays of the recession cone
  LpProblem<Q> problem{A, b, {}, {}};
  for (const auto& [k, v] : P.vertex) {
    std::vector<Vec<Q>> expected_neighbours, expected_rays;
    for (const auto& [k2, u] : P.vertex)
      if (k2 != k && face_dimension(A, u, v) == 1) expected_neighbours.push_back(u);
    for (const auto& [k2, d] : R.vertex)
      if (face_dimension(A, v, d) == 1) expected_rays.push_back(normalised(d));
    for (const std::vector<Index>& basis : P.bases.at(k)) {
      const AdjacentResult<Q> res = adjacent_vertices(problem, basis);
      ASSERT_EQ(res.status, AdjacencyStatus::kComplete);
      ASSERT_EQ(key(res.vertex), k);
      EXPECT_EQ(keys(res.neighbours()), keys(expected_neighbours)) << "vertex " << k;
      EXPECT_EQ(keys(res.rays()), keys(expected_rays)) << "vertex " << k;
      EXPECT_EQ(res.edges.size(), expected_neighbours.size() + expected_rays.size());
      for (const Edge<Q>& e : res.edges) {
        if (!e.bounded) continue;
        const std::optional<SimplexTableau<Q>> nb = SimplexTableau<Q>::from_basis(A, b, e.neighbour_basis);
        ASSERT_TRUE(nb);
        EXPECT_EQ(key(nb->primal()), key(e.neighbour));
      }
    }
    if (degenerate_vertices && P.bases.at(k).size() > 1) ++*degenerate_vertices;
  }
}

Mat<Q> mat(std::initializer_list<std::initializer_list<int>> rows) {
  Mat<Q> A(static_cast<Index>(rows.size()), static_cast<Index>(rows.begin()->size()));
  Index i = 0;
  for (const auto& row : rows) {
    Index j = 0;
    for (int v : row) A(i, j++) = v;
    ++i;
  }
  return A;
}

Vec<Q> vec(std::initializer_list<int> v) {
  Vec<Q> out(static_cast<Index>(v.size()));
  Index i = 0;
  for (int x : v) out(i++) = x;
  return out;
}

// Square pyramid, base [0,2]^2 at z = 0, apex (1,1,1): z + x + s1 = 2, z - x + s2 = 0, z + y + s3 = 2,
// z - y + s4 = 0. Variables (x, y, z, s1..s4). At the apex all four s are 0: a degenerate vertex.
TEST(AdjacentVertices, SquarePyramidApexHasFourNeighbours) {
  const Mat<Q> A = mat({{1, 0, 1, 1, 0, 0, 0}, {-1, 0, 1, 0, 1, 0, 0}, {0, 1, 1, 0, 0, 1, 0}, {0, -1, 1, 0, 0, 0, 1}});
  const Vec<Q> b = vec({2, 0, 2, 0});
  const LpProblem<Q> p{A, b, {}, {}};
  const AdjacentResult<Q> res = adjacent_vertices(p, {0, 1, 2, 3});
  ASSERT_EQ(res.vertex, (Vec<Q>(vec({1, 1, 1, 0, 0, 0, 0}))));
  EXPECT_EQ(res.status, AdjacencyStatus::kComplete);
  const std::vector<Vec<Q>> nb = res.neighbours();
  ASSERT_EQ(nb.size(), 4u);
  std::vector<std::string> corners;
  for (const Vec<Q>& v : nb) {
    EXPECT_EQ(v(2), 0);
    corners.push_back(v(0).get_str() + "," + v(1).get_str());
  }
  std::sort(corners.begin(), corners.end());
  EXPECT_EQ(corners, (std::vector<std::string>{"0,0", "0,2", "2,0", "2,2"}));
  EXPECT_TRUE(res.rays().empty());
  check_polyhedron(A, b);
  // The float path finds the same four neighbours.
  const AdjacentResult<double> f =
      adjacent_vertices(LpProblem<double>{to_double(A), to_double(b), {}, {}}, {0, 1, 2, 3});
  EXPECT_EQ(f.neighbours().size(), 4u);
  // A budget of one intermediate ray cannot see all edges of the apex; the single pivots remain.
  const AdjacentResult<Q> cut = adjacent_vertices(p, {0, 1, 2, 3}, {.max_bases = 1});
  EXPECT_EQ(cut.status, AdjacencyStatus::kBudgetExceeded);
  EXPECT_LT(cut.edges.size(), 4u);
}

// Unit cube x, y, z <= 1 cut by x + y - z <= 1 through the vertex (1,1,1) (cuts off (1,1,0)), and the cube
// with the redundant x + y + z <= 3 through (1,1,1).
TEST(AdjacentVertices, CubeCutThroughAVertex) {
  const Mat<Q> A = mat({{1, 0, 0, 1, 0, 0, 0}, {0, 1, 0, 0, 1, 0, 0}, {0, 0, 1, 0, 0, 1, 0}, {1, 1, -1, 0, 0, 0, 1}});
  const Vec<Q> b = vec({1, 1, 1, 1});
  const AdjacentResult<Q> res = adjacent_vertices(LpProblem<Q>{A, b, {}, {}}, {0, 1, 2, 6});
  ASSERT_EQ(res.vertex.head(3), (Vec<Q>(vec({1, 1, 1}))));
  EXPECT_EQ(res.neighbours().size(), 4u);  // (0,1,1), (1,0,1), (1,0,0), (0,1,0)
  int degenerate = 0;
  check_polyhedron(A, b, &degenerate);
  EXPECT_GE(degenerate, 1);
  const Mat<Q> A2 = mat({{1, 0, 0, 1, 0, 0, 0}, {0, 1, 0, 0, 1, 0, 0}, {0, 0, 1, 0, 0, 1, 0}, {1, 1, 1, 0, 0, 0, 1}});
  const Vec<Q> b2 = vec({1, 1, 1, 3});
  const AdjacentResult<Q> res2 = adjacent_vertices(LpProblem<Q>{A2, b2, {}, {}}, {0, 1, 2, 3});
  EXPECT_EQ(res2.neighbours().size(), 3u);
  check_polyhedron(A2, b2);
}

// An unbounded polyhedron: {x - y + s = 1}: vertices (1,0,0) and (0,0,1), rays.
TEST(AdjacentVertices, RaysOfAnUnboundedPolyhedron) {
  const Mat<Q> A = mat({{1, -1, 1}});
  const Vec<Q> b = vec({1});
  const AdjacentResult<Q> res = adjacent_vertices(LpProblem<Q>{A, b, {}, {}}, {0});
  EXPECT_EQ(res.neighbours().size(), 1u);
  ASSERT_EQ(res.rays().size(), 1u);
  EXPECT_EQ(res.rays()[0], (Vec<Q>(vec({1, 1, 0}))));
  check_polyhedron(A, b);
  // x_0 = -1 < 0 and a singular basis: statuses, no edges, no exception
  EXPECT_EQ(adjacent_vertices(LpProblem<Q>{A, vec({-1}), {}, {}}, {0}).status, AdjacencyStatus::kBasisNotFeasible);
  const AdjacentResult<Q> singular = adjacent_vertices(LpProblem<Q>{mat({{1, 1, 0}}), vec({1}), {}, {}}, {2});
  EXPECT_EQ(singular.status, AdjacencyStatus::kBasisNotFeasible);
  EXPECT_TRUE(singular.edges.empty());
}

// Random small polyhedra, degenerate by construction (b = A x0 with sparse x0, repeated rows), bounded and
// unbounded: every vertex against brute force.
TEST(AdjacentVertices, RandomDegeneratePolyhedraAgreeWithBruteForce) {
  std::mt19937_64 rng(4242);
  std::uniform_int_distribution<int> small(-2, 2), rows(1, 4), cols(3, 7), pct(0, 99);
  int degenerate = 0;
  for (int t = 0; t < 250; ++t) {
    const int m = rows(rng), n = std::max(cols(rng), m + 1);
    Mat<Q> A(m, n);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = pct(rng) < 25 ? 0 : small(rng);
    if (m >= 2 && pct(rng) < 20) A.row(m - 1) = A.row(0) + A.row(m - 2);
    if (pct(rng) < 50) A.row(0) = Mat<Q>::Ones(1, n);  // bounded polytope
    Vec<Q> x0 = Vec<Q>::Zero(n);
    for (int j = 0; j < n; ++j) x0(j) = pct(rng) < 50 ? 0 : 1 + pct(rng) % 2;
    check_polyhedron(A, Vec<Q>(A * x0), &degenerate);
    if (::testing::Test::HasFailure()) FAIL() << "case " << t;
  }
  EXPECT_GT(degenerate, 50);
}

}  // namespace
}  // namespace contactcert::exact
