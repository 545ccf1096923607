// `contactcert stability FILE --wrench fx,fy,tz`: strongly stable, only weakly stable, or unstable
// (wrench cone paper, section 7; SPEC sections 6-7), with a witness or a certificate.
#include <CLI/CLI.hpp>

#include <iostream>

#include "cli/command.h"
#include "cli/json_out.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "solvers/stability/stability_certificate.h"

namespace contactcert::cli {
namespace {

using exact::Q;
using solvers::StabilityResult;

struct StabilityOptions {
  CommonOptions common;
  std::string file;
  std::string wrench;
  std::string certificate;
};

template <class T>
json witness_json(const solvers::MotionWitness<T>& w) {
  json j;
  j["mode"] = w.mode.text();
  if constexpr (std::is_same_v<T, Q>) {
    j["forces"] = exact_json(w.forces);
    j["acceleration"] = exact_json(w.acceleration);
    j["acceleration_approx"] = approx_json(w.acceleration);
  } else {
    j["forces_approx"] = approx_json(w.forces);
    j["acceleration_approx"] = approx_json(w.acceleration);
  }
  return j;
}

template <class T>
json forces_json(const exact::Vec<T>& c) {
  if constexpr (std::is_same_v<T, Q>) return exact_json(c);
  else return approx_json(c);
}

std::string vec_text(const exact::Vec<Q>& v) {
  std::string s = "(";
  for (Eigen::Index i = 0; i < v.size(); ++i) s += (i ? ", " : "") + exact::to_string(v(i));
  return s + ")";
}
std::string vec_text(const exact::Vec<double>& v) {
  std::string s = "(";
  for (Eigen::Index i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v(i));
  return s + ")";
}

template <class T>
int report(const StabilityOptions& o, const exact::Vec<Q>& g, const StabilityResult<T>& r) {
  if (o.common.json) {
    json j;
    j["verdict"] = solvers::verdict_name(r.verdict);
    j["wrench"] = exact_json(g);
    j["arith"] = o.common.arith;
    json touching = json::array();
    for (auto i : r.touching) touching.push_back(i);
    j["touching_fixels"] = touching;
    json w;
    if (r.has_resting) w["resting_forces"] = forces_json(r.resting_forces);
    if (r.has_moving) w["moving"] = witness_json(r.moving);
    j["witness"] = w;
    j["lps"] = r.lps;
    j["modes_checked"] = r.modes_checked;
    j["modes_kinematically_feasible"] = r.modes_kinematically_feasible;
    if (!o.certificate.empty()) j["certificate"] = o.certificate;
    std::cout << j.dump() << "\n";
    return 0;
  }
  const std::size_t k = r.touching.size();
  std::cout << "verdict: " << solvers::verdict_name(r.verdict) << "\n"
            << "  wrench g = " << vec_text(g) << " on " << o.file << " (" << k << " touching fixels, "
            << o.common.arith << " arithmetic)\n";
  if (r.has_resting) std::cout << "  at rest with contact forces (c_n..., c_t...) = " << vec_text(r.resting_forces) << "\n";
  else std::cout << "  no contact forces in the friction cones balance g (Motzkin certificate found)\n";
  if (r.has_moving)
    std::cout << "  moves in mode '" << r.moving.mode.text() << "' with acceleration " << vec_text(r.moving.acceleration)
              << ", forces " << vec_text(r.moving.forces) << "\n";
  else if (r.has_resting)
    std::cout << "  no moving mode admits g: " << r.proofs.size() << " proofs ("
              << (r.modes_checked - r.modes_kinematically_feasible) << " modes kinematically impossible)\n";
  std::cout << "  LPs: " << r.lps << "\n";
  if (!o.certificate.empty()) std::cout << "  certificate: " << o.certificate << "\n";
  return 0;
}

int run_stability(const StabilityOptions& o) {
  const std::string text = exact::JsonInput::read_text(o.file);
  const geometry::PlanarScene scene = geometry::read_planar_scene(exact::JsonInput::parse(text, o.file));
  const exact::Vec<Q> g = parse_number_list(o.wrench, "--wrench", 3);
  const exact::Arith arith = exact::parse_arith(o.common.arith);
  if (arith == exact::Arith::kFloat) {
    if (!o.certificate.empty())
      throw exact::InputError("command line", "--certificate", "certificates need --arith exact or verified");
    return report(o, g, solvers::strong_stability<double>(scene, exact::to_double(g), {arith}));
  }
  const auto r = solvers::strong_stability<Q>(scene, g, {arith});
  if (!o.certificate.empty()) write_text_file(o.certificate, solvers::stability_certificate(text, g, r));
  return report(o, g, r);
}

}  // namespace

void register_stability(CLI::App& app, Action& action) {
  auto o = std::make_shared<StabilityOptions>();
  CLI::App* sub = app.add_subcommand(
      "stability", "Is the workpiece strongly stable, only weakly stable, or unstable under a wrench?");
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Planar scene file (SPEC section 3)")->required();
  sub->add_option("--wrench", o->wrench, "External wrench fx,fy,tz (torque about the centre of mass), exact numbers")
      ->required();
  sub->add_option("--certificate", o->certificate, "Write the evidence for `contactcert check` to this file");
  sub->callback([o, &action] { action = [o] { return run_stability(*o); }; });
}

}  // namespace contactcert::cli
