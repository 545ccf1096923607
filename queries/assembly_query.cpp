#include "queries/assembly_query.h"

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "queries/assembly_svg.h"
#include "solvers/assembly/assembly_certificate.h"

namespace contactcert::queries {
namespace {

using exact::Q;
using geometry::Party;
using geometry::Point2;
namespace sa = solvers::assembly;

const char* party_kind(const Party& p) {
  switch (p.kind) {
    case Party::Kind::kBody:
      return "body";
    case Party::Kind::kObstacle:
      return "obstacle";
    case Party::Kind::kFixel:
      return "fixel";
    default:
      return "finger";
  }
}

json party_json(const Party& p) { return {{party_kind(p), p.index}}; }
std::string party_text(const Party& p) { return std::string(party_kind(p)) + " " + std::to_string(p.index); }
json point_json(const Point2& p) { return json::array({exact_json(p.x), exact_json(p.y)}); }

/// "body 0 (ax, ay, alpha), body 1 (...)" of the accelerations vdot, body by body.
std::string accelerations_text(const exact::Vec<Q>& vdot) {
  std::string s;
  for (Eigen::Index b = 0; 3 * b < vdot.size(); ++b)
    s += std::string(b ? ", body " : "body ") + std::to_string(b) + " " +
         tuple_text(exact::Vec<Q>(vdot.segment(3 * b, 3)));
  return s;
}

}  // namespace

AssemblyInput parse_assembly(const std::string& text, const std::string& name) {
  const exact::JsonInput root = exact::JsonInput::parse(text, name);
  if (!geometry::is_assembly(root))
    throw exact::InputError(name, "$.bodies",
                            "an assembly: a \"planar\" or \"quasistatic_scene\" file with bodies (docs/formats.md "
                            "section 3a)");
  return {name, text, geometry::read_assembly(root)};
}

AssemblyInput load_assembly(const std::string& path) { return parse_assembly(exact::JsonInput::read_text(path), path); }

std::vector<AssemblyContactForce> assembly_forces(const geometry::Assembly& a, const exact::Vec<Q>& c) {
  const auto k = static_cast<Eigen::Index>(a.contacts.size());
  std::vector<AssemblyContactForce> out;
  for (Eigen::Index i = 0; i < k; ++i) {
    const geometry::AssemblyContact& ac = a.contacts[static_cast<std::size_t>(i)];
    const Point2 t = geometry::perp(ac.normal);
    out.push_back({static_cast<std::size_t>(i), ac.from, ac.to, ac.point, ac.normal, t, c(i), c(k + i),
                   c(i) * ac.normal + c(k + i) * t});
  }
  return out;
}

json assembly_forces_json(const std::vector<AssemblyContactForce>& forces) {
  json out = json::array();
  for (const AssemblyContactForce& f : forces)
    out.push_back({{"contact", f.contact},
                   {"from", party_json(f.from)},
                   {"to", party_json(f.to)},
                   {"point", point_json(f.point)},
                   {"normal", point_json(f.normal)},
                   {"tangent", point_json(f.tangent)},
                   {"c_n", exact_json(f.c_n)},
                   {"c_t", exact_json(f.c_t)},
                   {"force", point_json(f.force)}});
  return out;
}

std::string assembly_forces_text(const std::vector<AssemblyContactForce>& forces, const std::string& indent) {
  std::string out;
  for (const AssemblyContactForce& f : forces)
    out += indent + "contact " + std::to_string(f.contact) + " (" + party_text(f.from) + " -> " + party_text(f.to) +
           ") at " + geometry::point_text(f.point) + ": force " + geometry::point_text(f.force) + " on " +
           party_text(f.to) + "  (c_n = " + exact::to_string(f.c_n) + " along n = " + geometry::point_text(f.normal) +
           ", c_t = " + exact::to_string(f.c_t) + " along t = " + geometry::point_text(f.tangent) + ")\n";
  return out;
}

namespace {

AssemblyStabilityAnswer assembly_stability_answer(const AssemblyInput& in, const AssemblyStabilityOptions& options) {
  refuse_float(options.common.arith, "an assembly's stability is decided exactly (use exact or verified)");
  const geometry::Assembly& a = in.assembly;
  AssemblyStabilityAnswer ans;
  ans.arith = scene_arith(options.common.arith);
  ans.bodies = a.bodies.size();
  ans.contacts = a.contacts.size();
  sa::AssemblyStabilityOptions o;
  o.arith = ans.arith;
  o.max_nodes = options.max_nodes;
  o.deadline = options.common.deadline();
  ans.result = sa::assembly_stability(a, o);
  const sa::AssemblyStabilityResult& r = ans.result;
  if (r.has_resting) ans.resting = assembly_forces(a, r.resting_forces);
  if (r.has_moving) ans.moving = assembly_forces(a, r.moving.forces);
  if (!options.certificate.empty() && ans.decided()) ans.certificate_text = sa::assembly_certificate(in.text, r);
  write_files(in, options, ans);
  return ans;
}

}  // namespace

Limited<AssemblyStabilityAnswer> run_assembly_stability(const AssemblyInput& in,
                                                        const AssemblyStabilityOptions& options) {
  return with_limits(options.common.arith, [&] { return assembly_stability_answer(in, options); });
}

std::optional<Limit> limit_of(const AssemblyStabilityAnswer& ans) {
  if (ans.decided()) return std::nullopt;
  return Limit{sa::status_name(ans.result.status), ans.result.covered};
}

json to_json(const AssemblyStabilityAnswer& ans) {
  const sa::AssemblyStabilityResult& r = ans.result;
  json j;
  j["verdict"] = ans.decided() ? sa::verdict_name(r.verdict) : "unknown";
  j["status"] = sa::status_name(r.status);
  j["arith"] = exact::arith_name(ans.arith);
  j["bodies"] = ans.bodies;
  j["contacts"] = ans.contacts;
  json w = json::object();
  if (r.has_resting)
    w["resting"] = {{"forces", exact_json(r.resting_forces)}, {"contacts", assembly_forces_json(ans.resting)}};
  if (r.has_moving) {
    json bodies = json::array();
    for (Eigen::Index b = 0; 3 * b < r.moving.acceleration.size(); ++b) {
      const exact::Vec<Q> v = r.moving.acceleration.segment(3 * b, 3);
      bodies.push_back({{"body", b}, {"acceleration", exact_json(v)}, {"acceleration_approx", approx_json(v)}});
    }
    w["moving"] = {{"mode", r.moving.mode},
                   {"bodies", bodies},
                   {"forces", exact_json(r.moving.forces)},
                   {"contacts", assembly_forces_json(ans.moving)}};
  }
  j["witness"] = w;
  j["search"] = {{"nodes", r.nodes}, {"lps", r.lps}, {"dead_prefixes", r.dead.size()}};
  if (!ans.decided()) j["covered"] = r.covered;
  if (!ans.certificate.empty()) j["certificate"] = ans.certificate;
  if (!ans.svg.empty()) j["svg"] = ans.svg;
  return j;
}

std::string to_text(const AssemblyStabilityAnswer& ans, const std::string& name) {
  const sa::AssemblyStabilityResult& r = ans.result;
  std::string s = std::string("verdict: ") + (ans.decided() ? sa::verdict_name(r.verdict) : "unknown") + "\n  " + name +
                  ": " + std::to_string(ans.bodies) + (ans.bodies == 1 ? " body, " : " bodies, ") +
                  std::to_string(ans.contacts) + " contacts, each body under its load (" +
                  exact::arith_name(ans.arith) + " arithmetic)\n";
  if (!ans.decided()) s += std::string("  ") + sa::status_name(r.status) + ": " + r.covered + "\n";
  if (r.has_resting)
    s +=
        std::string("  at rest with contact forces (world coordinates; each acts on `to`, its opposite on `from`):\n") +
        assembly_forces_text(ans.resting, "    ");
  else if (ans.decided())
    s += "  no contact forces in the friction cones hold every body at rest (Motzkin certificate found)\n";
  if (r.has_moving)
    s += std::string("  moves in mode '") + r.moving.mode +
         "' with accelerations (a_x, a_y, alpha of each com): " + accelerations_text(r.moving.acceleration) +
         "; contact forces:\n" + assembly_forces_text(ans.moving, "    ");
  else if (ans.decided() && r.has_resting)
    s += std::string("  no moving solution: every mode over s l r n extends one of ") + std::to_string(r.dead.size()) +
         " infeasible prefixes\n";
  s += std::string("  search: ") + std::to_string(r.nodes) + " prefixes, " + std::to_string(r.lps) + " LPs\n";
  if (!ans.certificate.empty()) s += std::string("  certificate: ") + ans.certificate + "\n";
  if (!ans.svg.empty()) s += std::string("  picture: ") + ans.svg + "\n";
  return s;
}

}  // namespace contactcert::queries
