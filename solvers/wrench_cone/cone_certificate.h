// Certificates of a wrench cone's verdict (`cone --certificate F`; their checker: checker/cone_check.h).
// The wrench cone of a mode is { g : K z = P g for some z >= 0 with z_j > 0 on the strict components }
// (Balkcom-Trinkle eqs. 13-17). Both kinds embed the scene (its text under "scene", its digest under
// "problem_sha256") and the "mode":
//   "cone_nonempty": a witness, "wrench" g and "z" (forces and accelerations, named in "z_names") with
//     K z = P g, z >= 0 and z_j > 0 on the strict components (a readable view of the witness, "contacts" and
//     "acceleration", may follow; cli/cone.cpp writes it and `check` compares it with its own);
//   "cone_empty": a Motzkin vector y (sparse, solvers/stability/sparse_motzkin.h) with y^T K >= 0, y^T P = 0 and (y^T
//   K)_j > 0 on some strict component j
//     (if some (z, g) solved the system, 0 = y^T P g = y^T K z > 0).
// The checker rebuilds K, P and the strict components from the embedded scene and mode with its own code
// (checker/table2_rows.h, not cone_form.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "exact/json_input.h"
#include "exact/number.h"
#include "geometry/planar_scene.h"
#include "solvers/wrench_cone/mode.h"

namespace contactcert::solvers {

/// A wrench cone certificate: the file's JSON ("scene" its last key) and, for "cone_nonempty", its witness.
struct ConeCertificate {
  nlohmann::ordered_json file;
  exact::Vec<exact::Q> wrench{};  ///< g of a witness (empty for "cone_empty")
  exact::Vec<exact::Q> z{};       ///< z of a witness, K z = P g (empty for "cone_empty")
  bool witness() const { return z.size() > 0; }
};

/// The certificate of the wrench cone of `mode` in `scene` (read from `scene_text`).
ConeCertificate cone_certificate(const std::string& scene_text, const geometry::PlanarScene& scene,
                                 const ModeString& mode);

/// True if `kind` names a wrench cone certificate.
bool is_cone_certificate_kind(const std::string& kind);

}  // namespace contactcert::solvers
