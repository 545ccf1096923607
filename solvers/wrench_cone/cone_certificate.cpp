#include "solvers/wrench_cone/cone_certificate.h"

#include <nlohmann/json.hpp>

#include "exact/rational_text.h"
#include "exact/strict_feasibility.h"
#include "solvers/stability/frame_check.h"
#include "solvers/stability/sparse_motzkin.h"
#include "solvers/stability/table2_rows_check.h"
#include "solvers/wrench_cone/cone_form.h"
#include "solvers/wrench_cone/contact_model.h"

namespace contactcert::solvers {
namespace {

using Index = Eigen::Index;

nlohmann::ordered_json strings(const Vec<Q>& v) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (Index i = 0; i < v.size(); ++i) a.push_back(exact::to_string(v(i)));
  return a;
}

ConeForm<Q> system_of(const geometry::PlanarScene& scene, const ModeString& mode) {
  return cone_form<Q>(scene, contact_model<Q>(scene), mode);
}

}  // namespace

ConeCertificate cone_certificate(const std::string& scene_text, const geometry::PlanarScene& scene,
                                 const ModeString& mode) {
  const ConeForm<Q> f = system_of(scene, mode);
  const Index k = f.K.cols(), d = f.P.cols();
  // (z, g) with [K | -P] (z, g) = 0, z >= 0, z strict > 0 where Table 2 says so, g free.
  exact::StrictSystem<Q> s;
  s.A = Mat<Q>(f.K.rows(), k + d);
  s.A << f.K, Mat<Q>(-f.P);
  s.b = Vec<Q>::Zero(f.K.rows());
  s.is_free.assign(static_cast<std::size_t>(k + d), false);
  s.strict.assign(static_cast<std::size_t>(k + d), false);
  for (Index j = 0; j < k + d; ++j) {
    s.is_free[static_cast<std::size_t>(j)] = j >= k;
    s.strict[static_cast<std::size_t>(j)] = j < k && f.strict[static_cast<std::size_t>(j)];
  }
  const exact::StrictFeasibility<Q> r = exact::StrictSolver<Q>(s).solve(s.b);
  ConeCertificate out;
  nlohmann::ordered_json& j = out.file;
  const bool empty = r.status == exact::StrictStatus::kInfeasible;
  j["kind"] = empty ? "cone_empty" : "cone_nonempty";
  j["problem_sha256"] = exact::JsonInput::parse(scene_text, "scene").canonical_sha256();
  j["mode"] = mode.text();
  if (empty) {
    j["motzkin"] = sparse_motzkin_json(r.motzkin);
  } else {
    out.wrench = r.x.tail(d);
    out.z = r.x.head(k);
    j["wrench"] = strings(out.wrench);
    j["z"] = strings(out.z);
    j["z_names"] = f.names;
  }
  j["scene"] = scene_text;
  return out;
}

bool is_cone_certificate_kind(const std::string& kind) { return kind == "cone_empty" || kind == "cone_nonempty"; }

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
  const ModeParse mode = parse_mode(c.at("mode").string(), touching);
  if (mode.status != ModeStatus::kValid) c.at("mode").fail(mode.message);
  // K and P are the checker's own (table2_rows_check.h), rebuilt from the scene's contact frames, not cone_form's.
  namespace t2 = table2_check;
  const t2::CheckedScene checked = t2::checked_scene(scene, /*touching_only=*/false);
  t2::ConeColumns cols;
  if (!t2::cone_columns(checked, mode.mode.text(), cols)) c.at("mode").fail("not a mode of Table 2 for this scene");
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

}  // namespace contactcert::solvers
