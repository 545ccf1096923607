#include "checker/spatial_modes_check.h"

#include "checker/spatial_proofs.h"

namespace contactcert::checker {

using namespace spatial_check;  // the checker's own reading of a body in space

ModesCertificateCheck check_spatial_modes_certificate(const CertificateLines& lines) {
  const exact::JsonInput& c = lines.head();
  c.expect_keys({"kind", "scene", "problem_sha256"});
  lines.expect_lists({"vectors", "dead", "modes"});
  const exact::JsonInput embedded = exact::JsonInput::parse(c.at("scene").string(), c.file() + " (embedded scene)");
  const geometry::SpatialScene scene = geometry::read_spatial_scene(embedded);
  const std::vector<Seen> cs = seen(scene);
  if (c.at("problem_sha256").string() != embedded.canonical_sha256())
    return {false, "problem_sha256 is not the digest of the embedded scene", 0, 0};
  if (const std::string fault = frame_fault(cs); !fault.empty()) return {false, fault, 0, 0};
  std::vector<std::string> leaves, dead;
  for (std::size_t at = 0; at < lines.size("modes"); ++at) {
    const exact::JsonInput e = lines.element("modes", at);
    e.expect_keys({"mode", "acceleration"});
    std::string m = read_letters(e.at("mode"), cs, true);
    if (!realises(cs, m, e.at("acceleration").rational_vector(6)))
      return {false, "the acceleration listed for mode " + m + " does not realise it", 0, 0};
    leaves.push_back(std::move(m));
  }
  const SpatialProofs proofs(lines, scene.body, cs, nullptr);
  if (std::string why = proofs.dead_fault(lines, dead); !why.empty()) return {false, why, 0, 0};
  return modes_coverage_check(
      cs.size(), [&](std::size_t i) { return alphabet(cs[i].d.size()); }, dead, leaves);
}

}  // namespace contactcert::checker
