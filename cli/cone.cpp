// `contactcert cone FILE --mode MODE`: the wrench cone of an augmented contact mode (Balkcom,
// Trinkle 2002), exactly, with the face form (strict rows marked), the span form of its closure
// (which faces are open), the generators read as lines of force, and optionally an SVG picture.
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "cli/snap_option.h"
#include "exact/rational_text.h"
#include "queries/cone_query.h"
#include "queries/contact_forces.h"
#include "queries/spatial_cone_query.h"
#include "solvers/stability/world_forces.h"

namespace contactcert::cli {
namespace {

using exact::Mat;
using exact::Q;
using exact::to_string;

struct ConeCliOptions {
  CommonOptions common;
  std::string file;
  std::string snap;  ///< --snap TOL ("" = none)
  std::string mode;
  std::string route = "paper";
  std::string svg;
  std::string table2 = "strict";
  std::string certificate;
};

const char* interaction_name(solvers::Interaction l) {
  switch (l) {
    case solvers::Interaction::kSeparate:
      return "separate";
    case solvers::Interaction::kApproach:
      return "approach";
    case solvers::Interaction::kUnconstrained:
      return "unconstrained";
    case solvers::Interaction::kSlideLeft:
      return "slide left";
    case solvers::Interaction::kSlideRight:
      return "slide right";
    case solvers::Interaction::kRoll:
      return "roll";
    case solvers::Interaction::kMaintain:
      return "maintain";
    case solvers::Interaction::kSeparatePrinted:
      return "separate, a_n >= 0 as Table 2 prints it";
  }
  return "";
}

std::string row_text(const Mat<Q>& M, Eigen::Index r) {
  std::string s = "(";
  for (Eigen::Index c = 0; c < M.cols(); ++c) s += (c ? ", " : "") + to_string(M(r, c));
  return s + ")";
}

void print_cone_exact(const std::string& file, const ConeAnswer& a) {
  const geometry::PlanarScene& scene = a.scene;
  const solvers::WrenchCone<Q>& c = *a.cone;
  const geometry::NncForm<Q>& f = c.cone;
  const geometry::Point2& com = scene.workpiece.com;
  const std::string& certificate = a.options.certificate;
  std::cout << "contactcert cone: " << file << ", mode '" << a.mode.text() << "' (route " << route_name(a.options.route)
            << ", exact)\n";
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const auto& fx = scene.fixels[i];
    std::cout << "  fixel " << i << ": " << (fx.frame.touching() ? "touching at " : "gap, closest point ")
              << point_text(fx.frame.point) << ", n = " << point_text(solvers::reported_normal(fx))
              << ", mu_s = " << to_string(fx.mu_s) << ", mu_k = " << to_string(fx.mu_k) << ": "
              << static_cast<char>(a.mode.letters[i]) << " (" << interaction_name(a.mode.letters[i]) << ")\n";
  }
  std::cout << "  K z = P g, z >= 0 (eqs. 13-17): K is " << c.form.K.rows() << " x " << c.form.K.cols() << "; z = (";
  for (std::size_t i = 0; i < c.form.names.size(); ++i)
    std::cout << (i ? ", " : "") << c.form.names[i] << (c.form.strict[i] ? " > 0" : "");
  std::cout << ")\n";
  if (a.empty()) {
    std::cout << "wrench cone: EMPTY (no external wrench is consistent with this mode)\n";
    if (!certificate.empty())
      std::cout << "certificate: " << certificate << " (a Motzkin vector: no wrench has the mode)\n";
    return;
  }
  std::cout << "wrench cone: non-empty, dimension " << f.dimension()
            << "; wrenches g = (f_x, f_y, torque about the com " << point_text(com) << ")\n";
  std::cout << "face form (f . g <= 0, or < 0 where strict):\n";
  for (Eigen::Index r = 0; r < f.face.inequalities.rows(); ++r)
    std::cout << "  " << row_text(f.face.inequalities, r) << " . g <= 0\n";
  for (Eigen::Index r = 0; r < f.face.strict.rows(); ++r)
    std::cout << "  " << row_text(f.face.strict, r) << " . g < 0   (strict)\n";
  for (Eigen::Index r = 0; r < f.face.equalities.rows(); ++r)
    std::cout << "  " << row_text(f.face.equalities, r) << " . g = 0\n";
  std::cout << "span form of the closure: " << f.closure.rays.rows() << " generators, " << f.closure.lines.rows()
            << " lines\n";
  for (Eigen::Index r = 0; r < f.closure.rays.rows(); ++r)
    std::cout << "  g" << r + 1 << " = " << row_text(f.closure.rays, r) << ": "
              << line_of_force_text(f.closure.rays.row(r).transpose(), com) << "\n";
  for (Eigen::Index r = 0; r < f.closure.lines.rows(); ++r)
    std::cout << "  l" << r + 1 << " = +-" << row_text(f.closure.lines, r) << ": "
              << line_of_force_text(f.closure.lines.row(r).transpose(), com) << ", both senses\n";
  if (f.open_faces.empty()) {
    std::cout << "closed: every face belongs to the cone\n";
  } else {
    std::cout << "open faces (in the closure, not in the cone):\n";
    for (const auto& face : f.open_faces) {
      std::cout << "  ";
      if (face.empty()) std::cout << (f.closure.lines.rows() ? "the lineality space" : "the origin");
      for (std::size_t k = 0; k < face.size(); ++k) std::cout << (k ? ", " : "spanned by ") << "g" << face[k] + 1;
      if (!face.empty() && f.closure.lines.rows() > 0) std::cout << " and the lines";
      std::cout << "\n";
    }
  }
  if (a.witness)
    std::cout << "certificate: " << certificate << "\n"
              << witness_text(scene, a.witness->touching, a.witness->c, a.witness->g, "  ");
  if (!a.options.svg.empty()) std::cout << "picture: " << a.options.svg << "\n";
}

void print_cone_float(const std::string& file, const ConeAnswer& a) {
  const solvers::WrenchCone<double>& c = *a.cone_float;
  std::cout << "contactcert cone: " << file << ", mode '" << a.mode.text() << "' (route " << route_name(a.options.route)
            << ", float: unchecked doubles)\n";
  if (a.empty()) {
    std::cout << "wrench cone: EMPTY (float decision)\n";
    return;
  }
  std::cout << "wrench cone: non-empty; " << c.cone.face.inequalities.rows() << " closed faces, "
            << c.cone.face.strict.rows() << " strict, " << c.cone.closure.rays.rows() << " generators\n";
  for (Eigen::Index r = 0; r < c.cone.closure.rays.rows(); ++r)
    std::cout << "  g" << r + 1 << " ~ (" << c.cone.closure.rays(r, 0) << ", " << c.cone.closure.rays(r, 1) << ", "
              << c.cone.closure.rays(r, 2) << ")\n";
}

/// `cone SPATIAL --mode M`: a body in space (queries/spatial_cone_query.h); the planar-only options are refused.
int run_spatial_cone_command(const ConeCliOptions& o, const SpatialInput& in) {
  const std::pair<bool, const char*> planar[] = {
      {o.route != "paper", "--route"}, {o.table2 != "strict", "--table2"}, {!o.svg.empty(), "--svg"}};
  for (const auto& [given, name] : planar)
    if (given)
      throw exact::InputError("command line", name, "a spatial scene's cone takes --mode and --certificate only");
  const Limited<SpatialConeAnswer> r = run_spatial_cone(in, {o.common.query(), o.mode, o.certificate});
  if (!r) return report_limit("cone", r.limit(), o.common.json);
  std::cout << (o.common.json ? to_json(*r).dump() + "\n" : to_text(*r, o.file));
  return 0;
}

int run_cone_command(const ConeCliOptions& o) {
  SceneOrAssembly read = read_scene_or_assembly(o.file, o.snap);  // read once: FILE may be a pipe
  if (const auto* spatial = std::get_if<SpatialInput>(&read)) return run_spatial_cone_command(o, *spatial);
  if (std::holds_alternative<AssemblyInput>(read))
    throw exact::InputError(o.file, "$.bodies", "one workpiece: `cone` takes a planar or a spatial scene");
  const SceneInput& input = std::get<SceneInput>(read);
  ConeOptions options;
  options.common = o.common.query();
  options.mode = o.mode;
  options.route = parse_route(o.route, "--route");
  options.table2 = parse_table2(o.table2, "--table2");
  options.certificate = o.certificate;
  options.svg = o.svg;
  const Limited<ConeAnswer> r = run_cone(input, options);
  if (!r) return report_limit("cone", r.limit(), o.common.json);
  const ConeAnswer& a = *r;
  if (o.common.json)
    std::cout << to_json(a).dump() << "\n";
  else if (a.cone)
    print_cone_exact(o.file, a);
  else
    print_cone_float(o.file, a);
  return 0;
}

}  // namespace

void register_cone(CLI::App& app, Action& action) {
  auto opts = std::make_shared<ConeCliOptions>();
  CLI::App* sub = app.add_subcommand("cone", "Wrench cone of an augmented contact mode (Balkcom, Trinkle 2002)");
  sub->add_option("FILE", opts->file, "Planar scene file (format: docs/formats.md, section 3) or a spatial scene (3b)")
      ->required();
  sub->add_option("--mode", opts->mode, "One letter per fixel from s a u l r n m (Table 2)")->required();
  sub->add_option("--route", opts->route, "paper: F = K^F P; project: facets by exact LPs in wrench space")
      ->check(CLI::IsMember({"paper", "project"}))
      ->capture_default_str();
  sub->add_option("--svg", opts->svg, "Write a picture: workpiece, fixels, friction cones, lines of force");
  sub->add_option("--table2", opts->table2,
                  "strict: s at a touching fixel is a_n > 0 (seeds errata); printed: a_n >= 0 as Table 2 prints it")
      ->check(CLI::IsMember({"strict", "printed"}))
      ->default_str("strict");
  sub->add_option(
      "--certificate", opts->certificate,
      "Write the evidence for `contactcert check`: a Motzkin vector (empty cone) or a witness wrench; for a "
      "spatial scene, the proof of the cone in both forms");
  add_snap_option(*sub, opts->snap);
  add_common_options(*sub, opts->common);
  sub->callback([opts, &action] { action = [opts] { return run_cone_command(*opts); }; });
}

}  // namespace contactcert::cli
