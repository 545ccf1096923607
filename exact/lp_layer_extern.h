// One list of the LP layer's templates (simplex, tableau, linear algebra, the integer matrix's echelon form, double
// description, tangent cone, adjacent vertices) declared `extern` for a number type of the precision ladder, so that
// every file including the number type's header uses the one instantiation compiled in exact/ instead of compiling its
// own.
#pragma once

#include "exact/adjacent_vertices.h"
#include "exact/double_description.h"
#include "exact/int_matrix.h"
#include "exact/linalg.h"
#include "exact/lp_problem.h"
#include "exact/simplex.h"
#include "exact/tangent_cone.h"

#define CONTACTCERT_LP_LAYER_EXTERN(T)                                                                            \
  extern template class SimplexTableau<T>;                                                                        \
  extern template LpResult<T> solve_lp<T>(const LpProblem<T>&, const LpOptions&);                                 \
  extern template LpResult<T> solve_lp_from_tableau<T>(const LpProblem<T>&, SimplexTableau<T>, const LpOptions&); \
  CONTACTCERT_LINALG_EXTERN(T)                                                                                    \
  extern template void IntMatrix<T>::make_primitive();                                                            \
  extern template std::vector<Eigen::Index> IntMatrix<T>::echelon(Eigen::Index, Eigen::Index, Eigen::Index);      \
  extern template std::optional<std::vector<Vec<T>>> orthant_cone_rays<T>(const Mat<T>&, long);                 \
  CONTACTCERT_DD_RING_EXTERN(T)                                                                                   \
  extern template struct AdjacentResult<T>;                                                                       \
  extern template AdjacentResult<T> adjacent_vertices<T>(const LpProblem<T>&, const std::vector<Eigen::Index>&,   \
                                                         const AdjacencyOptions&);
