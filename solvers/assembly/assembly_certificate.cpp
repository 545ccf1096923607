#include "solvers/assembly/assembly_certificate.h"

#include <nlohmann/json.hpp>
#include <set>

#include "exact/rational_text.h"
#include "solvers/assembly/assembly_check.h"
#include "solvers/stability/sparse_motzkin.h"

namespace contactcert::solvers::assembly {
namespace {

using json = nlohmann::ordered_json;

json exact_strings(const Vec<Q>& v) {
  json a = json::array();
  for (const Q& x : v) a.push_back(exact::to_string(x));
  return a;
}

/// Rows of the system of `letters` (s l r n *) over N bodies, or of the resting system (docs/formats.md section
/// 3a): the energy row, then per contact s: 1, l r: 2, n: 4, *: 3 (resting: its 2 friction rows), then 3N. Only
/// sizes the vectors read; the checker builds the rows themselves and refuses a vector of another length.
std::size_t system_rows(std::size_t N, const std::string& letters, std::size_t k, bool resting) {
  if (resting) return 2 * k + 3 * N;
  std::size_t rows = 1 + 3 * N;
  for (const char L : letters) rows += L == 's' ? 1 : L == 'n' ? 4 : L == '*' ? 3 : 2;
  return rows;
}

/// A prefix (`whole`: a mode) of k letters over s l r n, or InputError naming the field.
std::string read_letters(const exact::JsonInput& j, std::size_t k, bool whole) {
  const std::string text = j.string();
  if (text.find_first_not_of("slrn") != std::string::npos || text.size() > k || (whole && text.size() != k))
    j.fail(whole ? "a mode: one letter s l r n per contact (" + std::to_string(k) + ")"
                 : "a prefix: at most " + std::to_string(k) + " letters s l r n");
  return text;
}

}  // namespace

std::string assembly_certificate(const std::string& scene_text, const AssemblyStabilityResult& r) {
  json j;
  j["kind"] = "assembly_stability";
  j["verdict"] = verdict_name(r.verdict);
  j["scene"] = scene_text;
  j["problem_sha256"] = exact::JsonInput::parse(scene_text, "scene").canonical_sha256();
  if (r.has_resting)
    j["resting"] = {{"forces", exact_strings(r.resting_forces)}};
  else
    j["resting"] = {{"motzkin", sparse_motzkin_json(r.resting_farkas)}};
  if (r.has_moving)
    j["moving"] = {{"mode", r.moving.mode},
                   {"acceleration", exact_strings(r.moving.acceleration)},
                   {"forces", exact_strings(r.moving.forces)}};
  json dead = json::array();
  for (const AssemblyDeadPrefix& d : r.dead)
    dead.push_back({{"prefix", d.prefix}, {"motzkin", sparse_motzkin_json(d.motzkin)}});
  j["dead"] = dead;
  return j.dump(1) + "\n";
}

AssemblyCertificateCheck check_assembly_certificate(const exact::JsonInput& c) {
  c.expect_keys({"kind", "verdict", "scene", "problem_sha256", "resting", "moving", "dead"});
  const exact::JsonInput embedded = exact::JsonInput::parse(c.at("scene").string(), c.file() + " (embedded scene)");
  const geometry::Assembly a = geometry::read_assembly(embedded);
  const std::size_t N = a.bodies.size(), k = a.contacts.size();
  AssemblyCertificateCheck out{false, "", N, k, 0};
  if (c.at("problem_sha256").string() != embedded.canonical_sha256()) {
    out.reason = "problem_sha256 is not the digest of the embedded scene";
    return out;
  }
  AssemblyStabilityResult claim;
  const std::string verdict = c.at("verdict").string();
  if (verdict == "strongly_stable")
    claim.verdict = AssemblyVerdict::kStronglyStable;
  else if (verdict == "weakly_stable")
    claim.verdict = AssemblyVerdict::kWeaklyStable;
  else if (verdict == "unstable")
    claim.verdict = AssemblyVerdict::kUnstable;
  else
    c.at("verdict").fail("expected strongly_stable, weakly_stable or unstable");
  const exact::JsonInput resting = c.at("resting");
  if (const auto f = resting.find("forces")) {
    resting.expect_keys({"forces"});
    claim.has_resting = true;
    claim.resting_forces = f->rational_vector(2 * k);
  } else {
    resting.expect_keys({"motzkin"});
    claim.resting_farkas = read_sparse_motzkin(resting.at("motzkin"), system_rows(N, "", k, true));
  }
  if (const auto m = c.find("moving")) {
    m->expect_keys({"mode", "acceleration", "forces"});
    claim.has_moving = true;
    claim.moving = {read_letters(m->at("mode"), k, true), m->at("acceleration").rational_vector(3 * N),
                    m->at("forces").rational_vector(2 * k)};
  }
  std::set<std::string> listed;
  for (const exact::JsonInput& d : c.at("dead").elements()) {
    d.expect_keys({"prefix", "motzkin"});
    std::string prefix = read_letters(d.at("prefix"), k, false);
    if (!listed.insert(prefix).second) {
      out.reason = "dead prefix \"" + prefix + "\" is listed twice";
      return out;
    }
    const std::string letters = prefix + std::string(k - prefix.size(), '*');
    claim.dead.push_back({std::move(prefix), read_sparse_motzkin(d.at("motzkin"), system_rows(N, letters, k, false))});
  }
  out.dead = claim.dead.size();
  const std::string why = check_assembly_stability(a, claim);
  out.valid = why.empty();
  out.reason = why.empty() ? "every vector of the evidence verifies exactly: " + verdict : why;
  return out;
}

}  // namespace contactcert::solvers::assembly
