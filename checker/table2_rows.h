// The certificate checkers' own reading of the wrench cone paper (Balkcom, Trinkle 2002), written apart from the
// solver's model (contact_model.h, motion_system.h, cone_form.h) so that a modelling error is not shared by the
// solver and the checker that verifies it. From each fixel's contact frame (p_i on the workpiece, n_i from the
// fixel to the workpiece, t_i = n_i turned by +90 degrees; docs/papers.md errata) and the workpiece's com and I/m:
//   w_in = (n_i, (p_i - com) x n_i), w_it = (t_i, (p_i - com) x t_i)   the wrenches of unit contact forces (eq. 4)
//   a_in = w_in . vdot, a_it = w_it . vdot                              contact accelerations from rest (eq. 6)
//   M vdot = g + sum_i (c_in w_in + c_it w_it),  M = diag(1, 1, I/m)    the workpiece's motion (eq. 4, unit mass)
// and Table 2 per letter (the errata's strict `s` at a touching fixel; friction opposes sliding):
//   s: a_n > 0 (>= 0 at a gap or as printed), c = 0     a: a_n < 0, c = 0      u: c = 0
//   l: a_n = 0, a_t > 0, c_t = -mu_k c_n                 r: a_n = 0, a_t < 0, c_t = mu_k c_n
//   n: a_n = a_t = 0, |c_t| <= mu_s c_n                  m: a_n = 0, |c_t| <= mu_s c_n         (c_n >= 0 in l r n m)
// The certificates' rows are these, in a fixed layout (docs/formats.md), with each fixel's pair (w_in, w_it)
// scaled to the primitive integer 6-vector that is a positive multiple of it (the scale of a frame changes no
// cone, and it fixes the scale of each row a Motzkin vector weighs). Everything here is linear in the number of
// fixels: rows are kept by their non-zero entries and no matrix of the model (J^T M^-1 J) is formed.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "exact/number.h"
#include "geometry/planar_scene.h"

namespace contactcert::checker::table2_check {

using exact::Q;
using exact::Vec;

/// One fixel as the checker reads it from the scene.
struct CheckedFixel {
  std::array<Q, 3> w_n, w_t;  ///< the wrenches of unit forces along n_i and t_i, scaled together to integers
  Q mu_s, mu_k;
  bool touching = true;
};

/// The checker's model of a scene: its fixels (all, or the touching ones) and I/m.
struct CheckedScene {
  std::vector<CheckedFixel> fixels;
  Q inertia_per_mass;
};

/// The checker's model of `scene`; with `touching_only`, of its touching fixels in scene order (the fixels strong
/// stability considers). A checker's scene has its own frames (frame_check::read_checked_scene), never the solver's.
CheckedScene checked_scene(const geometry::PlanarScene& scene, bool touching_only);

/// A linear system A x = b with signs on x: rows by their non-zero entries, per column free, x >= 0 or x > 0.
struct Rows {
  enum class Sign : char { kFree, kNonNegative, kPositive };
  struct Entry {
    std::size_t col;
    Q value;
  };
  std::vector<std::vector<Entry>> rows;
  std::vector<Sign> columns;
  Vec<Q> b;  ///< empty: zero
};

/// Whether y is a Motzkin certificate that `rows` has no solution: (y^T A)_j = 0 on free columns and >= 0 on the
/// others, y^T b <= 0, and y^T b < 0 or (y^T A)_j > 0 on a strict column. Time and memory linear in the entries.
bool motzkin_holds(const Rows& rows, const Vec<Q>& y);

/// The kinematic rows of a mode or of a prefix of one (letters for the first fixels) on vdot and one slack sigma
/// per signed row, sigma's columns in fixel order after vdot's three:
///   s, S: a_n - sigma = 0     a: a_n + sigma = 0     u: none
///   l r n m: a_n = 0, then   l: a_t - sigma = 0     r: a_t + sigma = 0     n: a_t = 0     m: none
/// sigma > 0 for a l r, and for s at a touching fixel unless `printed_separation`; else sigma >= 0.
/// Returns false (rows untouched) if a letter is not one of Table 2's or does not fit its fixel.
bool kinematic_rows(const CheckedScene& scene, const std::string& letters, bool printed_separation, Rows& out);

/// The rows of a moving mode over s l r n (one letter per fixel, every fixel touching) for wrench g: columns vdot
/// (free), then per fixel [sigma unless n] [c_n unless s] [c_t (free), rho+, rho- if n]; rows: the kinematic rows
/// above, then per rolling fixel mu_s c_n - c_t - rho+ = 0 and mu_s c_n + c_t - rho- = 0, then the three rows of
/// M vdot - sum_i c_in (w_in + e_i w_it) - sum_n c_it w_it = g, e_i = -mu_k for l, mu_k for r. False on other
/// letters or a wrong length.
bool motion_rows(const CheckedScene& scene, const std::string& mode, const Vec<Q>& g, Rows& out);

/// The rows of a resting solution for wrench g: per fixel columns c_n, c_t (free), rho+, rho-; rows the friction
/// rows of every fixel, then the three rows of -sum_i (c_in w_in + c_it w_it) = g.
Rows resting_rows(const CheckedScene& scene, const Vec<Q>& g);

/// Whether acceleration vdot meets Table 2's signs for the letters (a mode or a prefix), read directly.
bool realises(const CheckedScene& scene, const std::string& letters, bool printed_separation, const Vec<Q>& vdot);

/// Why contact forces c = (c_1n..c_kn, c_1t..c_kt) and acceleration vdot are not a solution of `mode` (letters
/// s l r n) for wrench g - M vdot = g + J c, and Table 2's signs and friction per fixel - or "" if they are.
std::string motion_violation(const CheckedScene& scene, const std::string& mode, const Vec<Q>& g, const Vec<Q>& vdot,
                             const Vec<Q>& c);

/// Why c is not a resting solution for g (J c + g = 0, every c_i in its static friction cone), or "".
std::string resting_violation(const CheckedScene& scene, const Vec<Q>& g, const Vec<Q>& c);

/// The wrench cone of a mode (eqs. 13-17) as the checker sees it: K z = P g, i.e. a_r = w_r . M^-1 (J c + g) for each
/// row r, one row per acceleration that Table 2 constrains (a_n of every fixel, then a_t, skipping free ones). The
/// z are the signed accelerations in the same order (a zero one has none; "a1n", or "-a1n" for a negative one,
/// strict if Table 2 says > 0 or < 0), then the force multipliers: per fixel of l r n m its c_n, as
/// "c<i>[n-mu t]" (l, and the first edge of n m: c = c_n (n - mu t)) or "c<i>[n+mu t]" (r), then per fixel of n m
/// the second edge "c<i>[n+mu t]". This is the order of cone_form.h's rows (E) and columns (V).
struct ConeColumns {
  struct Z {
    bool acceleration = false;
    std::size_t fixel = 0;
    std::size_t row = 0;  ///< acceleration: its row
    int sign = 1;         ///< acceleration: +1, or -1 for a negative one
    Q t_per_n;            ///< force: the force is z (w_n + t_per_n w_t), t_per_n = -+mu_k or -+mu_s
    bool strict = false;
    std::string name;
  };
  std::vector<std::array<Q, 3>> row_wrenches;  ///< per row: the wrench w whose a = w . vdot the row constrains
  std::vector<Z> z;
};

/// The columns of mode `mode` (one Table 2 letter per fixel that fits it), or false.
bool cone_columns(const CheckedScene& scene, const std::string& mode, ConeColumns& out);

/// Whether y (one entry per row) proves the cone of the mode empty: y^T P = 0, y^T K >= 0 and > 0 on a strict z.
/// With M invertible, y^T P = 0 says sum_r y_r w_r = 0, and then y^T K is y_r sign on each acceleration z. Returns
/// "" if it does, else why not.
std::string cone_empty_violation(const ConeColumns& cols, const Vec<Q>& y);

/// Whether y (one entry per row) proves the wrench g outside the cone of the mode (Motzkin): y^T K >= 0,
/// y^T P g <= 0, and y^T P g < 0 or (y^T K)_j > 0 on a strict z. With v = M^-1 sum_r y_r w_r, y^T P g = v . g and
/// (y^T K)_j is sign y_row on an acceleration z, -v . (w_n + t_per_n w_t) on a force z; any positive scale of
/// M^-1 scales P and the force columns alike and changes no sign. Returns "" if it does, else why not.
std::string wrench_outside_violation(const CheckedScene& scene, const ConeColumns& cols, const Vec<Q>& y,
                                     const Vec<Q>& g);

/// The contact forces c = (c_1n..c_kn, c_1t..c_kt) of the fixels `touching` (indices into the scene's fixels,
/// in order) that z applies, against the frames (w_in, w_it) as scaled here: a force z_j of fixel i is
/// z_j (w_in + t_per_n w_it), so it adds z_j to c_in and t_per_n z_j to c_it.
Vec<Q> cone_contact_forces(const ConeColumns& cols, const std::vector<std::size_t>& touching, const Vec<Q>& z);

/// Whether (z, g) solves K z = P g with z's signs, for the certificates' scale of M^-1: diag(p, p, q) for I/m =
/// p/q in lowest terms (a positive multiple of M^-1). Returns "" if it does, else why not.
std::string cone_witness_violation(const CheckedScene& scene, const ConeColumns& cols, const Vec<Q>& z,
                                   const Vec<Q>& g);

}  // namespace contactcert::checker::table2_check
