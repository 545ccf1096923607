#include "checker/spatial_stability_check.h"

#include <algorithm>

#include "checker/mode_coverage.h"
#include "checker/sparse_motzkin_reader.h"
#include "checker/spatial_rows.h"

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

/// A Motzkin vector of the certificate's "vectors", read once: its weights by row class (contact, class; RowBlocks)
/// and its six Newton-Euler weights z, with what does not depend on the rows it is applied to verified once: that it
/// balances on vdot's columns (sum_w w (u, r x u) of its classes' directions + M^T z = 0), sgn(z . g), and per
/// contact and edge the sign of -z . (u, r x u), u = n + d_j (the weight column beta_ij of a mode's system).
struct Vector {
  struct Weight {
    std::size_t contact, cls;
    Q w;  ///< on the class's direction
  };
  std::vector<Weight> weights;
  bool dynamics = false;  ///< z != 0
  bool balanced = false;
  int zg = 0;
  std::vector<std::vector<int>> beta_signs;  ///< per contact and edge
};

/// The weight columns' rows (u, r x u), u = n + d_j, per contact and edge: built once per scene.
using EdgeRows = std::vector<std::vector<std::vector<Rows::Entry>>>;

Vector read_vector(const exact::JsonInput& e, const geometry::SpatialBody& body, const RowBlocks& blocks,
                   const EdgeRows& edges, const Vec<Q>& g) {
  e.expect_keys({"rows", "motzkin"});
  const exact::JsonInput rows = e.at("rows");
  const std::size_t n = rows.size();
  const Vec<Q> y = read_sparse_motzkin(e.at("motzkin"), n + 6);  // the rows', then z's
  Vector v;
  Vec<Q> balance = Vec<Q>::Zero(6);
  for (std::size_t r = 0; r < n; ++r) {
    const exact::JsonInput row = rows.at(r);
    if (!row.is_array() || row.size() != 3) row.fail("a row [contact, letter, row of the letter]");
    const auto i = static_cast<std::size_t>(row.at(0).integer(0, static_cast<long>(edges.size()) - 1));
    const std::string L = row.at(1).string();
    const auto* letter = L.size() == 1 ? blocks.rows(i, L[0]) : nullptr;
    if (letter == nullptr) row.at(1).fail("a letter of contact " + std::to_string(i) + ": s, f or A..");
    const RowBlocks::Row& at =
        (*letter)[static_cast<std::size_t>(row.at(2).integer(0, static_cast<long>(letter->size()) - 1))];
    const Q& w = y(static_cast<Eigen::Index>(r));
    if (sgn(w) == 0) row.fail("a row the vector weighs (its motzkin lists every row)");
    for (const Vector::Weight& x : v.weights)
      if (x.contact == i && x.cls == at.cls) row.fail("each functional weighed once: this row's is weighed twice");
    v.weights.push_back({i, at.cls, at.sign > 0 ? w : Q(-w)});
    for (const Rows::Entry& f : blocks.functional(i, at.cls))
      balance(static_cast<Eigen::Index>(f.col)) += v.weights.back().w * f.value;
  }
  const Vec<Q> z = y.tail(6);
  v.dynamics = !z.isZero();
  for (std::size_t d = 0; d < 6 && v.dynamics; ++d)
    for (const Rows::Entry& f : mass_row(body, d))
      balance(static_cast<Eigen::Index>(f.col)) += z(static_cast<Eigen::Index>(d)) * f.value;
  v.balanced = balance.isZero();
  v.zg = sgn(z.dot(g));
  for (const std::vector<std::vector<Rows::Entry>>& contact : edges) {
    std::vector<int>& signs = v.beta_signs.emplace_back(contact.size(), 0);
    for (std::size_t j = 0; j < signs.size() && v.dynamics; ++j) {
      Q dot(0);
      for (const Rows::Entry& f : contact[j]) dot -= z(static_cast<Eigen::Index>(f.col)) * f.value;
      signs[j] = sgn(dot);
    }
  }
  return v;
}

/// Whether v, placed on the rows of `letters` (each weight on its class's row in the letter at its contact, an
/// equality row before a strict one, times the row's sign), is a Motzkin certificate (table2_check::motzkin_holds's
/// conditions) of the letters' kinematic rows (a dead prefix: v has no dynamics weights, b = 0), or with `mode` of the
/// mode's system for g (spatial_stability.h's Newton-Euler rows): balanced on vdot; y <= 0 on every strict row (its
/// slack column); -z . (u, r x u) >= 0 on every weight column the letters allow; z . g <= 0; and z . g < 0 or some
/// strict row's y < 0.
bool proves(const Vector& v, const RowBlocks& blocks, const std::vector<Seen>& cs, const std::string& letters,
            bool mode) {
  if (!v.balanced || (v.dynamics && !mode)) return false;
  bool strict_negative = false;
  for (const Vector::Weight& x : v.weights) {
    if (x.contact >= letters.size()) return false;
    const RowBlocks::Row* on = nullptr;
    for (const RowBlocks::Row& row : *blocks.rows(x.contact, letters[x.contact]))
      if (row.cls == x.cls && (on == nullptr || (on->strict && !row.strict))) on = &row;
    if (on == nullptr) return false;
    const int y = on->sign * sgn(x.w);
    if (on->strict && y > 0) return false;
    strict_negative = strict_negative || (on->strict && y < 0);
  }
  if (!mode) return strict_negative;
  for (std::size_t i = 0; i < letters.size(); ++i)
    for (const std::size_t j : allowed(cs[i].d.size(), letters[i]))
      if (v.beta_signs[i][j] < 0) return false;
  return v.zg < 0 || (v.zg == 0 && strict_negative);
}

/// Why the proofs of a strongly stable verdict do not cover every moving mode (empty if they do): each vector read
/// and verified once (read_vector), each dead prefix (a parent and one of its letters) and each moving mode proven by
/// the vector it names (proves), and together with f..f they partition the mode strings (mode_coverage).
std::string proofs_fault(const CertificateLines& c, const geometry::SpatialBody& body, const std::vector<Seen>& cs,
                         const Vec<Q>& g) {
  const RowBlocks blocks(cs);
  EdgeRows edges;
  for (const Seen& s : cs) {
    edges.emplace_back();
    for (std::size_t j = 0; j < s.d.size(); ++j) edges.back().push_back(along(s, edge_force(s, j)));
  }
  std::vector<Vector> vectors;
  for (std::size_t i = 0; i < c.size("vectors"); ++i)
    vectors.push_back(read_vector(c.element("vectors", i), body, blocks, edges, g));
  auto vector = [&](const exact::JsonInput& id) -> const Vector& {
    if (vectors.empty()) id.fail("an index of \"vectors\", which lists none");
    return vectors[static_cast<std::size_t>(id.integer(0, static_cast<long>(vectors.size()) - 1))];
  };
  const std::size_t k = cs.size();
  const std::string sticking(k, 'f');
  std::vector<std::string> dead, leaves{sticking};
  for (std::size_t at = 0; at < c.size("dead"); ++at) {
    const exact::JsonInput e = c.element("dead", at);
    e.expect_keys({"parent", "letters", "vectors"});
    const std::string parent = read_letters(e.at("parent"), cs, false, true);
    const std::string letters = e.at("letters").string();
    const exact::JsonInput ids = e.at("vectors");
    const std::string alphabet_here = alphabet(cs[parent.size()].d.size());
    if (letters.empty() || letters.find_first_not_of(alphabet_here) != std::string::npos)
      e.at("letters").fail("letters of contact " + std::to_string(parent.size()) + ": s, f or A.., at least one");
    if (ids.size() != letters.size()) ids.fail("one vector index per letter (" + std::to_string(letters.size()) + ")");
    for (std::size_t l = 0; l < letters.size(); ++l) {
      std::string prefix = parent + letters[l];
      if (!proves(vector(ids.at(l)), blocks, cs, prefix, false))
        return "the kinematic proof for prefix " + prefix + " does not verify";
      dead.push_back(std::move(prefix));
    }
  }
  for (std::size_t at = 0; at < c.size("modes"); ++at) {
    const exact::JsonInput e = c.element("modes", at);
    e.expect_keys({"mode", "vector"});
    std::string mode = read_letters(e.at("mode"), cs, true);
    if (mode == sticking) return "a proof for f..f is not evidence beside a resting solution";
    if (!proves(vector(e.at("vector")), blocks, cs, mode, true))
      return "the proof for mode " + mode + " does not verify";
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
