#include "solvers/stability/stability_certificate.h"

#include <utility>

#include "exact/rational_text.h"
#include "solvers/stability/sparse_motzkin.h"

namespace contactcert::solvers {
namespace {

using json = nlohmann::ordered_json;
using Index = Eigen::Index;

json strings(const Vec<Q>& v) {
  json a = json::array();
  for (Index i = 0; i < v.size(); ++i) a.push_back(exact::to_string(v(i)));
  return a;
}

}  // namespace

json exact_strings(const Vec<Q>& v) { return strings(v); }

json stability_certificate_head(const char* kind, StabilityVerdict v, const std::string& scene_text, const Vec<Q>& g) {
  json j;
  j["kind"] = kind;
  j["verdict"] = verdict_name(v);
  j["wrench"] = strings(g);
  j["scene"] = scene_text;
  j["problem_sha256"] = exact::JsonInput::parse(scene_text, "scene").canonical_sha256();
  return j;
}

json stability_certificate_json(const std::string& scene_text, const Vec<Q>& g, const StabilityResult<Q>& r) {
  json j = stability_certificate_head("stability", r.verdict, scene_text, g);
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
  j["proofs"] = std::move(proofs);
  return j;
}

std::string stability_certificate(const std::string& scene_text, const Vec<Q>& g, const StabilityResult<Q>& r) {
  return exact::json_text(stability_certificate_json(scene_text, g, r), 1) + "\n";
}

}  // namespace contactcert::solvers
