// A dense simplex tableau B^-1 [A | b] over a field T with its basis and objective row: the pivoting engine
// of solve_lp (simplex.h) and of adjacent_vertices (adjacent_vertices.h), exposed for later pivoting code.
#pragma once

#include <optional>
#include <vector>

#include "exact/number.h"

namespace contactcert::exact {

/// Tableau rows r = 0..rows()-1 hold B^-1 A x = B^-1 b for the basis B = basis(); entries are stored
/// row-major. A basic index >= cols() denotes an artificial variable (phase 1 of solve_lp): the artificial of
/// original row i has index cols() + i and column sign(b_i) e_i, and is never stored or re-entered.
template <class T>
class SimplexTableau {
 public:
  using Index = Eigen::Index;

  /// The tableau of A x = b for the given basis (columns of A; |basis| = rank A), built by Gauss-Jordan
  /// elimination; rows of A that are redundant are dropped. nullopt if the columns are dependent, do not
  /// span the column space of A, or b is not in the column space of A.
  static std::optional<SimplexTableau> from_basis(const Mat<T>& A, const Vec<T>& b, const std::vector<Index>& basis);
  /// The phase-1 start of A x + S a = b, S = diag(sign b): every row basic in its artificial, rhs = |b|.
  static SimplexTableau artificial_start(const Mat<T>& A, const Vec<T>& b);

  /// Number of tableau rows (= rank of A once redundant rows are dropped).
  Index rows() const { return m_; }
  /// Number of structural columns (artificials excluded).
  Index cols() const { return n_; }
  /// basis()[r] = variable basic in row r.
  const std::vector<Index>& basis() const { return basis_; }
  /// (B^-1 A)(r, j).
  const T& entry(Index r, Index j) const { return t_[static_cast<size_t>(r * (n_ + 1) + j)]; }
  /// (B^-1 b)(r): the value of the basic variable of row r.
  const T& rhs(Index r) const { return entry(r, n_); }
  /// Row of basic column j, or -1 if j is non-basic.
  Index row_of(Index j) const { return row_of_[static_cast<size_t>(j)]; }
  /// True if column j is basic.
  bool is_basic(Index j) const { return row_of(j) >= 0; }
  /// True if some basic variable is an artificial one.
  bool has_artificial() const;

  /// Pivot: column j (non-basic, structural) enters in row r; entry(r, j) must be non-zero.
  void pivot(Index r, Index j);
  /// Drops the rows `rows` (redundant rows whose structural entries are all zero; any order), moving each kept row
  /// once.
  void remove_rows(const std::vector<Index>& rows);

  /// Sets the objective row for costs c over the structural columns (artificials cost `artificial_cost`):
  /// reduced costs d = c - c_B^T B^-1 A and value c_B^T B^-1 b.
  void set_objective(const Vec<T>& c, const T& artificial_cost = T(0));
  /// Reduced cost of column j for the current objective.
  const T& reduced_cost(Index j) const { return d_[static_cast<size_t>(j)]; }
  /// c_B^T B^-1 b for the current objective.
  const T& objective_value() const { return z_; }

  /// The basic solution x (structural columns; non-basic = 0).
  Vec<T> primal() const;

 private:
  SimplexTableau(Index m, Index n);
  T& at(Index r, Index j) { return t_[static_cast<size_t>(r * (n_ + 1) + j)]; }

  Index m_ = 0, n_ = 0;
  std::vector<T> t_;  // m x (n + 1), row-major, last column = rhs
  std::vector<Index> basis_;
  std::vector<Index> row_of_;
  std::vector<T> d_;  // reduced costs, size n
  T z_ = T(0);
  std::vector<Index> nz_;  // scratch: non-zero columns of the pivot row
};

extern template class SimplexTableau<double>;
extern template class SimplexTableau<Q>;

}  // namespace contactcert::exact
