// A mode prefix's kinematic rows decided without an LP (mode_tree.h). From rest every row of a prefix is a sign
// condition f . vdot = 0, >= 0 or > 0 on the acceleration vdot in R^3 (eq. 6, Table 2), so the prefix is feasible
// exactly when some vdot meets them all, and the rows cut R^3 into the cells of an arrangement of planes through
// the origin. The closure cone C = { vdot : f . vdot >= 0 (= 0 on equality rows) } is kept by its generators
// (C = lin(L) + cone(R)) and cut one row at a time as the tree descends (the double description method,
// Motzkin et al. 1953, in three dimensions). The strict rows hold somewhere on C exactly when they hold at the sum
// of the rays (each f >= 0 on C, so f vanishes on C unless it is positive at a ray). If a strict row f_r vanishes
// on C, then -f_r is in the dual cone of C (Farkas), hence by Caratheodory a non-negative combination of at most
// three rows (equality rows with either sign), and the weights - three planes' determinants, Cramer's rule - are a
// Motzkin certificate of the prefix's system. Integers throughout (128 bits, overflow-checked: RingOverflow).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "exact/fraction_free.h"

namespace contactcert::solvers {

using Int3 = std::array<exact::Int128, 3>;

/// f . v, overflow-checked.
exact::Int128 dot(const Int3& f, const Int3& v);

/// How a row constrains f . vdot.
enum class RowSign : char { kZero, kNonNegative, kPositive };

/// One row of a prefix's kinematic system as an integer sign condition (a positive multiple of the row, oriented
/// so that its slack is f . vdot).
struct ConeRow {
  Int3 f;
  RowSign sign;
};

/// The closure cone of the rows cut so far: lineality vectors and extreme rays, primitive integer vectors. A pointed
/// cone of three or more rays is three-dimensional and keeps its rays in cyclic order (the cut is then the clipping
/// of a convex polygon); a cone with lineality has at most two rays.
class PrefixCone {
 public:
  /// R^3.
  PrefixCone();
  /// C := C intersected with { f . v >= 0 } (or { f . v = 0 }). Throws exact::RingOverflow.
  void cut(const ConeRow& row);
  const std::vector<Int3>& rays() const { return rays_; }
  /// The sum of the rays over the gcd of its entries (0 if none): in C, and positive on every row that is positive
  /// somewhere on C.
  Int3 ray_sum() const;
  /// A point of C meeting every row (f . v = 0, >= 0, > 0; the rows C was cut by): the first ray that does (the
  /// smallest numbers), else the ray sum if it does, else none (then no point of C does).
  std::optional<Int3> point_meeting(const std::vector<ConeRow>& rows) const;

 private:
  std::vector<Int3> lineality_, rays_;
};

/// Whether v meets every row (f . v = 0, >= 0, > 0).
bool meets_rows(const std::vector<ConeRow>& rows, const Int3& v);

/// The rows a Motzkin certificate of `rows` = (the rows of `parent`) + (rows from index `first_new` on) needs at
/// most: the new rows and the parent's rows tight at one of its rays (every row if it has at most one ray), one row
/// per direction, and of the equality rows only independent ones (their span is what a certificate uses).
struct CertificateCandidates {
  std::vector<std::size_t> rows;  ///< indices into the rows, the new ones first
  std::size_t new_rows = 0;       ///< how many of them are new
};
CertificateCandidates certificate_candidates(const std::vector<ConeRow>& rows, std::size_t first_new,
                                             const PrefixCone& parent);

/// Integer weights w on `rows` with sum w_i f_i = 0, w_i >= 0 on sign rows and w_r > 0 on a kPositive row r: a
/// Motzkin certificate of the rows, when `cone` (the cone of all of them) has no point meeting them. The first one
/// found - a strict row that vanishes on `cone` with one to three candidates, smallest subsets first - unless a
/// circuit of the candidates (a minimal dependent set of 2 to 4 of them, a new one among them) has fewer rows, or
/// as many and is shorter as written: row i's written entry is factors[i] w_i (w_i without factors), the entries
/// made primitive (sparse_motzkin.h). `first_found`, if given, receives the first one when it was not chosen (else
/// it is emptied). Each answer checked. Nullopt if none qualifies within `budget` subsets of four rows. Throws
/// exact::RingOverflow.
std::optional<std::vector<exact::Int128>> cone_motzkin(const std::vector<ConeRow>& rows, const PrefixCone& cone,
                                                       const CertificateCandidates& candidates, long budget,
                                                       const std::vector<std::int64_t>* factors = nullptr,
                                                       std::vector<exact::Int128>* first_found = nullptr);

}  // namespace contactcert::solvers
