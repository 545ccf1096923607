#include "solvers/wrench_cone/wrench_cone.h"

#include "exact/linalg.h"

namespace contactcert::solvers {
namespace {

template <class T>
geometry::FaceCone<T> run_route(const ConeForm<T>& form, Route route, const geometry::DdBudget& budget, Preconditioning pre) {
  // eqs. (13)-(14) with z_i > 0 on the strict components: Theorem 1 with k -> 0+ (section 5.6).
  const geometry::ProjectionProblem<T> problem =
      pre == Preconditioning::kRowReduce ? row_reduced(form) : geometry::ProjectionProblem<T>{form.K, form.P, form.strict};
  return route == Route::kPaper ? geometry::project_by_polar(problem, budget) : geometry::project_by_lp(problem, budget);
}

}  // namespace

template <class T>
geometry::ProjectionProblem<T> row_reduced(const ConeForm<T>& form) {
  const Eigen::Index m = form.K.rows(), k = form.K.cols(), d = form.P.cols();
  if (m == 0) return {form.K, form.P, form.strict};
  // rref [P | I] = [T P | T] with T invertible; its first r rows hold the pivots of P.
  Mat<T> aug(m, d + m);
  aug.leftCols(d) = form.P;
  aug.rightCols(m) = Mat<T>::Identity(m, m);
  const exact::Rref<T> e = exact::rref(aug);
  Eigen::Index r = 0;
  while (r < e.rank() && e.pivots[static_cast<std::size_t>(r)] < d) ++r;
  const Mat<T> TK = e.R.rightCols(m) * form.K;
  // 0 = K2 z: keep a basis of the row space of K2.
  const exact::Rref<T> k2 = exact::rref<T>(TK.bottomRows(m - r));
  geometry::ProjectionProblem<T> out;
  out.K.resize(r + k2.rank(), k);
  out.K.topRows(r) = TK.topRows(r);
  out.K.bottomRows(k2.rank()) = k2.R.topRows(k2.rank());
  out.P = Mat<T>::Zero(r + k2.rank(), d);
  out.P.topRows(r) = e.R.topLeftCorner(r, d);
  out.strict = form.strict;
  return out;
}

template <class T>
geometry::FaceCone<T> wrench_cone_face(const geometry::PlanarScene& scene, const ContactModel<T>& model,
                                       const ModeString& mode, Route route, const geometry::DdBudget& budget,
                                       Preconditioning pre) {
  return run_route(cone_form(scene, model, mode), route, budget, pre);
}

template <class T>
WrenchCone<T> wrench_cone(const geometry::PlanarScene& scene, const ModeString& mode, Route route,
                          const geometry::DdBudget& budget, Preconditioning pre) {
  WrenchCone<T> out;
  out.mode = mode;
  out.route = route;
  const ContactModel<T> model = contact_model<T>(scene);
  out.form = cone_form(scene, model, mode);
  const geometry::FaceCone<T> face = run_route(out.form, route, budget, pre);
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

#define CONTACTCERT_WRENCH_CONE_INSTANTIATE(T)                                                                  \
  template geometry::ProjectionProblem<T> row_reduced<T>(const ConeForm<T>&);                                   \
  template geometry::FaceCone<T> wrench_cone_face<T>(const geometry::PlanarScene&, const ContactModel<T>&,       \
                                                     const ModeString&, Route, const geometry::DdBudget&,        \
                                                     Preconditioning);                                           \
  template WrenchCone<T> wrench_cone<T>(const geometry::PlanarScene&, const ModeString&, Route,                  \
                                        const geometry::DdBudget&, Preconditioning);                             \
  template bool is_empty_cone<T>(const geometry::FaceCone<T>&);                                                  \
  template geometry::AffineFace<T> wrench_set_with_minimum_acceleration<T>(                                      \
      const geometry::PlanarScene&, const ModeString&, const Q&, const geometry::DdBudget&);
CONTACTCERT_WRENCH_CONE_INSTANTIATE(double)
CONTACTCERT_WRENCH_CONE_INSTANTIATE(Q)
#undef CONTACTCERT_WRENCH_CONE_INSTANTIATE

}  // namespace contactcert::solvers
