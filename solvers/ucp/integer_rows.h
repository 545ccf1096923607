// The rows of X and Y (Pang, Trinkle, Lo section 2) as integers, computed in integers: the left null space of P as
// the kernel of exact::IntMatrix (Int128, restarted in GMP integers on overflow), sparse where the structure is (a
// null-space row has at most rank(P) + 1 non-zero entries, a row of Y's C at most 2 per contact).
#pragma once

#include <cstddef>
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

/// A lower bound on the bits of the minors an elimination over the rows of M (by_rows) or over its columns forms:
/// each row over its common denominator, the largest min(rows, cols) of them summed (cancellation aside).
std::size_t elimination_bits(const exact::Mat<exact::Q>& M, bool by_rows);

/// f in Int128, restarted in Z on overflow (exact::with_exact_ring<Q, Int128>), or straight in Z when `bits` (a
/// lower bound on the bits f forms) is over the 127 that Int128 holds: a skipped attempt would have overflowed
/// (cancellation aside, when only time is lost: both rings give the same answer).
template <class F>
auto in_ring(std::size_t bits, F&& f) {
  return bits <= 127 ? exact::with_exact_ring<exact::Q, exact::Int128>(f) : f.template operator()<exact::Z>();
}

/// A basis of the left null space {z : z^T P = 0} of P: one row per row f of P outside the pivots of the
/// reduced row echelon form of P^T, with z_f > 0, zero at the other non-pivot rows (the basis of
/// exact::null_space(P^T)), each scaled to a primitive integer vector. Rows ascending in f.
SparseRows left_null_rows(const exact::Mat<exact::Q>& P);

/// The positive multiple of the rationals *v[0], ..., *v[k-1] that is a primitive integer vector (all zero: zeros).
std::vector<exact::Z> primitive_integers(const std::vector<const exact::Q*>& v);

}  // namespace contactcert::solvers::ucp
