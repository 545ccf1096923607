#include "queries/spatial_stability_query.h"

#include "exact/input_error.h"
#include "queries/stability_query.h"
#include "solvers/spatial/spatial_stability_certificate.h"

namespace contactcert::queries {
namespace {

namespace sp = solvers::spatial;

SpatialStabilityAnswer spatial_stability_answer(const SpatialInput& in, const SpatialStabilityOptions& options) {
  refuse_float(options.common.arith, "strong stability in space is decided exactly (use exact or verified)");
  if (options.wrench.size() != 6)
    throw exact::InputError("command line", "--wrench", "six numbers fx,fy,fz,tx,ty,tz for a spatial scene");
  sp::SpatialModeOptions tree;
  tree.arith = scene_arith(options.common.arith);
  tree.max_nodes = options.max_nodes;
  tree.deadline = options.common.deadline();
  SpatialStabilityAnswer a{in.scene, options.wrench, sp::spatial_stability(in.scene, options.wrench, tree), {}, {}};
  if (!options.certificate.empty()) {
    a.certificate_text = sp::spatial_stability_certificate(in.scene, in.text, options.wrench, a.result);
    write_certificate_file("stability", options.certificate, a.certificate_text,
                           std::string("the verdict is ") + solvers::verdict_name(a.result.verdict));
    a.certificate = options.certificate;
  }
  return a;
}

exact::Vec<exact::Q> vec(const geometry::Vec3& f) {
  exact::Vec<exact::Q> v(3);
  v << f[0], f[1], f[2];
  return v;
}

json forces_json(const std::vector<geometry::Vec3>& forces) {
  json out = json::array();
  for (const geometry::Vec3& f : forces) out.push_back(exact_json(vec(f)));
  return out;
}

std::string forces_text(const std::vector<geometry::Vec3>& forces) {
  std::string s;
  for (std::size_t i = 0; i < forces.size(); ++i)
    s += "    contact " + std::to_string(i) + ": " + tuple_text(vec(forces[i])) + "\n";
  return s;
}

}  // namespace

Limited<SpatialStabilityAnswer> run_spatial_stability(const SpatialInput& in, const SpatialStabilityOptions& options) {
  return with_limits(options.common.arith, [&] { return spatial_stability_answer(in, options); });
}

json to_json(const SpatialStabilityAnswer& a) {
  const sp::SpatialStability& r = a.result;
  json w = json::object();
  if (r.has_resting) {
    w["resting_weights"] = exact_json(r.resting_weights);
    w["resting_forces"] = forces_json(sp::contact_forces(a.scene, r.resting_weights));
  }
  if (r.has_moving)
    w["moving"] = {{"mode", r.moving.mode},
                   {"acceleration", exact_json(r.moving.acceleration)},
                   {"weights", exact_json(r.moving.weights)},
                   {"forces", forces_json(sp::contact_forces(a.scene, r.moving.weights))}};
  json j;
  j["kind"] = "spatial";
  j["verdict"] = solvers::verdict_name(r.verdict);
  j["wrench"] = exact_json(a.wrench);
  j["contacts"] = a.scene.contacts.size();
  j["witness"] = w;
  put_search_counts(j, r);
  if (!a.certificate.empty()) j["certificate"] = a.certificate;
  return j;
}

std::string to_text(const SpatialStabilityAnswer& a, const std::string& name) {
  const sp::SpatialStability& r = a.result;
  std::string s = std::string("verdict: ") + solvers::verdict_name(r.verdict) +
                  "\n  wrench g = " + tuple_text(a.wrench) + " (force, torque about the com) on " + name + " (" +
                  std::to_string(a.scene.contacts.size()) + " contacts of a body in space)\n";
  if (r.has_resting)
    s += "  at rest with contact forces (world coordinates; they balance g):\n" +
         forces_text(sp::contact_forces(a.scene, r.resting_weights));
  else
    s += "  no contact forces in the friction pyramids balance g (Motzkin certificate found)\n";
  if (r.has_moving)
    s += "  moves in mode '" + r.moving.mode + "' with vdot = " + tuple_text(r.moving.acceleration) +
         " (a of the com, alpha; M vdot = g + the contact wrenches), contact forces:\n" +
         forces_text(sp::contact_forces(a.scene, r.moving.weights));
  else if (r.has_resting)
    s += "  no moving mode admits g: " + std::to_string(r.modes_kinematically_feasible) +
         " kinematically feasible moving modes, each with a proof for g; every other mode extends one of " +
         std::to_string(r.dead_prefixes) + " infeasible prefixes (mode tree: " + std::to_string(r.tree_nodes) +
         " prefixes)\n";
  s += "  LPs: " + std::to_string(r.lps) + "\n";
  if (!a.certificate.empty()) s += "  certificate: " + a.certificate + "\n";
  return s;
}

}  // namespace contactcert::queries
