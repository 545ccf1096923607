#include "checker/stability_check.h"

#include "checker/frame_check.h"
#include "checker/mode_coverage.h"
#include "checker/sparse_motzkin_reader.h"
#include "checker/table2_rows.h"

namespace contactcert::checker {
namespace {

using exact::Q;
using exact::Vec;
using Index = Eigen::Index;
using namespace solvers;  // the verdict and mode types the certificates are read into

/// Whether every letter is one of s l r n, the letters of motion from rest at a touching fixel (section 7).
bool motion_letters(const std::string& letters) { return letters.find_first_not_of("slrn") == std::string::npos; }

// A mode of the k touching fixels over s l r n, the letters of motion from rest (section 7), or with `prefix` one of
// its prefixes (1 to k letters).
ModeString read_mode(const exact::JsonInput& j, std::size_t k, bool prefix = false) {
  ModeString m;
  for (const char L : read_mode_letters(j, ModeAlphabet{}, k, prefix)) m.letters.push_back(static_cast<Interaction>(L));
  return m;
}

}  // namespace

std::string check_stability(const geometry::PlanarScene& full, const Vec<Q>& g, const StabilityResult<Q>& claim) {
  // Every row is the checker's own (table2_rows.h), rebuilt from the scene's contact frames.
  namespace t2 = table2_check;
  const t2::CheckedScene scene = t2::checked_scene(full, /*touching_only=*/true);
  const std::size_t k = scene.fixels.size();
  if (g.size() != 3) return "the wrench must have 3 entries";
  // Resting evidence: a point (J c + g = 0, c in the friction cones) or a Motzkin certificate.
  bool resting = false;
  if (claim.has_resting) {
    if (std::string why = t2::resting_violation(scene, g, claim.resting_forces); !why.empty()) return why;
    resting = true;
  } else if (!t2::motzkin_holds(t2::resting_rows(scene, g), claim.resting_farkas)) {
    return "the certificate that no resting solution exists does not verify";
  }
  // Moving evidence: a witness solution, or one proof per moving mode.
  bool moving = false;
  if (claim.has_moving) {
    const MotionWitness<Q>& w = claim.moving;
    if (w.mode.letters.size() != k) return "the witness mode has the wrong length";
    if (!motion_letters(w.mode.text())) return "the witness mode: only the letters s l r n describe motion from rest";
    if (w.acceleration.size() != 3 || w.forces.size() != static_cast<Index>(2 * k)) return "witness sizes";
    if (w.acceleration.isZero()) return "the witness does not move";
    if (std::string why = t2::motion_violation(scene, w.mode.text(), g, w.acceleration, w.forces); !why.empty())
      return "the moving witness violates its mode: " + why;
    moving = true;
  } else if (resting) {
    // Every moving mode is covered: it extends a dead prefix (kinematic proof, any g) or has its own proof for
    // g; n..n needs none beside a resting solution.
    std::vector<std::string> dead, leaves{std::string(k, 'n')};
    t2::Rows rows;
    for (const ModeProof<Q>& p : claim.proofs) {
      const std::string text = p.mode.text();
      if (!motion_letters(text)) return "proof for '" + text + "': only the letters s l r n describe motion from rest";
      if (p.kinematic) {
        if (p.mode.letters.empty() || p.mode.letters.size() > k)
          return "a dead prefix of the wrong length: '" + text + "'";
        if (!t2::kinematic_rows(scene, text, false, rows) || !t2::motzkin_holds(rows, p.motzkin))
          return "the kinematic proof for prefix " + text + " does not verify";
        dead.push_back(text);
      } else {
        if (p.mode.letters.size() != k) return "proof for '" + text + "': a mode has one letter per touching fixel";
        if (text == leaves.front())
          return "a proof for n..n is not evidence (it moves only without a resting solution)";
        if (!t2::motion_rows(scene, text, g, rows) || !t2::motzkin_holds(rows, p.motzkin))
          return "the proof for mode " + text + " does not verify";
        leaves.push_back(text);
      }
    }
    if (auto gap = mode_coverage(k, ModeAlphabet{}, dead, leaves))
      return gap->kind == CoverageGap::Kind::kMissing
                 ? "no proof covers the moving modes that start with '" + gap->prefix + "'"
                 : coverage_gap_text(*gap);
  }
  if (claim.proofs.size() && (!resting || moving))
    return "the proofs are extra entries: they are evidence only beside a resting solution and no moving witness "
           "(strongly stable)";
  const StabilityVerdict v = !resting ? StabilityVerdict::kUnstable
                             : moving ? StabilityVerdict::kWeaklyStable
                                      : StabilityVerdict::kStronglyStable;
  if (v != claim.verdict) return std::string("the evidence supports ") + verdict_name(v);
  return "";
}

StabilityCertificateCheck check_stability_certificate(const exact::JsonInput& c) {
  c.expect_keys({"kind", "verdict", "wrench", "scene", "problem_sha256", "resting", "moving", "proofs"});
  // The frames are the checker's own (frame_check.h), never the solvers'; the digest is checked first.
  const frame_check::CheckedSceneRead read = frame_check::read_embedded_scene(c);
  if (!read.violation.empty()) return {false, read.violation};
  const geometry::PlanarScene& scene = read.scene;
  const std::size_t k = solvers::touching_scene(scene).fixels.size();
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
  // The Motzkin vectors are read against the row counts of the checker's own systems (table2_rows.h).
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

}  // namespace contactcert::checker
