#include "solvers/wrench_cone/wrench_cone.h"

#include <algorithm>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/int_matrix.h"
#include "exact/ladder_numbers.h"

namespace contactcert::solvers {
namespace {

using Index = Eigen::Index;
namespace rg = exact::ring;

// Row echelon form of the ring rows [P | K] of P g = K z (d columns of P, k of K), rows primitive (IntMatrix): the
// columns of P give T P = [P1; 0] and T K = [K1; K2]; continuing in the columns of K on the rows below leaves a basis
// of the row space of K2 and zero rows, which are dropped. (Reducing above the pivots too keeps the entries as small
// as those of reduced row echelon form.)
template <class R>
void reduce_rows(exact::IntMatrix<R>& E, Index d) {
  const auto r = static_cast<Index>(E.echelon(0, 0, d).size());
  E.resize_rows(r + static_cast<Index>(E.echelon(r, d).size()));
}

// The reduced ring rows as K z = P g over T.
template <class T, class R>
geometry::ProjectionProblem<T> to_problem(const exact::IntMatrix<R>& rows, Index d, Index k,
                                          const std::vector<bool>& strict) {
  return {rg::to_field_rows<T>(rows, k, d), rg::to_field_rows<T>(rows, d), strict};
}

// The RingForm of the mode, row-reduced.
template <class R, class T>
RingForm<R> reduced_form(const geometry::PlanarScene& scene, const ContactModel<T>& model, const ModeString& mode) {
  RingForm<R> form = ring_form<R>(scene, model, mode);
  reduce_rows<R>(form.rows, form.d);
  return form;
}

template <class T>
geometry::FaceCone<T> run_route(const geometry::ProjectionProblem<T>& problem, Route route,
                                const geometry::DdBudget& budget) {
  // eqs. (13)-(14) with z_i > 0 on the strict components: Theorem 1 with k -> 0+ (section 5.6).
  return route == Route::kPaper ? geometry::project_by_polar(problem, budget)
                                : geometry::project_by_lp(problem, budget);
}

}  // namespace

template <class T>
geometry::FaceCone<T> wrench_cone_face(const geometry::PlanarScene& scene, const ContactModel<T>& model,
                                       const ModeString& mode, Route route, const geometry::DdBudget& budget,
                                       Preconditioning pre) {
  if (pre == Preconditioning::kNone) {
    const ConeForm<T> form = cone_form(scene, model, mode);
    return run_route<T>({form.K, form.P, form.strict}, route, budget);
  }
  // K z = P g read from the model in the ring and row-reduced there (the same cone as row-reducing the
  // rows [P | K] of cone_form: the rows differ by positive factors, the columns of K by positive
  // factors); the paper's route stays in the ring up to the canonical face form.
  if (route == Route::kPaper)
    return exact::with_exact_ring<T>([&]<class R>() {
      const RingForm<R> form = reduced_form<R>(scene, model, mode);
      return geometry::project_by_polar_rows<T, R>(form.rows, form.d, form.strict, budget);
    });
  return geometry::project_by_lp(exact::with_exact_ring<T>([&]<class R>() {
                                   const RingForm<R> form = reduced_form<R>(scene, model, mode);
                                   return to_problem<T, R>(form.rows, form.d, form.k, form.strict);
                                 }),
                                 budget);
}

template <class T>
WrenchCone<T> wrench_cone(const geometry::PlanarScene& scene, const ModeString& mode, Route route,
                          const geometry::DdBudget& budget, Preconditioning pre) {
  WrenchCone<T> out;
  out.mode = mode;
  out.route = route;
  const ContactModel<T> model = contact_model<T>(scene);
  out.form = cone_form(scene, model, mode);
  const geometry::FaceCone<T> face = pre == Preconditioning::kRowReduce
                                         ? wrench_cone_face(scene, model, mode, route, budget, pre)
                                         : run_route<T>({out.form.K, out.form.P, out.form.strict}, route, budget);
  out.cone = geometry::nnc_form(face, budget);
  out.status = out.cone.status == geometry::NncStatus::kEmpty ? ConeStatus::kEmpty : ConeStatus::kNonEmpty;
  return out;
}

template <class T>
bool is_empty_cone(const geometry::FaceCone<T>& face) {
  for (Eigen::Index r = 0; r < face.strict.rows(); ++r) {
    bool zero = true;
    for (Eigen::Index c = 0; c < face.strict.cols() && zero; ++c) zero = exact::is_zero(face.strict(r, c));
    if (zero) return true;
  }
  return false;
}

template <class T>
geometry::AffineFace<T> wrench_set_with_minimum_acceleration(const geometry::PlanarScene& scene, const ModeString& mode,
                                                             const Q& a_min, const geometry::DdBudget& budget) {
  const ContactModel<T> model = contact_model<T>(scene);
  const ConeForm<T> form = cone_form(scene, model, mode);
  // Theorem 1: z >= k with k = a_min on the acceleration components, 0 on the forces.
  Vec<T> k = Vec<T>::Zero(form.K.cols());
  for (Eigen::Index j = 0; j < k.size(); ++j)
    if (form.acceleration[static_cast<std::size_t>(j)]) k(j) = from_exact<T>(a_min);
  return geometry::theorem1(form.K, form.P, k, budget);
}

#define CONTACTCERT_WRENCH_CONE_INSTANTIATE(T)                                                             \
  template geometry::FaceCone<T> wrench_cone_face<T>(const geometry::PlanarScene&, const ContactModel<T>&, \
                                                     const ModeString&, Route, const geometry::DdBudget&,  \
                                                     Preconditioning);                                     \
  template WrenchCone<T> wrench_cone<T>(const geometry::PlanarScene&, const ModeString&, Route,            \
                                        const geometry::DdBudget&, Preconditioning);                       \
  template bool is_empty_cone<T>(const geometry::FaceCone<T>&);                                            \
  template geometry::AffineFace<T> wrench_set_with_minimum_acceleration<T>(                                \
      const geometry::PlanarScene&, const ModeString&, const Q&, const geometry::DdBudget&);
CONTACTCERT_WRENCH_CONE_INSTANTIATE(double)
CONTACTCERT_WRENCH_CONE_INSTANTIATE(Q)
CONTACTCERT_WRENCH_CONE_INSTANTIATE(exact::Mpfr)
CONTACTCERT_WRENCH_CONE_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_WRENCH_CONE_INSTANTIATE

}  // namespace contactcert::solvers
