// The Farkas vectors that prove a face of the UCP's polyhedra empty, from the float search's approximate ones:
// rounded (rational reconstruction) or recomputed exactly from a float phase-1 basis (fraction-free
// elimination), then checked in integers. R = Int128 (throws RingOverflow) or Z: exact::with_exact_ring.
#pragma once

#include <optional>
#include <vector>

#include "exact/integer_system.h"

namespace contactcert::solvers::ucp {

using exact::Q;
using exact::Vec;

/// A Farkas vector y for the rows of A x = b, with the columns j where y^T A_j < 0.
struct FarkasVector {
  Vec<Q> y;
  std::vector<Eigen::Index> negative;
};

/// A Farkas vector y proving that face empty, near y_approx (a float one for the rows of A x = b):
/// y^T A_j >= 0 for every j off `zero` and y^T b < 0 (then no x >= 0 of the face has A x = b). The entries
/// y_approx_i / row_scale_i, scaled to max-norm 1, are rounded to fractions Y_i / E and checked against the
/// integer rows; the
/// result is y_i = row_scale_i Y_i, a positive multiple of the rounded vector, with its negative columns
/// (all in `zero`). nullopt if a rounding or the check fails.
template <class R>
std::optional<FarkasVector> rounded_farkas(const exact::IntegerSystem<R>& s, const Vec<double>& y_approx,
                                           const std::vector<bool>& zero);

/// The Farkas vector y_approx of a float phase-1 basis (columns of A, and n + i for the artificial of row i),
/// recomputed exactly: f with f^T A_v = 0 on the basis' structural columns and, on its artificial rows, the
/// entries of y_approx rounded to signed powers of two (the artificials' costs on rows the float simplex
/// scaled by powers of two), solved by fraction-free elimination in R and checked as rounded_farkas checks.
/// nullopt if the basis is singular or f is not a Farkas vector for `zero`.
template <class R>
std::optional<FarkasVector> basis_farkas(const exact::IntegerSystem<R>& s, const Vec<double>& y_approx,
                                         const std::vector<Eigen::Index>& basis, const std::vector<bool>& zero);

#define CONTACTCERT_FARKAS_ROUNDING_EXTERN(R)                                                                          \
  extern template std::optional<FarkasVector> basis_farkas<R>(                                                         \
      const exact::IntegerSystem<R>&, const Vec<double>&, const std::vector<Eigen::Index>&, const std::vector<bool>&); \
  extern template std::optional<FarkasVector> rounded_farkas<R>(const exact::IntegerSystem<R>&, const Vec<double>&,    \
                                                                const std::vector<bool>&);
CONTACTCERT_FARKAS_ROUNDING_EXTERN(exact::Int128)
CONTACTCERT_FARKAS_ROUNDING_EXTERN(exact::Z)
#undef CONTACTCERT_FARKAS_ROUNDING_EXTERN

}  // namespace contactcert::solvers::ucp
