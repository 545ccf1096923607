// Section 5 of the wrench cone paper: from eq. (7), C y = B g, and the constraints of a mode
// (Table 2) to K z = P g, z >= 0 (eqs. 13-17), through the matrices E, N, R, S, V.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "exact/int_matrix.h"
#include "geometry/planar_scene.h"
#include "solvers/wrench_cone/contact_model.h"
#include "solvers/wrench_cone/mode.h"

namespace contactcert::solvers {

/// The paper's five matrices for one mode (sections 5.1-5.5), literally.
template <class T>
struct ModeMatrices {
  Mat<T> E;  ///< row selection: drops the equations of unconstrained accelerations (5.1)
  Mat<T> N;  ///< 4n x 4n diagonal sign change of negative variables (5.2)
  Mat<T> R;  ///< 4n x 4n rolling friction substitution (5.3)
  Mat<T> S;  ///< 4n x 4n sliding friction substitution (5.4), signs of Table 2 (friction opposes sliding)
  Mat<T> V;  ///< column selection: drops zero, sliding c_t and unconstrained variables (5.5)
};

/// K z = P g, z >= 0 with z_i > 0 where strict (eqs. 13-17).
template <class T>
struct ConeForm {
  Mat<T> K;                         ///< K = E C N R S V (eq. 15)
  Mat<T> P;                         ///< P = E B (eq. 17)
  std::vector<bool> strict;         ///< per z: the strict rows of Table 2 (a, l, r, and s when touching)
  std::vector<bool> acceleration;   ///< per z: an acceleration (true) or a contact force (false)
  std::vector<std::string> names;   ///< per z, e.g. "-a1n", "c0[n-mu t]", "c0[n+mu t]" (fixels numbered from 0)
  std::vector<Eigen::Index> fixel;  ///< per z: the fixel whose acceleration or contact force it is
  std::vector<Q> t_per_n;           ///< per force z: its force is z (n_i + t_per_n t_i) (R and S); 0 otherwise
};

/// The contact forces c = (c_1n..c_kn, c_1t..c_kt) in the model's frames of the fixels `touching` (scene
/// indices, in order) that a solution z of K z = P g applies: each force component z_j of fixel i adds z_j to
/// c_in and t_per_n_j z_j to c_it (eq. 15 after R and S); the other fixels carry none.
Vec<Q> contact_forces(const ConeForm<Q>& form, const std::vector<Eigen::Index>& touching, const Vec<Q>& z);

/// E, N, R, S, V of sections 5.1-5.5 for a valid mode of the scene (validate with parse_mode first).
template <class T>
ModeMatrices<T> mode_matrices(const geometry::PlanarScene& scene, const ModeString& mode);

/// K and P of eqs. (15) and (17), computed by the column operations that E C N R S V and E B stand
/// for (equal to the literal products, without the 4n x 4n products).
template <class T>
ConeForm<T> cone_form(const geometry::PlanarScene& scene, const ContactModel<T>& model, const ModeString& mode);

/// K z = P g as ring rows [P | K'] over the ring R of T (exact/fraction_free.h), read straight from the
/// model: K' is K with each force column scaled by the denominator of its friction coefficient and each
/// row [P | K'] by a positive factor (to_ring); pos(K') = pos(K) and the cone of eqs. (13)-(14) is the
/// same, with the same z and strict components as cone_form.
template <class R>
struct RingForm {
  Eigen::Index d = 3;        ///< columns of P
  Eigen::Index k = 0;        ///< columns of K
  exact::IntMatrix<R> rows;  ///< the rows of E: d + k columns
  std::vector<bool> strict;  ///< per z, as ConeForm::strict
};

/// The RingForm of a valid mode of the scene.
template <class R, class T>
RingForm<R> ring_form(const geometry::PlanarScene& scene, const ContactModel<T>& model, const ModeString& mode);

extern template RingForm<double> ring_form<double, double>(const geometry::PlanarScene&, const ContactModel<double>&,
                                                           const ModeString&);
extern template RingForm<std::int64_t> ring_form<std::int64_t, Q>(const geometry::PlanarScene&, const ContactModel<Q>&,
                                                                  const ModeString&);
extern template RingForm<exact::Z> ring_form<exact::Z, Q>(const geometry::PlanarScene&, const ContactModel<Q>&,
                                                          const ModeString&);

#define CONTACTCERT_CONE_FORM_EXTERN(T)                                                              \
  extern template ModeMatrices<T> mode_matrices<T>(const geometry::PlanarScene&, const ModeString&); \
  extern template ConeForm<T> cone_form<T>(const geometry::PlanarScene&, const ContactModel<T>&, const ModeString&);
CONTACTCERT_CONE_FORM_EXTERN(double)
CONTACTCERT_CONE_FORM_EXTERN(Q)
#undef CONTACTCERT_CONE_FORM_EXTERN

}  // namespace contactcert::solvers
