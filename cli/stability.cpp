// `contactcert stability FILE --wrench fx,fy,tz`: strongly stable, only weakly stable, or unstable
// (wrench cone paper, section 7; SPEC sections 6-7), with a witness or a certificate.
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <optional>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/results.h"
#include "cli/snap_option.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "queries/boundary_marks.h"
#include "queries/boundary_text.h"
#include "queries/contact_forces.h"
#include "queries/contact_notes.h"
#include "queries/json_out.h"
#include "queries/region_data.h"
#include "queries/stability_svg.h"
#include "solvers/stability/finger_push.h"
#include "solvers/stability/margin.h"
#include "solvers/stability/stability_certificate.h"
#include "solvers/stability/stable_region.h"
#include "solvers/stability/strong_cones.h"

namespace contactcert::cli {
namespace {

using exact::Q;
using solvers::StabilityResult;

struct StabilityOptions {
  CommonOptions common;
  std::string file;
  std::string snap;  ///< --snap TOL ("" = none)
  std::string wrench;
  std::string certificate;
  bool region = false;
  bool finger = false;
  bool margin = false;
  std::string svg;
  std::string wrenches;
};

// The mode tree's budget: --time-limit (the node budget is the default).
solvers::ModeTreeOptions tree_budget(const StabilityOptions& o) {
  solvers::ModeTreeOptions t;
  t.deadline = exact::Deadline::after(o.common.time_limit);
  return t;
}

solvers::StabilityOptions budget(const StabilityOptions& o, exact::Arith arith) {
  solvers::StabilityOptions s;
  s.arith = arith;
  s.deadline = exact::Deadline::after(o.common.time_limit);
  return s;
}

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

double signed_degrees(const exact::Vec<Q>& u) { return std::atan2(u(1).get_d(), u(0).get_d()) * 180.0 / M_PI; }

}  // namespace

template <class T>
json stability_json(const geometry::PlanarScene& scene, const exact::Vec<Q>& g, const StabilityResult<T>& r,
                    const std::string& arith, const std::string& certificate,
                    const std::optional<solvers::Margin<Q>>& margin) {
  json j;
  j["verdict"] = solvers::verdict_name(r.verdict);
  j["wrench"] = exact_json(g);
  j["arith"] = arith;
  json touching = json::array();
  for (auto i : r.touching) touching.push_back(i);
  j["touching_fixels"] = touching;
  json w;
  if (r.has_resting) {
    w["resting_forces"] = vector_json(r.resting_forces);
    w["resting_contacts"] = contacts_json(scene, r.touching, r.resting_forces);
  }
  if (r.has_moving) {
    w["moving"] = witness_json(r.moving);
    w["moving"]["contacts"] = contacts_json(scene, r.touching, r.moving.forces);
  }
  j["witness"] = w;
  j["lps"] = r.lps;
  j["modes_checked"] = r.modes_checked;
  j["modes_kinematically_feasible"] = r.modes_kinematically_feasible;
  j["mode_tree"] = {{"nodes", r.tree_nodes}, {"dead_prefixes", r.dead_prefixes}};
  if (!certificate.empty()) j["certificate"] = certificate;
  if (margin && !margin->nearest.empty())
    j["margin"] = {{"squared_radius", exact_json(margin->squared_radius)},
                   {"radius_approx", std::sqrt(margin->squared_radius.get_d())},
                   {"nearest", margin->nearest}};
  return j;
}
template json stability_json(const geometry::PlanarScene&, const exact::Vec<Q>&, const StabilityResult<Q>&,
                             const std::string&, const std::string&, const std::optional<solvers::Margin<Q>>&);
template json stability_json(const geometry::PlanarScene&, const exact::Vec<Q>&, const StabilityResult<double>&,
                             const std::string&, const std::string&, const std::optional<solvers::Margin<Q>>&);

std::string stability_certificate_file(const std::string& scene_text, const geometry::PlanarScene& scene,
                                       const exact::Vec<Q>& g, const StabilityResult<Q>& r) {
  json j = json::parse(solvers::stability_certificate(scene_text, g, r));
  if (r.has_resting) j["resting"]["contacts"] = contacts_json(scene, r.touching, r.resting_forces);
  if (r.has_moving) j["moving"]["contacts"] = contacts_json(scene, r.touching, r.moving.forces);
  return j.dump(1) + "\n";
}

json region_json(const solvers::StableRegion<Q>& region) {
  json modes = json::array();
  for (const auto& m : region.modes) modes.push_back(m.text());
  json j;
  j["region"] = region_data_json(region);
  j["region"]["nonempty_moving_modes"] = modes;
  return j;
}

json finger_json(const solvers::FingerPushes<Q>& pushes) {
  json edges = json::array(), arcs = json::array();
  for (const auto& p : pushes.edges)
    edges.push_back({{"edge", p.edge},
                     {"from", exact_json(p.from)},
                     {"to", exact_json(p.to)},
                     {"from_closed", p.from_closed},
                     {"to_closed", p.to_closed},
                     {"label", solvers::verdict_name(p.label)}});
  for (const auto& p : pushes.arcs)
    arcs.push_back({{"from_direction", primitive_json(p.from)},
                    {"to_direction", primitive_json(p.to)},
                    {"from_closed", p.from_closed},
                    {"to_closed", p.to_closed},
                    {"from_degrees_approx", signed_degrees(p.from)},
                    {"to_degrees_approx", signed_degrees(p.to)},
                    {"label", solvers::verdict_name(p.label)}});
  json j;
  j["finger"] = {{"edges", edges}, {"arcs", arcs}};
  return j;
}

std::string finger_svg(const geometry::PlanarScene& scene, const solvers::FingerPushes<Q>& pushes) {
  return wrench_cone_svg(scene, exact::Mat<Q>(0, 3), exact::Mat<Q>(0, 3),
                         "finger pushes: green strongly stable, yellow weakly, red unstable",
                         verdict_marks(scene, pushes));
}

namespace {

template <class T>
int report(const StabilityOptions& o, const geometry::PlanarScene& scene, const exact::Vec<Q>& g,
           const StabilityResult<T>& r, const std::optional<solvers::Margin<Q>>& margin = std::nullopt) {
  if (o.common.json) {
    std::cout << stability_json(scene, g, r, o.common.arith, o.certificate, margin).dump() << "\n";
    return 0;
  }
  const std::size_t k = r.touching.size();
  std::cout << "verdict: " << solvers::verdict_name(r.verdict) << "\n"
            << "  wrench g = " << tuple_text(g) << " on " << o.file << " (" << k << " touching fixels, "
            << o.common.arith << " arithmetic)\n"
            << tiny_gap_notes(scene, "  ");
  if (r.has_resting) {
    std::cout << "  at rest with contact forces (world coordinates; they balance g):\n";
    std::cout << contacts_text(scene, r.touching, r.resting_forces, "    ");
  } else {
    std::cout << "  no contact forces in the friction cones balance g (Motzkin certificate found)\n";
  }
  if (r.has_moving) {
    std::cout << "  moves in mode '" << r.moving.mode.text() << "' with acceleration "
              << tuple_text(r.moving.acceleration) << " (eq. 4: M vdot = g + the contact wrenches), contact forces:\n";
    std::cout << contacts_text(scene, r.touching, r.moving.forces, "    ");
  } else if (r.has_resting) {
    std::cout << "  no moving mode admits g: " << r.modes_kinematically_feasible
              << " kinematically feasible moving modes, each with a proof for g; every other mode extends one of "
              << r.dead_prefixes << " infeasible prefixes (mode tree: " << r.tree_nodes << " prefixes)\n";
  }
  if (margin && !margin->nearest.empty())
    std::cout << "  margin: squared radius " << exact::to_string(margin->squared_radius) << " (radius ~"
              << std::sqrt(margin->squared_radius.get_d()) << "), nearest: "
              << (margin->nearest == "weak" ? std::string("edge of the weakly stable cone")
                                            : "mode '" + margin->nearest + "'")
              << "\n";
  std::cout << "  LPs: " << r.lps << "\n";
  if (!o.certificate.empty()) std::cout << "  certificate: " << o.certificate << "\n";
  return 0;
}

int run_region(const StabilityOptions& o, const geometry::PlanarScene& scene, const std::optional<exact::Vec<Q>>& g) {
  if (exact::parse_arith(o.common.arith) == exact::Arith::kFloat)
    throw exact::InputError("command line", "--arith", "--region is computed exactly (use exact or verified)");
  const auto region = solvers::stable_region<Q>(scene, solvers::Route::kPaper, tree_budget(o));
  if (!o.svg.empty()) write_text_file(o.svg, stability_sphere_svg(region, g));
  int count[3][4] = {};
  for (const auto& c : region.cells) ++count[static_cast<int>(c.label)][c.dimension];
  if (o.common.json) {
    json j = region_json(region);
    if (g) j["region"]["wrench"] = {{"g", exact_json(*g)}, {"label", solvers::verdict_name(region.label(*g))}};
    std::cout << j.dump() << "\n";
    return 0;
  }
  std::cout << "stable region of " << o.file << ": " << region.cells.size() << " cells cut by " << region.planes.rows()
            << " planes (" << region.modes.size() << " moving modes with non-empty wrench cones)\n"
            << tiny_gap_notes(scene, "  ");
  static const char* kind[4] = {"origin", "rays", "2-d sectors", "open regions"};
  for (int l = 0; l < 3; ++l) {
    std::cout << "  " << solvers::verdict_name(static_cast<solvers::StabilityVerdict>(l)) << ":";
    int cells = 0;
    for (int d = 0; d < 4; ++d)
      if (count[l][d]) std::cout << " " << count[l][d] << " " << kind[d], cells += count[l][d];
    std::cout << (cells == 0 ? " none\n" : "\n");
  }
  const auto cones = solvers::strongly_stable_cones(region);
  std::cout << "  strongly stable set: " << (cones.empty() ? "none" : "the union of these convex cones (g is in one)")
            << "\n";
  for (std::size_t k = 0; k < cones.size(); ++k) {
    std::string rows;
    auto add = [&](const exact::Mat<Q>& M, const char* relation) {
      for (Eigen::Index r = 0; r < M.rows(); ++r)
        rows += (rows.empty() ? "" : ", ") + tuple_text(exact::primitive(exact::Vec<Q>(M.row(r).transpose()))) +
                " . g " + relation;
    };
    add(cones[k].cone.inequalities, "<= 0");
    add(cones[k].cone.strict, "< 0");
    add(cones[k].cone.equalities, "= 0");
    std::cout << "    cone " << k << ": " << (rows.empty() ? "every wrench" : rows) << "\n";
  }
  int shown = 0;
  const auto reps = cell_representatives(region);
  for (std::size_t i = 0; i < region.cells.size(); ++i)
    if (region.cells[i].dimension == 3 && region.cells[i].label == solvers::StabilityVerdict::kStronglyStable &&
        shown++ < 5)
      std::cout << "  strongly stable open region through g = " << tuple_text(reps[i]) << "\n";
  if (shown > 5) std::cout << "  ... (" << shown - 5 << " more; --json lists every cell)\n";
  if (g)
    std::cout << "  the wrench g = " << tuple_text(*g) << " is " << solvers::verdict_name(region.label(*g))
              << (o.svg.empty() ? "" : " (marked in the picture)") << "\n";
  if (!o.svg.empty()) std::cout << "  picture: " << o.svg << "\n";
  return 0;
}

int run_finger(const StabilityOptions& o, const geometry::PlanarScene& scene) {
  if (exact::parse_arith(o.common.arith) == exact::Arith::kFloat)
    throw exact::InputError("command line", "--arith", "--finger is computed exactly (use exact or verified)");
  const solvers::ModeTreeOptions budget = tree_budget(o);  // one deadline for the region and the pushes
  const auto region = solvers::stable_region<Q>(scene, solvers::Route::kPaper, budget);
  const auto pushes = solvers::finger_pushes<Q>(scene, region, budget.deadline);
  if (!o.svg.empty()) write_text_file(o.svg, finger_svg(scene, pushes));
  if (o.common.json) {
    std::cout << finger_json(pushes).dump() << "\n";
    return 0;
  }
  std::cout << "frictionless finger pushes along the inward normal of " << o.file << ":\n"
            << tiny_gap_notes(scene, "  ")
            << pieces_text(
                   scene, pushes, "  ", [](solvers::StabilityVerdict) { return true; },
                   [](solvers::StabilityVerdict v) { return std::string(": ") + solvers::verdict_name(v); });
  return 0;
}

/// One verdict per wrench of a file, from one StabilityOracle prepared for the scene.
template <class T>
int run_wrenches(const StabilityOptions& o, const geometry::PlanarScene& scene, const exact::Arith arith) {
  const std::vector<exact::Vec<Q>> gs = read_wrenches(o.wrenches);
  const solvers::StabilityOracle<T> oracle(scene, budget(o, arith));
  json rows = json::array();
  long count[3] = {}, lps = oracle.preparation_lps();
  for (const auto& g : gs) {
    exact::Vec<T> gt(3);
    for (int k = 0; k < 3; ++k) gt(k) = solvers::from_exact<T>(g(k));
    const auto r = oracle.verdict(gt);
    ++count[static_cast<int>(r.verdict)];
    lps += r.lps;
    if (o.common.json)
      rows.push_back({{"wrench", exact_json(g)}, {"verdict", solvers::verdict_name(r.verdict)}});
    else
      std::cout << "  g = " << tuple_text(g) << ": " << solvers::verdict_name(r.verdict) << "\n";
  }
  if (o.common.json) {
    std::cout << json{{"wrenches", rows},
                      {"counts", {{"strongly_stable", count[0]}, {"weakly_stable", count[1]}, {"unstable", count[2]}}},
                      {"arith", o.common.arith},
                      {"lps", lps}}
                     .dump()
              << "\n";
  } else {
    std::cout << gs.size() << " wrenches on " << o.file << ": " << count[0] << " strongly stable, " << count[1]
              << " weakly stable, " << count[2] << " unstable (" << lps << " LPs, " << o.common.arith
              << " arithmetic)\n";
  }
  return 0;
}

int run_stability(const StabilityOptions& options) {
  // The precision ladder is the UCP's (--arith adaptive); stability's verified path already settles each LP
  // from a float answer checked exactly, so adaptive runs (and is reported) as verified here.
  StabilityOptions o = options;
  if (o.common.arith == "adaptive") o.common.arith = "verified";
  const std::string text = read_scene_text(o.file, o.snap);
  const geometry::PlanarScene scene = geometry::read_planar_scene(exact::JsonInput::parse(text, o.file));
  if (int(o.region) + int(o.finger) + int(!o.wrench.empty() && !o.region) + int(!o.wrenches.empty()) != 1)
    throw exact::InputError("command line", "--wrench",
                            "give exactly one of --wrench fx,fy,tz, --wrenches FILE, --region or --finger");
  if (!o.wrenches.empty())
    return exact::parse_arith(o.common.arith) == exact::Arith::kFloat
               ? run_wrenches<double>(o, scene, exact::Arith::kFloat)
               : run_wrenches<Q>(o, scene, exact::parse_arith(o.common.arith));
  if (o.region)
    return run_region(o, scene,
                      o.wrench.empty() ? std::nullopt : std::optional(parse_number_list(o.wrench, "--wrench", 3)));
  if (o.finger) return run_finger(o, scene);
  const exact::Vec<Q> g = parse_number_list(o.wrench, "--wrench", 3);
  const exact::Arith arith = exact::parse_arith(o.common.arith);
  if (arith == exact::Arith::kFloat) {
    if (!o.certificate.empty())
      throw exact::InputError("command line", "--certificate", "certificates need --arith exact or verified");
    if (o.margin)
      throw exact::InputError("command line", "--margin", "the margin is computed exactly (use exact or verified)");
    return report(o, scene, g, solvers::strong_stability<double>(scene, exact::to_double(g), budget(o, arith)));
  }
  const auto r = solvers::strong_stability<Q>(scene, g, budget(o, arith));
  if (!o.certificate.empty()) write_text_file(o.certificate, stability_certificate_file(text, scene, g, r));
  std::optional<solvers::Margin<Q>> margin;
  if (o.margin && r.verdict == solvers::StabilityVerdict::kStronglyStable)
    margin = solvers::stability_margin<Q>(solvers::stable_region<Q>(scene, solvers::Route::kPaper, tree_budget(o)), g);
  return report(o, scene, g, r, margin);
}

}  // namespace

void register_stability(CLI::App& app, Action& action) {
  auto o = std::make_shared<StabilityOptions>();
  CLI::App* sub = app.add_subcommand(
      "stability", "Is the workpiece strongly stable, only weakly stable, or unstable under a wrench?");
  add_snap_option(*sub, o->snap);
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Planar scene file (format: docs/formats.md, section 3)")->required();
  CLI::Option* wrench = sub->add_option("--wrench", o->wrench,
                                        "External wrench fx,fy,tz (torque about the centre of mass), exact numbers");
  sub->add_option("--wrenches", o->wrenches,
                  "Many wrenches, one verdict each: a JSON array of [fx, fy, tz] or one fx,fy,tz per line");
  CLI::Option* region =
      sub->add_flag("--region", o->region, "The whole strongly stable set: labelled cells of wrench space");
  sub->add_flag("--margin", o->margin, "With --wrench: squared radius of the largest strongly stable ball around it")
      ->needs(wrench)
      ->excludes(region);
  sub->add_flag("--finger", o->finger, "Where a frictionless finger push along the boundary normal is strongly stable");
  sub->add_option("--svg", o->svg,
                  "With --region: the sphere of wrench directions; with --finger: the boundary coloured by verdict");
  sub->add_option("--certificate", o->certificate, "With --wrench: write the evidence for `contactcert check` here");
  sub->callback([o, sub, &action] {
    // Options the chosen question would ignore are refused rather than dropped silently.
    for (const char* question : {"--wrenches", "--region", "--finger"})
      if (sub->count(question) > 0)
        refuse_given(*sub, {"--certificate"}, std::string(question) + " writes no certificate (only --wrench does)");
    if (sub->count("--region") == 0 && sub->count("--finger") == 0)
      refuse_given(*sub, {"--svg"}, "a picture is drawn only with --region or --finger");
    action = [o] { return run_stability(*o); };
  });
}

}  // namespace contactcert::cli
