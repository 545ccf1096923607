#include "tests/reference/cdd_cone.h"

// clang-format off
// cddlib needs setoper.h before cdd.h.
#include <cddlib/setoper.h>
#include <cddlib/cdd.h>
#include <cddlib/cdd_f.h>
// clang-format on

#include <mutex>
#include <stdexcept>
#include <vector>

namespace contactcert::reference {
namespace {

using exact::Mat;
using exact::Q;
using Index = Eigen::Index;

void init_cdd() {
  static std::once_flag once;
  std::call_once(once, [] {
    dd_set_global_constants();
    ddf_set_global_constants();
  });
}

// Rows [0, v] for every row of each block; rows of linear_block go to the linearity set.
dd_MatrixPtr make_matrix(const Mat<Q>& block, const Mat<Q>& linear_block, Index dim, Q sign,
                         dd_RepresentationType rep) {
  const Index m = block.rows() + linear_block.rows();
  dd_MatrixPtr M = dd_CreateMatrix(m, dim + 1);
  M->representation = rep;
  M->numbtype = dd_Rational;
  for (Index i = 0; i < m; ++i) {
    const bool lin = i >= block.rows();
    dd_set_si(M->matrix[i][0], 0);
    for (Index j = 0; j < dim; ++j) {
      const Q v = sign * (lin ? linear_block(i - block.rows(), j) : block(i, j));
      dd_set(M->matrix[i][j + 1], v.get_mpq_t());
    }
    if (lin) set_addelem(M->linset, i + 1);
  }
  return M;
}

// Splits a cdd matrix into (non-linear rows, linear rows) times `sign`, skipping rows with b != 0
// (the origin as a vertex in a generator output).
void split(dd_MatrixPtr A, Index dim, Q sign, Mat<Q>& rows, Mat<Q>& linear) {
  std::vector<Index> r, l;
  for (Index i = 0; i < A->rowsize; ++i) {
    if (mpq_sgn(A->matrix[i][0]) != 0) continue;
    (set_member(i + 1, A->linset) ? l : r).push_back(i);
  }
  rows = Mat<Q>(static_cast<Index>(r.size()), dim);
  linear = Mat<Q>(static_cast<Index>(l.size()), dim);
  for (size_t k = 0; k < r.size(); ++k)
    for (Index j = 0; j < dim; ++j) rows(static_cast<Index>(k), j) = sign * Q(A->matrix[r[k]][j + 1]);
  for (size_t k = 0; k < l.size(); ++k)
    for (Index j = 0; j < dim; ++j) linear(static_cast<Index>(k), j) = sign * Q(A->matrix[l[k]][j + 1]);
}

}  // namespace

geometry::FaceCone<Q> cdd_to_face(const geometry::SpanCone<Q>& cone) {
  init_cdd();
  dd_MatrixPtr M = make_matrix(cone.rays, cone.lines, cone.dim, Q(1), dd_Generator);
  dd_ErrorType err = dd_NoError;
  dd_PolyhedraPtr P = dd_DDMatrix2Poly(M, &err);
  if (err != dd_NoError) throw std::runtime_error("cddlib conversion failed");
  dd_MatrixPtr A = dd_CopyInequalities(P);
  geometry::FaceCone<Q> out;
  out.dim = cone.dim;
  // cdd: b + a . x >= 0 with b = 0; ours: f . x <= 0 with f = -a.
  split(A, cone.dim, Q(-1), out.inequalities, out.equalities);
  out.strict = Mat<Q>(0, cone.dim);
  dd_FreeMatrix(A);
  dd_FreePolyhedra(P);
  dd_FreeMatrix(M);
  return out;
}

geometry::SpanCone<Q> cdd_to_span(const geometry::FaceCone<Q>& cone) {
  if (cone.strict.rows() > 0) throw std::invalid_argument("cdd_to_span: strict rows");
  init_cdd();
  dd_MatrixPtr M = make_matrix(cone.inequalities, cone.equalities, cone.dim, Q(-1), dd_Inequality);
  dd_ErrorType err = dd_NoError;
  dd_PolyhedraPtr P = dd_DDMatrix2Poly(M, &err);
  if (err != dd_NoError) throw std::runtime_error("cddlib conversion failed");
  dd_MatrixPtr G = dd_CopyGenerators(P);
  geometry::SpanCone<Q> out;
  out.dim = cone.dim;
  split(G, cone.dim, Q(1), out.rays, out.lines);
  dd_FreeMatrix(G);
  dd_FreePolyhedra(P);
  dd_FreeMatrix(M);
  return out;
}

geometry::FaceCone<double> cddf_to_face(const geometry::SpanCone<double>& cone) {
  init_cdd();
  const Index m = cone.rays.rows() + cone.lines.rows();
  ddf_MatrixPtr M = ddf_CreateMatrix(m, cone.dim + 1);
  M->representation = ddf_Generator;
  M->numbtype = ddf_Real;
  for (Index i = 0; i < m; ++i) {
    const bool lin = i >= cone.rays.rows();
    ddf_set_d(M->matrix[i][0], 0.0);
    for (Index j = 0; j < cone.dim; ++j)
      ddf_set_d(M->matrix[i][j + 1], lin ? cone.lines(i - cone.rays.rows(), j) : cone.rays(i, j));
    if (lin) set_addelem(M->linset, i + 1);
  }
  ddf_ErrorType err = ddf_NoError;
  ddf_PolyhedraPtr P = ddf_DDMatrix2Poly(M, &err);
  if (err != ddf_NoError) throw std::runtime_error("cddlib (double) conversion failed");
  ddf_MatrixPtr A = ddf_CopyInequalities(P);
  std::vector<Index> r, l;
  for (Index i = 0; i < A->rowsize; ++i) (set_member(i + 1, A->linset) ? l : r).push_back(i);
  geometry::FaceCone<double> out;
  out.dim = cone.dim;
  out.inequalities = Mat<double>(static_cast<Index>(r.size()), cone.dim);
  out.equalities = Mat<double>(static_cast<Index>(l.size()), cone.dim);
  out.strict = Mat<double>(0, cone.dim);
  for (size_t k = 0; k < r.size(); ++k)
    for (Index j = 0; j < cone.dim; ++j)
      out.inequalities(static_cast<Index>(k), j) = -ddf_get_d(A->matrix[r[k]][j + 1]);
  for (size_t k = 0; k < l.size(); ++k)
    for (Index j = 0; j < cone.dim; ++j) out.equalities(static_cast<Index>(k), j) = -ddf_get_d(A->matrix[l[k]][j + 1]);
  ddf_FreeMatrix(A);
  ddf_FreePolyhedra(P);
  ddf_FreeMatrix(M);
  return out;
}

}  // namespace contactcert::reference
