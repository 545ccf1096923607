#include "checker/modes_check.h"

#include "checker/frame_check.h"
#include "checker/table2_rows.h"
#include "solvers/stability/contact_modes.h"
#include "solvers/stability/sparse_motzkin.h"

namespace contactcert::checker {
namespace {

using namespace solvers;  // the mode types the certificate is read into

// A mode or prefix over the alphabet's letters for its fixels (1 to k letters; exactly k for a mode).
ModeString read_letters(const exact::JsonInput& j, const ModeAlphabet& alphabet, std::size_t k, bool prefix) {
  const std::string text = j.string();
  if (text.size() > k || (prefix ? text.empty() : text.size() != k))
    j.fail(prefix ? "a mode prefix of 1 to " + std::to_string(k) + " letters"
                  : "one letter per fixel (" + std::to_string(k) + ")");
  ModeString m;
  for (std::size_t i = 0; i < text.size(); ++i) {
    bool known = false;
    for (Interaction L : alphabet.letters(i)) known = known || static_cast<char>(L) == text[i];
    if (!known)
      j.fail("fixel " + std::to_string(i) + "'s letter '" + std::string(1, text[i]) +
             "' is not one of its letters in this alphabet");
    m.letters.push_back(static_cast<Interaction>(text[i]));
  }
  return m;
}

}  // namespace

ModesCertificateCheck check_modes_certificate(const exact::JsonInput& c) {
  c.expect_keys({"kind", "scene", "problem_sha256", "table2", "unions", "modes", "dead"});
  // The frames are the checker's own (frame_check.h), never the solvers'; the digest is checked first.
  const frame_check::CheckedSceneRead read = frame_check::read_embedded_scene(c);
  if (!read.violation.empty()) return {false, read.violation, 0, 0};
  const geometry::PlanarScene& scene = read.scene;
  const std::string table2 = c.at("table2").string();
  if (table2 != "strict" && table2 != "printed") c.at("table2").fail("expected \"strict\" or \"printed\"");
  std::vector<bool> touching;
  for (const geometry::Fixel& f : scene.fixels) touching.push_back(f.frame.touching());
  const ModeAlphabet alphabet = ModeAlphabet{{touching, table2 == "printed"}, c.at("unions").boolean()};
  const std::size_t k = scene.fixels.size();
  const bool printed = alphabet.rules.printed_separation;
  // The rows and signs are the checker's own (table2_rows.h), rebuilt from the scene's contact frames.
  const table2_check::CheckedScene checked = table2_check::checked_scene(scene, /*touching_only=*/false);
  std::vector<std::string> leaves, dead;
  for (const auto& e : c.at("modes").elements()) {
    e.expect_keys({"mode", "acceleration"});
    const ModeString m = read_letters(e.at("mode"), alphabet, k, false);
    if (!table2_check::realises(checked, m.text(), printed, e.at("acceleration").rational_vector(3)))
      return {false, "the acceleration listed for mode " + m.text() + " does not realise it (Table 2)", 0, 0};
    leaves.push_back(m.text());
  }
  for (const auto& e : c.at("dead").elements()) {
    e.expect_keys({"prefix", "motzkin"});
    const ModeString p = read_letters(e.at("prefix"), alphabet, k, true);
    table2_check::Rows rows;
    if (!table2_check::kinematic_rows(checked, p.text(), printed, rows) ||
        !table2_check::motzkin_holds(rows, read_sparse_motzkin(e.at("motzkin"), rows.rows.size())))
      return {false, "the certificate of dead prefix " + p.text() + " does not verify", 0, 0};
    dead.push_back(p.text());
  }
  return modes_coverage_check(k, alphabet, dead, leaves);
}

namespace {

// The verdict on verified leaves and dead prefixes: valid unless their coverage has a gap.
ModesCertificateCheck coverage_verdict(const std::optional<CoverageGap>& gap, const std::vector<std::string>& dead,
                                       const std::vector<std::string>& leaves) {
  ModesCertificateCheck out{false, "", static_cast<long>(leaves.size()), static_cast<long>(dead.size())};
  if (gap) {
    out.reason = coverage_gap_text(*gap);
    return out;
  }
  out.valid = true;
  out.reason =
      "every feasible mode is listed once, realised by its acceleration, and every other mode extends "
      "exactly one proven dead prefix: " +
      std::to_string(out.modes) + " feasible modes, " + std::to_string(out.dead) + " dead prefixes";
  return out;
}

}  // namespace

ModesCertificateCheck modes_coverage_check(std::size_t k, const ModeAlphabet& alphabet,
                                           const std::vector<std::string>& dead,
                                           const std::vector<std::string>& leaves) {
  return coverage_verdict(mode_coverage(k, alphabet, dead, leaves), dead, leaves);
}

ModesCertificateCheck modes_coverage_check(std::size_t k, const std::function<std::string(std::size_t)>& letters,
                                           const std::vector<std::string>& dead,
                                           const std::vector<std::string>& leaves) {
  return coverage_verdict(mode_coverage(k, letters, dead, leaves), dead, leaves);
}

}  // namespace contactcert::checker
