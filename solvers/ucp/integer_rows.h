// The rows of X and Y (Pang, Trinkle, Lo section 2) as integers, computed in integers: the left null space of P as
// the kernel of exact::IntMatrix (Int128, restarted in GMP integers on overflow), sparse where the structure is (a
// null-space row has at most rank(P) + 1 non-zero entries, a row of Y's C at most 2 per contact).
#pragma once

#include <vector>

#include "exact/int_matrix.h"
#include "exact/integer_system.h"
#include "exact/number.h"

namespace contactcert::solvers::ucp {

/// Sparse integer rows (exact::SparseIntMatrix over GMP integers).
using SparseRows = exact::SparseIntMatrix<exact::Z>;

/// The rows of a polyhedron {x >= 0 : A x = b} in R^n (n = A.cols()) in integers: row i of A over den[i] (1 for a
/// quasistatic problem, whose rows are primitive integers), b as rationals; exact::integer_system scales them for the
/// exact checks.
using IntegerPolyhedron = exact::RationalRows;

/// A basis of the left null space {z : z^T P = 0} of P: one row per row f of P outside the pivots of the
/// reduced row echelon form of P^T, with z_f > 0, zero at the other non-pivot rows (the basis of
/// exact::null_space(P^T)), each scaled to a primitive integer vector. Rows ascending in f.
SparseRows left_null_rows(const exact::Mat<exact::Q>& P);

/// The positive multiple of the rationals *v[0], ..., *v[k-1] that is a primitive integer vector (all zero: zeros).
std::vector<exact::Z> primitive_integers(const std::vector<const exact::Q*>& v);

}  // namespace contactcert::solvers::ucp
