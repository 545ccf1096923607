// The rows of X and Y (Pang, Trinkle, Lo section 2) as primitive integers, computed in integers: the left null
// space of P as the kernel of exact::IntMatrix (Int128, restarted in GMP integers on overflow), sparse
// where the structure is (a null-space row has at most rank(P) + 1 non-zero entries).
#pragma once

#include <vector>

#include "exact/number.h"

namespace contactcert::solvers::ucp {

/// A sparse integer row: value[k] at column col[k], columns ascending.
struct SparseRow {
  std::vector<Eigen::Index> col;
  std::vector<exact::Z> value;
};

/// A basis of the left null space {z : z^T P = 0} of P: one row per row f of P outside the pivots of the
/// reduced row echelon form of P^T, with z_f > 0, zero at the other non-pivot rows (the basis of
/// exact::null_space(P^T)), each scaled to a primitive integer vector. Rows ascending in f.
std::vector<SparseRow> left_null_rows(const exact::Mat<exact::Q>& P);

/// The positive multiple of the rationals *v[0], ..., *v[k-1] that is a primitive integer vector, written back in
/// place (all zero: unchanged).
void make_primitive(const std::vector<exact::Q*>& v);

}  // namespace contactcert::solvers::ucp
