#include "solvers/stability/stability_certificate.h"

#include <nlohmann/json.hpp>

#include "exact/rational_text.h"
#include "solvers/stability/frame_check.h"
#include "solvers/stability/sparse_motzkin.h"
#include "solvers/stability/table2_rows_check.h"

namespace contactcert::solvers {
namespace {

using json = nlohmann::ordered_json;
using Index = Eigen::Index;

json strings(const Vec<Q>& v) {
  json a = json::array();
  for (Index i = 0; i < v.size(); ++i) a.push_back(exact::to_string(v(i)));
  return a;
}

// A mode of the k touching fixels, or with `prefix` one of its prefixes (1 to k letters).
ModeString read_mode(const exact::JsonInput& j, std::size_t k, bool prefix = false) {
  const std::string text = j.string();
  if (prefix && (text.empty() || text.size() > k))
    j.fail("a mode prefix: 1 to " + std::to_string(k) + " letters from s l r n");
  const ModeParse p = parse_mode(text, std::vector<bool>(prefix ? text.size() : k, true));
  if (p.status != ModeStatus::kValid) j.fail(p.message);
  if (text.find_first_not_of("slrn") != std::string::npos)
    j.fail("only the letters s l r n describe motion from rest (strong stability, section 7)");
  return p.mode;
}

}  // namespace

std::string stability_certificate(const std::string& scene_text, const Vec<Q>& g, const StabilityResult<Q>& r) {
  json j;
  j["kind"] = "stability";
  j["verdict"] = verdict_name(r.verdict);
  j["wrench"] = strings(g);
  j["scene"] = scene_text;
  j["problem_sha256"] = exact::JsonInput::parse(scene_text, "scene").canonical_sha256();
  if (r.has_resting)
    j["resting"] = {{"forces", strings(r.resting_forces)}};
  else
    j["resting"] = {{"motzkin", sparse_motzkin_json(r.resting_farkas)}};
  if (r.has_moving)
    j["moving"] = {{"mode", r.moving.mode.text()},
                   {"forces", strings(r.moving.forces)},
                   {"acceleration", strings(r.moving.acceleration)}};
  json proofs = json::array();
  for (const auto& p : r.proofs)
    proofs.push_back(
        {{"mode", p.mode.text()}, {"kinematic", p.kinematic}, {"motzkin", sparse_motzkin_json(p.motzkin)}});
  j["proofs"] = proofs;
  return j.dump(1) + "\n";
}

StabilityCertificateCheck check_stability_certificate(const exact::JsonInput& c) {
  c.expect_keys({"kind", "verdict", "wrench", "scene", "problem_sha256", "resting", "moving", "proofs"});
  // The frames are the checker's own (frame_check.h), never the solvers'; the digest is checked first.
  const frame_check::CheckedSceneRead read = frame_check::read_embedded_scene(c);
  if (!read.violation.empty()) return {false, read.violation};
  const geometry::PlanarScene& scene = read.scene;
  const std::size_t k = touching_scene(scene).fixels.size();
  StabilityResult<Q> claim;
  const std::string verdict = c.at("verdict").string();
  if (verdict == "strongly_stable")
    claim.verdict = StabilityVerdict::kStronglyStable;
  else if (verdict == "weakly_stable")
    claim.verdict = StabilityVerdict::kWeaklyStable;
  else if (verdict == "unstable")
    claim.verdict = StabilityVerdict::kUnstable;
  else
    c.at("verdict").fail("expected strongly_stable, weakly_stable or unstable");
  const Vec<Q> g = c.at("wrench").rational_vector(3);
  // The Motzkin vectors are read against the row counts of the checker's own systems (table2_rows_check.h).
  namespace t2 = table2_check;
  const t2::CheckedScene checked = t2::checked_scene(scene, /*touching_only=*/true);
  const exact::JsonInput resting = c.at("resting");
  if (auto f = resting.find("forces")) {
    resting.expect_keys({"forces", "contacts"});
    claim.has_resting = true;
    claim.resting_forces = f->rational_vector(2 * k);
  } else {
    resting.expect_keys({"motzkin"});
    claim.resting_farkas = read_sparse_motzkin(resting.at("motzkin"), t2::resting_rows(checked, g).rows.size());
  }
  if (auto m = c.find("moving")) {
    m->expect_keys({"mode", "forces", "acceleration", "contacts"});
    claim.has_moving = true;
    claim.moving = {read_mode(m->at("mode"), k), m->at("forces").rational_vector(2 * k),
                    m->at("acceleration").rational_vector(3)};
  }
  if (auto ps = c.find("proofs"))
    for (const auto& p : ps->elements()) {
      p.expect_keys({"mode", "kinematic", "motzkin"});
      const bool kinematic = p.at("kinematic").boolean();
      const ModeString mode = read_mode(p.at("mode"), k, kinematic);
      t2::Rows rows;  // read_mode admits only modes and prefixes that have these rows
      if (kinematic ? !t2::kinematic_rows(checked, mode.text(), false, rows)
                    : !t2::motion_rows(checked, mode.text(), g, rows))
        p.at("mode").fail("a mode of the touching fixels over s l r n");
      claim.proofs.push_back({mode, kinematic, read_sparse_motzkin(p.at("motzkin"), rows.rows.size())});
    }
  const std::string why = check_stability(scene, g, claim);
  return {why.empty(), why.empty() ? std::string("every vector of the evidence verifies exactly: ") + verdict : why};
}

}  // namespace contactcert::solvers
