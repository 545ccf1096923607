#include "checker/spatial_modes_check.h"

#include "checker/sparse_motzkin_reader.h"
#include "checker/spatial_rows.h"

namespace contactcert::checker {

using namespace spatial_check;  // the checker's own reading of a body in space

ModesCertificateCheck check_spatial_modes_certificate(const exact::JsonInput& c) {
  c.expect_keys({"kind", "scene", "problem_sha256", "modes", "dead"});
  const exact::JsonInput embedded = exact::JsonInput::parse(c.at("scene").string(), c.file() + " (embedded scene)");
  const std::vector<Seen> cs = seen(geometry::read_spatial_scene(embedded));
  if (c.at("problem_sha256").string() != embedded.canonical_sha256())
    return {false, "problem_sha256 is not the digest of the embedded scene", 0, 0};
  if (const std::string fault = frame_fault(cs); !fault.empty()) return {false, fault, 0, 0};
  const RowBlocks blocks(cs);
  std::vector<std::string> leaves, dead;
  for (const exact::JsonInput& e : c.at("modes").elements()) {
    e.expect_keys({"mode", "acceleration"});
    std::string m = read_letters(e.at("mode"), cs, true);
    if (!realises(cs, m, e.at("acceleration").rational_vector(6)))
      return {false, "the acceleration listed for mode " + m + " does not realise it", 0, 0};
    leaves.push_back(std::move(m));
  }
  for (const exact::JsonInput& e : c.at("dead").elements()) {
    e.expect_keys({"prefix", "motzkin"});
    std::string p = read_letters(e.at("prefix"), cs, false);
    if (!prefix_motzkin_holds(blocks, p, read_sparse_motzkin_pairs(e.at("motzkin"), blocks.row_count(p))))
      return {false, "the certificate of dead prefix " + p + " does not verify", 0, 0};
    dead.push_back(std::move(p));
  }
  return modes_coverage_check(
      cs.size(), [&](std::size_t i) { return alphabet(cs[i].d.size()); }, dead, leaves);
}

}  // namespace contactcert::checker
