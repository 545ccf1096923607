// The proofs of the spatial certificates in lines (docs/formats.md sections 5b and 5c), shared by
// checker/spatial_modes_check.h and checker/spatial_stability_check.h: the list "vectors" (each distinct Motzkin
// vector once, by the functionals it weighs), each read and verified once, and the list "dead" (the dead prefixes by
// their parent, each naming its vector), each prefix proven by placing its vector on the prefix's rows.
#pragma once

#include <string>
#include <vector>

#include "checker/certificate_lines.h"
#include "checker/spatial_rows.h"

namespace contactcert::checker::spatial_check {

/// The certificate's vectors, read once: per vector its weights by row class (contact, class; RowBlocks) and, with
/// the Newton-Euler rows (a spatial_stability certificate, for wrench g), its six weights z, with what does not depend
/// on the rows it is applied to verified once: that it balances on vdot's columns (sum_w w (u, r x u) of its classes'
/// directions + M^T z = 0), sgn(z . g), and per contact and edge the sign of -z . (u, r x u), u = n + d_j (the weight
/// column beta_ij of a mode's system).
class SpatialProofs {
 public:
  struct Vector;  ///< a vector read and verified once (spatial_proofs.cpp)

  /// Reads list "vectors" of c; `g` null: the vectors have no Newton-Euler rows (a spatial_modes certificate).
  SpatialProofs(const CertificateLines& c, const geometry::SpatialBody& body, const std::vector<Seen>& cs,
                const exact::Vec<exact::Q>* g);
  ~SpatialProofs();
  SpatialProofs(const SpatialProofs&) = delete;
  SpatialProofs& operator=(const SpatialProofs&) = delete;

  /// Whether the vector of index `id` (InputError naming the field if there is none), placed on the rows of
  /// `letters` (each weight on its class's row in the letter at its contact, an equality row before a strict one,
  /// times the row's sign), is a Motzkin certificate (table2_check::motzkin_holds's conditions) of the letters'
  /// kinematic rows (a dead prefix: no Newton-Euler weights, b = 0), or with `mode` of the mode's system for g
  /// (spatial_stability.h's Newton-Euler rows): balanced on vdot; y <= 0 on every strict row (its slack column);
  /// -z . (u, r x u) >= 0 on every weight column the letters allow; z . g <= 0; and z . g < 0 or some strict row's
  /// y < 0. A dead prefix's rows also hold n . A vdot >= 0 at every contact past its letters (every letter implies
  /// it: s > 0, the others = 0, so every mode extending the prefix meets them): a weight on the normal's class there
  /// stands on that row, with y <= 0 (its slack sigma >= 0), and proves nothing strict. Motzkin's transposition
  /// theorem for rows f_r . v = 0 (E), >= 0 (N), > 0 (S): no v meets them all iff some y has sum_r y_r f_r = 0,
  /// y_r <= 0 on N and S and y_r < 0 on some row of S (if v met them, 0 = sum y_r f_r . v <= y_s f_s . v < 0).
  bool proves(const exact::JsonInput& id, const std::string& letters, bool mode) const;

  /// The dead prefixes of list "dead" ({"parent", "letters", "vectors"}), each proven by the vector it names, appended
  /// to `dead`; the first that is not, as a reason (empty if all are). Malformed lines throw InputError.
  std::string dead_fault(const CertificateLines& c, std::vector<std::string>& dead) const;

 private:
  const std::vector<Seen>& cs_;
  RowBlocks blocks_;
  std::vector<Vector> vectors_;
};

}  // namespace contactcert::checker::spatial_check
