#include "solvers/assembly/assembly_certificate.h"

#include <nlohmann/json.hpp>

#include "exact/rational_text.h"
#include "solvers/stability/sparse_motzkin.h"

namespace contactcert::solvers::assembly {
namespace {

using json = nlohmann::ordered_json;

json exact_strings(const Vec<Q>& v) {
  json a = json::array();
  for (const Q& x : v) a.push_back(exact::to_string(x));
  return a;
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
  // The walk's contact order, where a dead prefix has letters and it is not the file's (a certificate without it
  // reads its prefixes in the file's order).
  bool order_matters = false;
  for (const AssemblyDeadPrefix& d : r.dead) order_matters = order_matters || !d.prefix.empty();
  bool in_file_order = true;
  for (std::size_t i = 0; i < r.contact_order.size(); ++i) in_file_order = in_file_order && r.contact_order[i] == i;
  if (order_matters && !in_file_order) j["contact_order"] = r.contact_order;
  json dead = json::array();
  for (const AssemblyDeadPrefix& d : r.dead)
    dead.push_back({{"prefix", d.prefix}, {"motzkin", sparse_motzkin_json(d.motzkin)}});
  j["dead"] = dead;
  return j.dump(1) + "\n";
}

}  // namespace contactcert::solvers::assembly
