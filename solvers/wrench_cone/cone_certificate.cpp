#include "solvers/wrench_cone/cone_certificate.h"

#include <nlohmann/json.hpp>

#include "exact/rational_text.h"
#include "exact/strict_feasibility.h"
#include "solvers/stability/sparse_motzkin.h"
#include "solvers/wrench_cone/cone_form.h"
#include "solvers/wrench_cone/contact_model.h"

namespace contactcert::solvers {
namespace {

using Index = Eigen::Index;

nlohmann::ordered_json strings(const Vec<Q>& v) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (Index i = 0; i < v.size(); ++i) a.push_back(exact::to_string(v(i)));
  return a;
}

ConeForm<Q> system_of(const geometry::PlanarScene& scene, const ModeString& mode) {
  return cone_form<Q>(scene, contact_model<Q>(scene), mode);
}

}  // namespace

ConeCertificate cone_certificate(const std::string& scene_text, const geometry::PlanarScene& scene,
                                 const ModeString& mode) {
  const ConeForm<Q> f = system_of(scene, mode);
  const Index k = f.K.cols(), d = f.P.cols();
  // (z, g) with [K | -P] (z, g) = 0, z >= 0, z strict > 0 where Table 2 says so, g free.
  exact::StrictSystem<Q> s;
  s.A = Mat<Q>(f.K.rows(), k + d);
  s.A << f.K, Mat<Q>(-f.P);
  s.b = Vec<Q>::Zero(f.K.rows());
  s.is_free.assign(static_cast<std::size_t>(k + d), false);
  s.strict.assign(static_cast<std::size_t>(k + d), false);
  for (Index j = 0; j < k + d; ++j) {
    s.is_free[static_cast<std::size_t>(j)] = j >= k;
    s.strict[static_cast<std::size_t>(j)] = j < k && f.strict[static_cast<std::size_t>(j)];
  }
  const exact::StrictFeasibility<Q> r = exact::StrictSolver<Q>(s).solve(s.b);
  ConeCertificate out;
  nlohmann::ordered_json& j = out.file;
  const bool empty = r.status == exact::StrictStatus::kInfeasible;
  j["kind"] = empty ? "cone_empty" : "cone_nonempty";
  j["problem_sha256"] = exact::JsonInput::parse(scene_text, "scene").canonical_sha256();
  j["mode"] = mode.text();
  if (empty) {
    j["motzkin"] = sparse_motzkin_json(r.motzkin);
  } else {
    out.wrench = r.x.tail(d);
    out.z = r.x.head(k);
    j["wrench"] = strings(out.wrench);
    j["z"] = strings(out.z);
    j["z_names"] = f.names;
  }
  j["scene"] = scene_text;
  return out;
}

bool is_cone_certificate_kind(const std::string& kind) { return kind == "cone_empty" || kind == "cone_nonempty"; }

}  // namespace contactcert::solvers
