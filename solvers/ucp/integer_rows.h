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

/// The rows of a polyhedron {x >= 0 : A x = b} in R^n (n = A.cols()) in integers: row i of A over den[i] (den[i] > 0
/// the least common denominator of that row; 1 for a quasistatic problem, whose rows are primitive integers), b as
/// rationals (one per row).
struct IntegerPolyhedron {
  SparseRows A;
  std::vector<exact::Z> den;
  exact::Vec<exact::Q> b;
  Eigen::Index rows() const { return A.rows(); }
  Eigen::Index cols() const { return A.cols(); }
};

/// A basis of the left null space {z : z^T P = 0} of P: one row per row f of P outside the pivots of the
/// reduced row echelon form of P^T, with z_f > 0, zero at the other non-pivot rows (the basis of
/// exact::null_space(P^T)), each scaled to a primitive integer vector. Rows ascending in f.
SparseRows left_null_rows(const exact::Mat<exact::Q>& P);

/// The positive multiple of the rationals *v[0], ..., *v[k-1] that is a primitive integer vector (all zero: zeros).
std::vector<exact::Z> primitive_integers(const std::vector<const exact::Q*>& v);

/// The rows of [A | b] as given in rationals: each row of A over its least common denominator (its non-zero
/// entries), b as it is.
IntegerPolyhedron integer_polyhedron(const exact::Mat<exact::Q>& A, const exact::Vec<exact::Q>& b);

/// The rows of [A | b] over R, each times the lcm of its denominators: exact::integer_system of the rational rows,
/// made from the integers (Int128: throws RingOverflow if a number does not fit).
template <class R>
exact::IntegerSystem<R> integer_system(const IntegerPolyhedron& P);
extern template exact::IntegerSystem<exact::Int128> integer_system<exact::Int128>(const IntegerPolyhedron&);
extern template exact::IntegerSystem<exact::Z> integer_system<exact::Z>(const IntegerPolyhedron&);

}  // namespace contactcert::solvers::ucp
