// run_assembly_ucp and its writers (queries/assembly_query.h): Pang, Trinkle and Lo's problem for N bodies.
#include "exact/rational_text.h"
#include "queries/assembly_query.h"
#include "queries/assembly_svg.h"
#include "queries/ucp_query.h"
#include "solvers/assembly/assembly_ucp.h"

namespace contactcert::queries {

namespace ucp = solvers::ucp;
using exact::Q;

namespace {

Limited<AssemblyUcpAnswer> assembly_ucp_answer(const AssemblyInput& in, const AssemblyUcpOptions& options) {
  refuse_float(options.common.arith,
               "an assembly's quasistatic problem is solved exactly here (use exact, verified or adaptive)");
  check_uniqueness_options(options.uniqueness, options.common.arith);
  const geometry::Assembly& a = in.assembly;
  ucp::UcpProblem problem;
  problem.quasistatic = solvers::assembly::assembly_quasistatic(a, in.name);
  problem.set(ucp::build_ucp(*problem.quasistatic));
  ucp::UcpOptions o;
  o.arith = options.common.arith;
  o.max_nodes = options.max_nodes;
  o.max_bases = options.max_bases;
  o.time_limit = options.common.time_limit;
  AssemblyUcpAnswer ans;
  ans.report = ucp::solve_ucp(problem, o);
  if (const auto& p = ans.report.physical) {
    const exact::Vec<Q> q_dot = p->q_dot.to_q(), c_n = p->c_n.to_q(), c_t = p->c_t.to_q();
    for (std::size_t b = 0; b < a.bodies.size(); ++b) {
      const exact::Vec<Q> v = q_dot.segment(static_cast<Eigen::Index>(3 * b), 3);
      const geometry::Point2& com = a.bodies[b].com;
      ans.bodies.push_back({v, {v(0) - v(2) * com.y, v(1) + v(2) * com.x}});
    }
    exact::Vec<Q> c(c_n.size() + c_t.size());
    c << c_n, c_t;
    ans.forces = assembly_forces(a, c);
  }
  // The certificate embeds the assembly too: its checker derives P, Jn and Jt from the geometry itself.
  if (!options.certificate.empty()) ans.certificate_text = ucp::certificate_text(problem, ans.report, in.text);
  write_files(in, options, ans);
  Limited<std::optional<UniquenessAnswer>> u = decide_uniqueness(
      problem, ans.report, options.uniqueness, options.common.arith, command_name(options) + " " + in.name, in.text);
  if (!u) return u.limit();
  ans.uniqueness = *std::move(u);
  return ans;
}

}  // namespace

Limited<AssemblyUcpAnswer> run_assembly_ucp(const AssemblyInput& in, const AssemblyUcpOptions& options) {
  return with_limits(options.common.arith, [&] { return assembly_ucp_answer(in, options); });
}

json to_json(const AssemblyUcpAnswer& ans) {
  const ucp::UcpReport& r = ans.report;
  json j = report_head_json(r, false);
  if (r.physical) {
    json bodies = json::array();
    for (std::size_t b = 0; b < ans.bodies.size(); ++b)
      bodies.push_back({{"body", b},
                        {"q_dot", exact_json(ans.bodies[b].q_dot)},
                        {"com_velocity", json::array({exact_json(ans.bodies[b].com_velocity.x),
                                                      exact_json(ans.bodies[b].com_velocity.y)})}});
    j["bodies"] = bodies;
    j["contacts"] = assembly_forces_json(ans.forces);
    j["theta_dot"] = exact_json(r.physical->theta_dot.to_q());
    j["tau"] = exact_json(r.physical->tau.to_q());
  }
  if (r.conditions)
    j["conditions_2_to_10"] = r.conditions->status == ucp::ConditionsStatus::kSatisfied ? "satisfied" : "violated";
  j["pairs"] = r.pairs;
  j["lps"] = r.lps;
  j["nodes"] = r.nodes;
  if (!ans.certificate.empty()) j["certificate"] = ans.certificate;
  if (!ans.svg.empty()) j["svg"] = ans.svg;
  if (ans.uniqueness) j["uniqueness"] = to_json(*ans.uniqueness);
  return j;
}

std::string to_text(const AssemblyUcpAnswer& ans, const std::string& name) {
  const ucp::UcpReport& r = ans.report;
  std::string s = std::string("ucp ") + name + ": " + ucp::status_name(r.status) + " (" + r.reason + ")\n  " +
                  "method complete, arith " + exact::arith_name(r.arith) + ", pairs " + std::to_string(r.pairs) +
                  ", LPs " + std::to_string(r.lps) + ", nodes " + std::to_string(r.nodes) + "\n";
  for (std::size_t b = 0; b < ans.bodies.size(); ++b)
    s += std::string("  body ") + std::to_string(b) + ": q_dot " + tuple_text(ans.bodies[b].q_dot) +
         " (at the world origin), com velocity " + geometry::point_text(ans.bodies[b].com_velocity) + "\n";
  if (!ans.forces.empty())
    s += std::string("  contact forces (world coordinates; each acts on `to`, its opposite on `from`):\n") +
         assembly_forces_text(ans.forces, "    ");
  if (r.conditions)
    s += std::string("  conditions (2)-(10): ") +
         (r.conditions->status == ucp::ConditionsStatus::kSatisfied ? "satisfied exactly" : "VIOLATED") + "\n";
  if (!ans.certificate.empty()) s += std::string("  certificate: ") + ans.certificate + "\n";
  if (!ans.svg.empty()) s += std::string("  picture: ") + ans.svg + "\n";
  if (ans.uniqueness) s += to_text(*ans.uniqueness, 3);
  return s;
}

}  // namespace contactcert::queries
