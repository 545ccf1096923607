#include "solvers/motion/uniqueness_certificate.h"

#include <nlohmann/json.hpp>

#include "solvers/ucp/certificate.h"

namespace contactcert::solvers::motion {
namespace {

using json = nlohmann::ordered_json;
using exact::Vec;

json vectors_json(const std::vector<Vec<Q>>& v) {
  json a = json::array();
  for (const Vec<Q>& x : v) a.push_back(ucp::rationals_json(x));
  return a;
}

}  // namespace

std::string uniqueness_certificate(const ucp::UcpProblem& problem, const MotionUniqueness& u,
                                   const std::string& assembly_text) {
  if (!u.evidence || u.status == UniquenessStatus::kUnknown || u.solution_modes.empty()) return "";
  const UniquenessEvidence& ev = *u.evidence;
  json j = ucp::certificate_header("motion_uniqueness", 1, problem, assembly_text);
  const bool unique = u.status == UniquenessStatus::kUnique;
  j["verdict"] = uniqueness_name(u.status);
  if (unique) {
    j["motion"] = ucp::rationals_json(u.motions[0]);
    json dead = json::array();
    for (const ucp::PrefixEvidence::Dead& d : ev.tree.dead)
      dead.push_back({{"prefix", d.prefix},
                      {"empty", d.x_side ? "X" : "Y"},
                      {"farkas", ucp::integers_json(ucp::written_farkas(problem, d.x_side, d.farkas))}});
    j["dead"] = dead;
    json modes = json::array();
    for (std::size_t i = 0; i < u.solution_modes.size(); ++i)
      modes.push_back({{"mode", u.solution_modes[i]},
                       {"x", ucp::rationals_json(ev.tree.x[i])},
                       {"y", ucp::rationals_json(ev.tree.y[i])}});
    j["solution_modes"] = modes;
    json bounds = json::array();
    for (const UniquenessEvidence::Bound& b : ev.bounds)
      bounds.push_back(
          {{"mode", u.solution_modes[b.mode]}, {"low", vectors_json(b.low)}, {"high", vectors_json(b.high)}});
    j["bounds"] = bounds;
  } else {
    json witnesses = json::array();
    for (std::size_t k = 0; k < 2 && k < ev.witnesses.size(); ++k) {
      const UniquenessEvidence::Witness& w = ev.witnesses[k];
      witnesses.push_back({{"mode", u.solution_modes[w.mode]},
                           {"u", ucp::rationals_json(w.u)},
                           {"x", ucp::rationals_json(w.x)},
                           {"y", ucp::rationals_json(ev.tree.y[w.mode])}});
    }
    j["witnesses"] = witnesses;
  }
  return exact::json_text(j) + "\n";
}

}  // namespace contactcert::solvers::motion
