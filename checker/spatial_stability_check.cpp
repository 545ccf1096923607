#include "checker/spatial_stability_check.h"

#include <algorithm>

#include "checker/mode_coverage.h"
#include "checker/sparse_motzkin_reader.h"
#include "checker/spatial_proofs.h"

namespace contactcert::checker {
namespace {

using exact::Q;
using exact::Vec;
using geometry::Vec3;
using namespace spatial_check;  // the checker's own reading of a body in space
using solvers::StabilityVerdict;
using solvers::verdict_name;
using table2_check::Rows;

/// Why weights beta (every edge of every contact) with acceleration vdot are not a solution in `mode`: a negative
/// weight, a weight the letter does not allow, or Newton-Euler violated. Empty if they are one.
std::string motion_fault(const geometry::SpatialBody& body, const std::vector<Seen>& cs, const std::string& mode,
                         const Vec<Q>& g, const Vec<Q>& vdot, const Vec<Q>& beta) {
  Vec<Q> residual = -g;  // M vdot - sum beta (u, r x u) - g, entry by entry
  for (std::size_t d = 0; d < 6; ++d)
    for (const Rows::Entry& e : mass_row(body, d))
      residual(static_cast<Eigen::Index>(d)) += e.value * vdot(static_cast<Eigen::Index>(e.col));
  Eigen::Index at = 0;
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const std::vector<std::size_t> ok = allowed(cs[i].d.size(), mode[i]);
    for (std::size_t j = 0; j < cs[i].d.size(); ++j, ++at) {
      const int s = sgn(beta(at));
      if (s < 0) return "a negative weight at contact " + std::to_string(i);
      if (s == 0) continue;
      if (std::find(ok.begin(), ok.end(), j) == ok.end())
        return "contact " + std::to_string(i) + " carries force on edge " + std::to_string(j) + ", which letter " +
               mode[i] + " does not allow";
      for (const Rows::Entry& e : along(cs[i], edge_force(cs[i], j)))
        residual(static_cast<Eigen::Index>(e.col)) -= beta(at) * e.value;
    }
  }
  for (Eigen::Index d = 0; d < 6; ++d)
    if (sgn(residual(d)) != 0) return "Newton-Euler does not hold (M vdot != g + the contact wrenches)";
  return {};
}

/// Why the proofs of a strongly stable verdict do not cover every moving mode (empty if they do): each vector read
/// and verified once (SpatialProofs), each dead prefix (a parent and one of its letters) and each moving mode proven by
/// the vector it names (proves), and together with f..f they partition the mode strings (mode_coverage).
std::string proofs_fault(const CertificateLines& c, const geometry::SpatialBody& body, const std::vector<Seen>& cs,
                         const Vec<Q>& g) {
  const SpatialProofs proofs(c, body, cs, &g);
  const std::size_t k = cs.size();
  const std::string sticking(k, 'f');
  std::vector<std::string> dead, leaves{sticking};
  if (std::string why = proofs.dead_fault(c, dead); !why.empty()) return why;
  for (std::size_t at = 0; at < c.size("modes"); ++at) {
    const exact::JsonInput e = c.element("modes", at);
    e.expect_keys({"mode", "vector"});
    std::string mode = read_letters(e.at("mode"), cs, true);
    if (mode == sticking) return "a proof for f..f is not evidence beside a resting solution";
    if (!proofs.proves(e.at("vector"), mode, true)) return "the proof for mode " + mode + " does not verify";
    leaves.push_back(std::move(mode));
  }
  if (auto gap = mode_coverage(
          k, [&](std::size_t i) { return alphabet(cs[i].d.size()); }, dead, leaves))
    return gap->kind == CoverageGap::Kind::kMissing
               ? "no proof covers the moving modes that start with '" + gap->prefix + "'"
               : coverage_gap_text(*gap);
  return {};
}

StabilityVerdict read_verdict(const exact::JsonInput& v) {
  const std::string s = v.string();
  for (const StabilityVerdict x :
       {StabilityVerdict::kStronglyStable, StabilityVerdict::kWeaklyStable, StabilityVerdict::kUnstable})
    if (s == verdict_name(x)) return x;
  v.fail("expected strongly_stable, weakly_stable or unstable");
}

}  // namespace

StabilityCertificateCheck check_spatial_stability_certificate(const CertificateLines& lines) {
  const exact::JsonInput& c = lines.head();
  c.expect_keys({"kind", "verdict", "wrench", "scene", "problem_sha256", "resting", "moving"});
  lines.expect_lists({"vectors", "dead", "modes"});
  const exact::JsonInput embedded = exact::JsonInput::parse(c.at("scene").string(), c.file() + " (embedded scene)");
  const geometry::SpatialScene scene = geometry::read_spatial_scene(embedded);
  const std::vector<Seen> cs = seen(scene);
  if (c.at("problem_sha256").string() != embedded.canonical_sha256())
    return {false, "problem_sha256 is not the digest of the embedded scene"};
  if (const std::string fault = frame_fault(cs); !fault.empty()) return {false, fault};
  const StabilityVerdict claimed = read_verdict(c.at("verdict"));
  const Vec<Q> g = c.at("wrench").rational_vector(6);
  const std::size_t k = cs.size();
  std::size_t edges = 0;
  for (const Seen& s : cs) edges += s.d.size();
  const std::string sticking(k, 'f');
  const Vec<Q> zero = Vec<Q>::Zero(6);

  // Resting: weights that balance g, or a Motzkin vector of the resting rows.
  const exact::JsonInput resting = c.at("resting");
  bool rests = false;
  if (const auto w = resting.find("weights")) {
    resting.expect_keys({"weights"});
    if (std::string why = motion_fault(scene.body, cs, sticking, g, zero, w->rational_vector(edges)); !why.empty())
      return {false, "the resting forces: " + why};
    rests = true;
  } else {
    resting.expect_keys({"motzkin"});
    const Rows rows = motion_rows(scene.body, cs, sticking, g, true);
    if (!table2_check::motzkin_holds(rows, read_sparse_motzkin(resting.at("motzkin"), rows.rows.size())))
      return {false, "the certificate that no resting solution exists does not verify"};
  }
  // Moving: a solution with vdot != 0, or (beside a resting solution) proofs covering every moving mode.
  bool moves = false;
  if (const auto m = c.find("moving")) {
    m->expect_keys({"mode", "weights", "acceleration"});
    const std::string mode = read_letters(m->at("mode"), cs, true);
    const Vec<Q> vdot = m->at("acceleration").rational_vector(6);
    if (vdot == zero) return {false, "the moving witness does not move"};
    if (!realises(cs, mode, vdot)) return {false, "the moving witness's acceleration does not realise mode " + mode};
    if (std::string why = motion_fault(scene.body, cs, mode, g, vdot, m->at("weights").rational_vector(edges));
        !why.empty())
      return {false, "the moving witness: " + why};
    moves = true;
  }
  // Strongly stable: proofs covering every moving mode (f..f needs none beside a resting solution).
  const bool proofs = lines.size("vectors") + lines.size("dead") + lines.size("modes") > 0;
  if (proofs && (!rests || moves))
    return {false, "the proofs are extra entries: they are evidence only of a strongly stable verdict"};
  if (rests && !moves) {
    if (std::string why = proofs_fault(lines, scene.body, cs, g); !why.empty()) return {false, why};
  }
  const StabilityVerdict v = !rests  ? StabilityVerdict::kUnstable
                             : moves ? StabilityVerdict::kWeaklyStable
                                     : StabilityVerdict::kStronglyStable;
  if (v != claimed) return {false, std::string("the evidence supports ") + verdict_name(v)};
  return {true, std::string("every vector of the evidence verifies exactly: ") + verdict_name(v)};
}

}  // namespace contactcert::checker
