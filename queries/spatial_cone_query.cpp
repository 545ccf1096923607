#include "queries/spatial_cone_query.h"

#include "exact/input_error.h"
#include "geometry/cone_json.h"
#include "solvers/spatial/spatial_cone.h"
#include "solvers/spatial/spatial_cone_certificate.h"

namespace contactcert::queries {
namespace {

namespace sp = solvers::spatial;

SpatialConeAnswer spatial_cone_answer(const SpatialInput& in, const SpatialConeOptions& options) {
  refuse_float(options.common.arith, "a spatial wrench cone is computed exactly (use exact or verified)");
  bool ok = options.mode.size() == in.scene.contacts.size();
  for (std::size_t i = 0; ok && i < options.mode.size(); ++i)
    ok = sp::letters(in.scene.contacts[i].edges.size()).find(options.mode[i]) != std::string::npos;
  if (!ok)
    throw exact::InputError("command line", "--mode",
                            "one letter per contact (" + std::to_string(in.scene.contacts.size()) +
                                "): s, f, or a sliding letter A.. of its pyramid (2m letters for m edges)");
  exact::DdBudget budget;
  budget.deadline = options.common.deadline();
  SpatialConeAnswer a{options.mode, sp::spatial_wrench_cone(in.scene, options.mode, budget)};
  if (options.certificate.empty()) return a;
  a.certificate = options.certificate;
  a.certificate_text = sp::spatial_cone_certificate(in.text, in.scene, options.mode, a.cone, budget.deadline);
  write_certificate_file("cone", a.certificate, a.certificate_text,
                         a.cone.dimension() < 0 ? "the cone is empty" : "the cone in both forms");
  return a;
}

std::string rows_text(const exact::Mat<exact::Q>& M, const std::string& before, const std::string& after) {
  std::string s;
  for (Eigen::Index r = 0; r < M.rows(); ++r)
    s += "    " + before + tuple_text(exact::Vec<exact::Q>(M.row(r).transpose())) + after + "\n";
  return s;
}

}  // namespace

Limited<SpatialConeAnswer> run_spatial_cone(const SpatialInput& in, const SpatialConeOptions& options) {
  return with_limits(options.common.arith, [&] { return spatial_cone_answer(in, options); });
}

json to_json(const SpatialConeAnswer& a) {
  json j;
  j["kind"] = "spatial";
  j["mode"] = a.mode;
  j["cone"] = geometry::nnc_to_json(a.cone);
  if (!a.certificate.empty()) j["certificate"] = a.certificate;
  return j;
}

std::string to_text(const SpatialConeAnswer& a, const std::string& name) {
  const Eigen::Index d = a.cone.dimension();
  std::string s = "wrench cone of mode '" + a.mode + "' on " + name +
                  " (g = force, torque about the com: the wrenches for which the mode has a solution from rest)\n";
  const std::string certificate =
      a.certificate.empty() ? "" : "  certificate: " + a.certificate + " (for `contactcert check`)\n";
  if (d < 0) return s + "  EMPTY\n" + certificate;
  s += "  dimension " + std::to_string(d) + "; face form (g in the cone iff every row holds):\n";
  s += rows_text(a.cone.face.inequalities, "", " . g <= 0") + rows_text(a.cone.face.strict, "", " . g < 0") +
       rows_text(a.cone.face.equalities, "", " . g = 0");
  s += "  closure: " + std::to_string(a.cone.closure.rays.rows()) + " rays, " +
       std::to_string(a.cone.closure.lines.rows()) + " lines, " + std::to_string(a.cone.open_faces.size()) +
       " open faces\n" + rows_text(a.cone.closure.rays, "ray ", "") + rows_text(a.cone.closure.lines, "line ", "");
  return s + certificate;
}

}  // namespace contactcert::queries
