#include "checker/cone_check.h"

#include "checker/frame_check.h"
#include "checker/mode_letters.h"
#include "checker/sparse_motzkin_reader.h"
#include "checker/table2_rows.h"

namespace contactcert::checker {

using exact::Q;
using exact::Vec;

ConeCertificateCheck check_cone_certificate(const exact::JsonInput& c) {
  const std::string kind = c.at("kind").string();
  const bool empty = kind == "cone_empty";
  if (empty)
    c.expect_keys({"kind", "problem_sha256", "mode", "motzkin", "scene"});
  else
    c.expect_keys({"kind", "problem_sha256", "mode", "wrench", "z", "z_names", "contacts", "acceleration", "scene"});
  // The frames are the checker's own (frame_check.h), never the solvers'; the digest is checked first.
  const frame_check::CheckedSceneRead read = frame_check::read_embedded_scene(c);
  if (!read.violation.empty()) return {false, read.violation};
  const geometry::PlanarScene& scene = read.scene;
  std::vector<bool> touching;
  for (const auto& f : scene.fixels) touching.push_back(f.frame.touching());
  const std::string mode = read_mode_letters(c.at("mode"), ModeAlphabet{touching, true, true}, touching.size(), false);
  // K and P are the checker's own (table2_rows.h), rebuilt from the scene's contact frames, not cone_form's.
  namespace t2 = table2_check;
  const t2::CheckedScene checked = t2::checked_scene(scene, /*touching_only=*/false);
  t2::ConeColumns cols;
  if (!t2::cone_columns(checked, mode, cols)) c.at("mode").fail("not a mode of Table 2 for this scene");
  if (empty) {
    const std::string why =
        t2::cone_empty_violation(cols, read_sparse_motzkin(c.at("motzkin"), cols.row_wrenches.size()));
    if (!why.empty()) return {false, why};
    return {true,
            "the Motzkin vector proves that no wrench has the mode (y^T K >= 0, y^T P = 0, > 0 on a strict component)"};
  }
  const Vec<Q> g = c.at("wrench").rational_vector(3);
  const Vec<Q> z = c.at("z").rational_vector(cols.z.size());
  const std::vector<exact::JsonInput> names = c.at("z_names").elements();
  bool same_names = names.size() == cols.z.size();
  for (std::size_t j = 0; same_names && j < names.size(); ++j) same_names = names[j].string() == cols.z[j].name;
  if (!same_names) return {false, "z_names differ from the mode's components"};
  if (const std::string why = t2::cone_witness_violation(checked, cols, z, g); !why.empty()) return {false, why};
  ConeCertificateCheck out{true,
                           "the wrench has the mode with the given forces and accelerations (K z = P g, signs "
                           "of Table 2)"};
  std::vector<std::size_t> touching_fixels;
  for (std::size_t i = 0; i < touching.size(); ++i)
    if (touching[i]) {
      touching_fixels.push_back(i);
      out.touching.push_back(static_cast<Eigen::Index>(i));
    }
  out.forces = t2::cone_contact_forces(cols, touching_fixels, z);
  return out;
}

}  // namespace contactcert::checker
