// IntMatrix, the one fraction-free elimination: row echelon form with primitive rows, rank, kernel, make-primitive
// and the unique solution (dense, and square with a sparse front end), in Int128 with the restart in GMP integers on
// overflow; its row operations; its sparse form SparseIntMatrix.
#include "exact/int_matrix.h"

#include <gtest/gtest.h>

namespace contactcert::exact {
namespace {

using Index = Eigen::Index;

template <class R>
IntMatrix<R> matrix(Index rows, Index cols, std::initializer_list<long> entries) {
  IntMatrix<R> M(rows, cols);
  Index at = 0;
  for (long e : entries) {
    ring::from_integer(e, M(at / cols, at % cols));
    ++at;
  }
  return M;
}

template <class R>
Z row_gcd(const IntMatrix<R>& M, Index i) {
  Z g = 0;
  for (Index j = 0; j < M.cols(); ++j) g = gcd(g, ring::to_field<Z>(M(i, j)));
  return g;
}

// A z = 0 for every row z of K (A's entries as given, before any scaling).
template <class R>
void expect_kernel(const Mat<Q>& A, const IntMatrix<R>& K) {
  for (Index r = 0; r < K.rows(); ++r)
    for (Index i = 0; i < A.rows(); ++i) {
      Q s = 0;
      for (Index j = 0; j < A.cols(); ++j) s += A(i, j) * ring::to_field<Q>(K(r, j));
      EXPECT_EQ(s, 0) << "kernel row " << r << ", row " << i;
    }
}

TEST(IntMatrix, MakePrimitiveKeepsSignsAndZeroRows) {
  IntMatrix<Int128> M = matrix<Int128>(3, 4, {6, -4, 0, 10, 0, 0, 0, 0, -6, 4, 9, -3});
  M.make_primitive();
  // gcd(6, 4, 9, 3) = 1: the last row is unchanged.
  const IntMatrix<Int128> want = matrix<Int128>(3, 4, {3, -2, 0, 5, 0, 0, 0, 0, -6, 4, 9, -3});
  for (Index i = 0; i < 3; ++i)
    for (Index j = 0; j < 4; ++j) EXPECT_TRUE(M(i, j) == want(i, j)) << i << "," << j;
}

TEST(IntMatrix, EchelonRankAndPrimitiveRows) {
  // Row 2 = row 0 + 2 row 1: rank 2, pivots in columns 0 and 1 (column 2 = column 0 + column 1 in every row).
  IntMatrix<Z> M = matrix<Z>(3, 4, {2, 4, 6, 8, 1, -1, 0, 3, 4, 2, 6, 14});
  EXPECT_EQ(M.rank(), 2);
  const std::vector<Index> pivots = M.echelon();
  ASSERT_EQ(pivots, (std::vector<Index>{0, 1}));
  for (Index r = 0; r < 2; ++r) {
    EXPECT_EQ(row_gcd(M, r), 1) << r;
    EXPECT_EQ(M(r, 1 - r), 0) << r;  // Gauss-Jordan: zero in the other pivot column
  }
  for (Index j = 0; j < 4; ++j) EXPECT_EQ(M(2, j), 0);
  // Reduced row echelon form, row over pivot: [1 0 1 10/3; 0 1 1 1/3].
  EXPECT_EQ(Q(M(0, 3)) / Q(M(0, 0)), Q(10, 3));
  EXPECT_EQ(Q(M(1, 3)) / Q(M(1, 1)), Q(1, 3));
}

TEST(IntMatrix, KernelIsPrimitiveWithPositiveFreeEntries) {
  Mat<Q> A(2, 4);
  A << 2, 4, 6, 8, 1, -1, 0, 3;
  const IntMatrix<Int128> M =
      IntMatrix<Int128>::primitive_rows(A.rows(), A.cols(), [&](Index i, Index j) -> const Q& { return A(i, j); });
  const IntMatrix<Int128> K = M.kernel();
  ASSERT_EQ(K.rows(), 2);
  expect_kernel(A, K);
  // Free columns 2 and 3: (-1, -1, 1, 0) and (-10, -1, 0, 3).
  const IntMatrix<Int128> want = matrix<Int128>(2, 4, {-1, -1, 1, 0, -10, -1, 0, 3});
  for (Index r = 0; r < 2; ++r)
    for (Index j = 0; j < 4; ++j) EXPECT_TRUE(K(r, j) == want(r, j)) << r << "," << j;
}

TEST(IntMatrix, SolveUniqueRankDeficientInconsistent) {
  Int128 N[2], d;
  // x + 2y = 3, 2x + 4y = 6, x = 1: x = y = 1, d > 0.
  IntMatrix<Int128> M = matrix<Int128>(3, 3, {1, 2, 3, 2, 4, 6, 1, 0, 1});
  ASSERT_EQ(M.solve(N, d), SolutionKind::kUnique);
  EXPECT_TRUE(d > 0 && N[0] == d && N[1] == d);
  M = matrix<Int128>(3, 3, {1, 2, 3, 2, 4, 7, 1, 0, 1});
  EXPECT_EQ(M.solve(N, d), SolutionKind::kInconsistent);
  M = matrix<Int128>(2, 3, {1, 2, 3, 2, 4, 6});
  EXPECT_EQ(M.solve(N, d), SolutionKind::kRankDeficient);
}

// The sparse square solve: singleton equations fix u0, then u1; the core (u2, u3) goes to IntMatrix::solve. u = U / D
// with D > 0 in every exact ring, equal to the dense solve's N / d; a singular core and an equation left without an
// open unknown are rank deficient.
template <class R>
void expect_sparse_square_solve() {
  const auto eq = [](std::initializer_list<std::pair<Index, long>> terms, long rhs) {
    SparseEquation<R> e;
    for (const auto& [j, a] : terms) e.terms.push_back({j, R(a)});
    e.rhs = R(rhs);
    return e;
  };
  // 2 u0 = 3, u0 + 3 u1 = 1, u2 + u3 = 5, u1 + u2 - u3 = 0: u = (3/2, -1/6, 31/12, 29/12).
  std::vector<SparseEquation<R>> eqs{eq({{0, 2}}, 3), eq({{0, 1}, {1, 3}}, 1), eq({{2, 1}, {3, 1}}, 5),
                                     eq({{1, 1}, {2, 1}, {3, -1}}, 0)};
  std::vector<R> U;
  R D;
  ASSERT_EQ(solve_sparse_square(eqs, 4, U, D), SolutionKind::kUnique);
  EXPECT_GT(ring::sign(D), 0);
  const std::vector<Q> u{Q(3, 2), Q(-1, 6), Q(31, 12), Q(29, 12)};
  for (Index j = 0; j < 4; ++j) EXPECT_EQ(ring::to_field<Q>(U[static_cast<size_t>(j)]) / ring::to_field<Q>(D), u[j]);
  IntMatrix<R> M = matrix<R>(4, 5, {2, 0, 0, 0, 3, 1, 3, 0, 0, 1, 0, 0, 1, 1, 5, 0, 1, 1, -1, 0});
  std::vector<R> N(4);
  R d;
  ASSERT_EQ(M.solve(N.data(), d), SolutionKind::kUnique);
  for (Index j = 0; j < 4; ++j)
    EXPECT_EQ(ring::to_field<Q>(N[static_cast<size_t>(j)]) / ring::to_field<Q>(d), u[j]) << "dense, u" << j;
  // u2 + u3 = 5, 2 u2 + 2 u3 = 1: a singular core.
  eqs[3] = eq({{2, 2}, {3, 2}}, 1);
  EXPECT_EQ(solve_sparse_square(eqs, 4, U, D), SolutionKind::kRankDeficient);
  // 2 u0 = 3, u0 = 1: the second equation keeps no open unknown and u1 none at all.
  EXPECT_EQ(solve_sparse_square<R>({eq({{0, 2}}, 3), eq({{0, 1}}, 1)}, 2, U, D), SolutionKind::kRankDeficient);
}

TEST(IntMatrix, SparseSquareSolveAgreesWithTheDenseSolve) {
  expect_sparse_square_solve<std::int64_t>();
  expect_sparse_square_solve<Int128>();
  expect_sparse_square_solve<Z>();
}

// Entries near 2^62: after the first elimination step they are near 2^67 and the second step's products need about
// 134 bits, so Int128 throws and with_exact_ring
// restarts in GMP integers, with the kernel Z gives directly.
TEST(IntMatrix, Int128OverflowRestartsInGmpAndAgrees) {
  const Z big = Z(1) << 62;
  Mat<Q> A(3, 4);
  A << Q(big + 1), Q(big - 3), Q(big + 7), Q(5), Q(big - 11), Q(big + 13), Q(big - 17), Q(-2), Q(big + 19), Q(big - 23),
      Q(big + 29), Q(3);
  const auto kernel_in = [&]<class R>() {
    return IntMatrix<R>::primitive_rows(A.rows(), A.cols(), [&](Index i, Index j) -> const Q& { return A(i, j); })
        .kernel();
  };
  EXPECT_THROW(kernel_in.operator()<Int128>(), RingOverflow);
  int rings = 0;
  const IntMatrix<Z> K = with_exact_ring<Q, Int128>([&]<class R>() {
    ++rings;
    const IntMatrix<R> k = kernel_in.template operator()<R>();
    IntMatrix<Z> out(k.rows(), k.cols());
    for (Index r = 0; r < k.rows(); ++r)
      for (Index j = 0; j < k.cols(); ++j) out(r, j) = ring::to_field<Z>(k(r, j));
    return out;
  });
  EXPECT_EQ(rings, 2);
  const IntMatrix<Z> direct = kernel_in.operator()<Z>();
  ASSERT_EQ(K.rows(), 1);
  for (Index j = 0; j < 4; ++j) EXPECT_EQ(K(0, j), direct(0, j));
  EXPECT_EQ(row_gcd(K, 0), 1);
  EXPECT_GT(sgn(K(0, 3)), 0);
  expect_kernel(A, K);
}

// The row operations of the double description's rays and rows: append, erase (the rows below move up), swap,
// select (in the order asked, a row twice), resize (fewer rows: the first kept; more: zero rows appended), in the
// machine ring and in GMP integers, past the 64 entries held on the stack.
template <class R>
void expect_row_operations() {
  IntMatrix<R> M(0, 3);
  for (long i = 0; i < 30; ++i) {
    R row[3];
    for (long j = 0; j < 3; ++j) ring::from_integer(10 * i + j, row[j]);
    M.append_row(row);
  }
  ASSERT_EQ(M.rows(), 30);  // 90 entries: on the heap
  EXPECT_EQ(M(29, 2), R(292));
  M.erase_row(0);
  M.erase_row(28);  // the last
  ASSERT_EQ(M.rows(), 28);
  EXPECT_EQ(M(0, 0), R(10));
  EXPECT_EQ(M(27, 1), R(281));
  M.swap_rows(0, 27);
  EXPECT_EQ(M(0, 2), R(282));
  EXPECT_EQ(M(27, 2), R(12));
  const IntMatrix<R> S = M.select_rows({27, 0, 27});
  EXPECT_EQ(S, matrix<R>(3, 3, {10, 11, 12, 280, 281, 282, 10, 11, 12}));
  EXPECT_EQ(M.select_rows({}), IntMatrix<R>(0, 3));
  M.resize_rows(2);
  EXPECT_EQ(M, matrix<R>(2, 3, {280, 281, 282, 20, 21, 22}));
  M.resize_rows(3);
  EXPECT_EQ(M, matrix<R>(3, 3, {280, 281, 282, 20, 21, 22, 0, 0, 0}));
}

TEST(IntMatrix, RowOperations) {
  expect_row_operations<std::int64_t>();
  expect_row_operations<Z>();
}

// The compressed rows of a dense matrix: its non-zero entries, row by row with columns ascending (an empty row
// included), mapped from Int128 to GMP integers; dense() gives the matrix back.
TEST(SparseIntMatrix, NonzerosInCompressedRowsAndBack) {
  const IntMatrix<Int128> M = matrix<Int128>(3, 4, {0, -7, 0, 3, 0, 0, 0, 0, 5, 0, 0, -1});
  const SparseIntMatrix<Z> S = SparseIntMatrix<Z>::nonzeros(M, [](Int128 x) { return ring::to_z(x); });
  ASSERT_EQ(S.rows(), 3);
  EXPECT_EQ(S.cols(), 4);
  EXPECT_EQ(S.begin(0), 0);
  EXPECT_EQ(S.end(0), 2);
  EXPECT_EQ(S.begin(1), S.end(1));
  EXPECT_EQ(S.end(2), 4);
  const std::vector<std::pair<Index, long>> want = {{1, -7}, {3, 3}, {0, 5}, {3, -1}};
  for (Index t = 0; t < 4; ++t) {
    EXPECT_EQ(S.col(t), want[static_cast<std::size_t>(t)].first);
    EXPECT_EQ(S.value(t), want[static_cast<std::size_t>(t)].second);
  }
  EXPECT_EQ(S.dense(), matrix<Z>(3, 4, {0, -7, 0, 3, 0, 0, 0, 0, 5, 0, 0, -1}));
  SparseIntMatrix<Z> T(4);
  T.add_row();
  T.push(2, Z(9));
  EXPECT_EQ(T.dense(), matrix<Z>(1, 4, {0, 0, 9, 0}));
}

}  // namespace
}  // namespace contactcert::exact
