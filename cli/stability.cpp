// `contactcert stability FILE --wrench fx,fy,tz`: strongly stable, only weakly stable, or unstable
// (wrench cone paper, section 7; SPEC sections 6-7), with a witness or a certificate; --wrenches, --region and
// --finger. The queries run in queries/ (stability_query.h, wrenches_query.h, region_query.h, finger_query.h); this
// file reads the options and prints their answers.
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <optional>

#include "cli/assembly_answers.h"
#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/snap_option.h"
#include "exact/rational_text.h"
#include "queries/boundary_text.h"
#include "queries/contact_forces.h"
#include "queries/contact_notes.h"
#include "queries/finger_query.h"
#include "queries/json_out.h"
#include "queries/region_data.h"
#include "queries/region_query.h"
#include "queries/spatial_stability_query.h"
#include "queries/stability_query.h"
#include "queries/wrenches_query.h"
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

template <class T>
void print_stability(const StabilityOptions& o, const geometry::PlanarScene& scene, const StabilityAnswer& a,
                     const StabilityResult<T>& r) {
  const std::size_t k = r.touching.size();
  const char* arith = exact::arith_name(a.arith);
  std::cout << "verdict: " << solvers::verdict_name(r.verdict) << "\n"
            << "  wrench g = " << tuple_text(a.wrench) << " on " << o.file << " (" << k << " touching fixels, " << arith
            << " arithmetic)\n"
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
  const auto& margin = a.margin;
  if (margin && !margin->nearest.empty())
    std::cout << "  margin: squared radius " << exact::to_string(margin->squared_radius) << " (radius ~"
              << std::sqrt(margin->squared_radius.get_d()) << "), nearest: "
              << (margin->nearest == "weak" ? std::string("edge of the weakly stable cone")
                                            : "mode '" + margin->nearest + "'")
              << "\n";
  std::cout << "  LPs: " << r.lps << "\n";
  if (!a.certificate.empty()) std::cout << "  certificate: " << a.certificate << "\n";
}

/// The strongly stable set as a union of convex cones, each as its rows p . g <= 0, < 0, = 0.
void print_strong_cones(const solvers::StableRegion<Q>& region) {
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
}

void print_region(const StabilityOptions& o, const geometry::PlanarScene& scene, const RegionAnswer& a) {
  const auto& region = a.region;
  int count[3][4] = {};
  for (const auto& c : region.cells) ++count[static_cast<int>(c.label)][c.dimension];
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
  print_strong_cones(region);
  int shown = 0;
  const auto reps = cell_representatives(region);
  for (std::size_t i = 0; i < region.cells.size(); ++i)
    if (region.cells[i].dimension == 3 && region.cells[i].label == solvers::StabilityVerdict::kStronglyStable &&
        shown++ < 5)
      std::cout << "  strongly stable open region through g = " << tuple_text(reps[i]) << "\n";
  if (shown > 5) std::cout << "  ... (" << shown - 5 << " more; --json lists every cell)\n";
  if (a.wrench)
    std::cout << "  the wrench g = " << tuple_text(*a.wrench) << " is " << solvers::verdict_name(*a.wrench_label)
              << (a.svg.empty() ? "" : " (marked in the picture)") << "\n";
  if (!a.svg.empty()) std::cout << "  picture: " << a.svg << "\n";
}

void print_finger(const StabilityOptions& o, const geometry::PlanarScene& scene, const FingerAnswer& a) {
  std::cout << "frictionless finger pushes along the inward normal of " << o.file << ":\n"
            << tiny_gap_notes(scene, "  ")
            << pieces_text(
                   scene, a.pushes, "  ", [](solvers::StabilityVerdict) { return true; },
                   [](solvers::StabilityVerdict v) { return std::string(": ") + solvers::verdict_name(v); });
}

void print_wrenches(const StabilityOptions& o, const WrenchesAnswer& a) {
  for (std::size_t i = 0; i < a.wrenches.size(); ++i)
    std::cout << "  g = " << tuple_text(a.wrenches[i]) << ": " << solvers::verdict_name(a.verdicts[i]) << "\n";
  std::cout << a.wrenches.size() << " wrenches on " << o.file << ": " << a.counts[0] << " strongly stable, "
            << a.counts[1] << " weakly stable, " << a.counts[2] << " unstable (" << a.lps << " LPs, "
            << exact::arith_name(a.arith) << " arithmetic)\n";
}

/// Prints an answer: its --json object, or its text report by `text`; or the limit that stopped it.
template <class Answer, class Text>
int print(const StabilityOptions& o, const Limited<Answer>& answer, Text text) {
  if (!answer) return report_limit("stability", answer.limit(), o.common.json);
  if (o.common.json)
    std::cout << to_json(*answer).dump() << "\n";
  else
    text();
  return 0;
}

/// `stability ASSEMBLY`: the query of `contactcert assembly` (each body's load is in the file: no wrench).
int run_assembly_stability_command(const StabilityOptions& o, const AssemblyInput& in) {
  const std::pair<bool, const char*> wrench_options[] = {{!o.wrench.empty(), "--wrench"},
                                                         {!o.wrenches.empty(), "--wrenches"},
                                                         {o.region, "--region"},
                                                         {o.finger, "--finger"},
                                                         {o.margin, "--margin"}};
  for (const auto& [given, name] : wrench_options)
    if (given)
      throw exact::InputError("command line", name,
                              "an assembly's loads are in its file (each body's load); it takes no wrench");
  queries::AssemblyStabilityOptions q;
  q.common = o.common.query();
  q.certificate = o.certificate;
  return print_assembly_answer(run_assembly_stability(in, q), o.file, o.common.json, "stability");
}

/// `stability SPATIAL --wrench fx,fy,fz,tx,ty,tz`: a body in space (queries/spatial_stability_query.h).
int run_spatial_stability_command(const StabilityOptions& o, const SpatialInput& in) {
  const std::pair<bool, const char*> others[] = {
      {!o.wrenches.empty(), "--wrenches"}, {o.region, "--region"}, {o.finger, "--finger"}, {o.margin, "--margin"}};
  for (const auto& [given, name] : others)
    if (given) throw exact::InputError("command line", name, "a spatial scene takes one --wrench fx,fy,fz,tx,ty,tz");
  if (o.wrench.empty())
    throw exact::InputError("command line", "--wrench",
                            "a spatial scene needs --wrench fx,fy,fz,tx,ty,tz (force, torque about the com)");
  queries::SpatialStabilityOptions q;
  q.common = o.common.query();
  q.wrench = parse_number_list(o.wrench, "--wrench", 6);
  q.certificate = o.certificate;
  const auto a = run_spatial_stability(in, q);
  return print(o, a, [&] { std::cout << to_text(*a, o.file); });
}

int run_stability_command(const StabilityOptions& o) {
  SceneOrAssembly read = read_scene_or_assembly(o.file, o.snap);
  if (const auto* assembly = std::get_if<AssemblyInput>(&read)) return run_assembly_stability_command(o, *assembly);
  if (const auto* spatial = std::get_if<SpatialInput>(&read)) return run_spatial_stability_command(o, *spatial);
  const SceneInput& input = std::get<SceneInput>(read);
  if (int(o.region) + int(o.finger) + int(!o.wrench.empty() && !o.region) + int(!o.wrenches.empty()) != 1)
    throw exact::InputError("command line", "--wrench",
                            "give exactly one of --wrench fx,fy,tz, --wrenches FILE, --region or --finger");
  const queries::CommonOptions common = o.common.query();
  const geometry::PlanarScene& scene = input.scene;
  if (!o.wrenches.empty()) {
    const auto a = run_wrenches(input, {common, o.wrenches});
    return print(o, a, [&] { print_wrenches(o, *a); });
  }
  if (o.region) {
    RegionOptions q{common, std::nullopt, o.svg};
    if (!o.wrench.empty()) q.wrench = parse_number_list(o.wrench, "--wrench", 3);
    const auto a = run_region(input, q);
    return print(o, a, [&] { print_region(o, scene, *a); });
  }
  if (o.finger) {
    const auto a = run_finger(input, {common, o.svg});
    return print(o, a, [&] { print_finger(o, scene, *a); });
  }
  const auto a = run_stability(input, {common, parse_number_list(o.wrench, "--wrench", 3), o.margin, o.certificate});
  return print(o, a, [&] { std::visit([&](const auto& r) { print_stability(o, scene, *a, r); }, a->outcome); });
}

}  // namespace

void register_stability(CLI::App& app, Action& action) {
  auto o = std::make_shared<StabilityOptions>();
  CLI::App* sub = app.add_subcommand(
      "stability", "Is the workpiece strongly stable, only weakly stable, or unstable under a wrench?");
  add_snap_option(*sub, o->snap);
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file,
                  "Planar scene file (format: docs/formats.md, section 3), an assembly (section 3a) or a spatial scene "
                  "(3b)")
      ->required();
  CLI::Option* wrench =
      sub->add_option("--wrench", o->wrench,
                      "External wrench fx,fy,tz (torque about the centre of mass), exact numbers; a spatial "
                      "scene: fx,fy,fz,tx,ty,tz");
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
    action = [o] { return run_stability_command(*o); };
  });
}

}  // namespace contactcert::cli
