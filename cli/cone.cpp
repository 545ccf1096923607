// `contactcert cone FILE --mode MODE`: the wrench cone of an augmented contact mode (Balkcom,
// Trinkle 2002), exactly, with the face form (strict rows marked), the span form of its closure
// (which faces are open), the generators read as lines of force, and optionally an SVG picture.
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "cli/results.h"
#include "cli/snap_option.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "queries/cone_svg.h"
#include "queries/contact_forces.h"
#include "queries/json_out.h"
#include "solvers/stability/strong_stability.h"
#include "solvers/wrench_cone/cone_certificate.h"
#include "solvers/wrench_cone/line_of_force.h"
#include "solvers/wrench_cone/wrench_cone.h"

namespace contactcert::cli {
namespace {

using exact::Mat;
using exact::Q;
using exact::to_string;

struct ConeOptions {
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

nlohmann::json matrix_json(const Mat<Q>& M) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index c = 0; c < M.cols(); ++c) row.push_back(to_string(M(r, c)));
    rows.push_back(row);
  }
  return rows;
}

/// Rows as primitive integer direction vectors (SPEC section 1), as strings.
nlohmann::json directions_json(const Mat<Q>& M) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (const exact::Z& x : exact::primitive(exact::Vec<Q>(M.row(r).transpose()))) row.push_back(x.get_str());
    rows.push_back(row);
  }
  return rows;
}

nlohmann::json matrix_json(const Mat<double>& M) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index c = 0; c < M.cols(); ++c) row.push_back(M(r, c));
    rows.push_back(row);
  }
  return rows;
}

/// "force along (fx, fy) through (x, y)" or "pure moment".
std::string line_of_force_text(const exact::Vec<Q>& g, const geometry::Point2& com) {
  const solvers::LineOfForce l = solvers::line_of_force(g, com);
  if (l.kind == solvers::LineOfForce::Kind::kZero) return "zero wrench";
  if (l.kind == solvers::LineOfForce::Kind::kPureMoment)
    return std::string("pure moment, ") + (sgn(l.torque) > 0 ? "counter-clockwise" : "clockwise");
  return "force along " + point_text(l.direction) + " through " + point_text(l.through);
}

nlohmann::json line_of_force_json(const exact::Vec<Q>& g, const geometry::Point2& com) {
  const solvers::LineOfForce l = solvers::line_of_force(g, com);
  nlohmann::json j;
  j["kind"] = l.kind == solvers::LineOfForce::Kind::kForce
                  ? "force"
                  : (l.kind == solvers::LineOfForce::Kind::kPureMoment ? "pure_moment" : "zero");
  j["direction"] = {to_string(l.direction.x), to_string(l.direction.y)};
  j["through"] = {to_string(l.through.x), to_string(l.through.y)};
  j["torque"] = to_string(l.torque);
  return j;
}

}  // namespace

nlohmann::json cone_json(const geometry::PlanarScene& scene, const solvers::ModeString& mode,
                         const solvers::WrenchCone<Q>& c, const std::string& route, const std::string& arith) {
  const geometry::NncForm<Q>& f = c.cone;
  const bool empty = c.status == solvers::ConeStatus::kEmpty;
  nlohmann::json j;
  j["mode"] = mode.text();
  j["empty"] = empty;
  j["route"] = route;
  j["arith"] = arith;
  j["decided_by"] = "exact";
  if (empty) {
    j["face"] = {{"dim", 3}, {"empty", true}};
    j["span"] = nullptr;
  } else {
    // SPEC section 4; the exact cone is canonical, so its rows are primitive integer vectors.
    j["face"] = {{"dim", 3},
                 {"inequalities", directions_json(f.face.inequalities)},
                 {"strict", directions_json(f.face.strict)},
                 {"equalities", directions_json(f.face.equalities)}};
    j["span"] = {{"dim", 3}, {"rays", directions_json(f.closure.rays)}, {"lines", directions_json(f.closure.lines)}};
  }
  nlohmann::json open = nlohmann::json::array();
  for (const auto& face : f.open_faces) open.push_back(face);
  j["open_faces"] = open;
  j["dimension"] = f.dimension();
  j["K"] = matrix_json(c.form.K);
  j["P"] = matrix_json(c.form.P);
  j["z"] = c.form.names;
  j["z_strict"] = c.form.strict;
  nlohmann::json lof = nlohmann::json::array();
  if (!empty)
    for (Eigen::Index r = 0; r < f.closure.rays.rows(); ++r)
      lof.push_back(line_of_force_json(f.closure.rays.row(r).transpose(), scene.workpiece.com));
  j["lines_of_force"] = lof;
  return j;
}

nlohmann::json cone_json(const solvers::ModeString& mode, const solvers::WrenchCone<double>& c,
                         const std::string& route) {
  nlohmann::json j;
  j["mode"] = mode.text();
  j["empty"] = c.status == solvers::ConeStatus::kEmpty;
  j["route"] = route;
  j["arith"] = "float";
  j["decided_by"] = "float";
  j["face_approx"] = {{"inequalities", matrix_json(c.cone.face.inequalities)},
                      {"strict", matrix_json(c.cone.face.strict)},
                      {"equalities", matrix_json(c.cone.face.equalities)}};
  j["span_approx"] = {{"rays", matrix_json(c.cone.closure.rays)}, {"lines", matrix_json(c.cone.closure.lines)}};
  return j;
}

std::string cone_svg(const geometry::PlanarScene& scene, const solvers::ModeString& mode,
                     const solvers::WrenchCone<Q>& c) {
  const bool empty = c.status == solvers::ConeStatus::kEmpty;
  return wrench_cone_svg(scene, empty ? Mat<Q>(0, 3) : c.cone.closure.rays, empty ? Mat<Q>(0, 3) : c.cone.closure.lines,
                         "mode '" + mode.text() + "'" + (empty ? " (empty cone)" : ""));
}

solvers::ModeString cone_mode(const geometry::PlanarScene& scene, const std::string& file, const std::string& text,
                              bool printed_separation) {
  std::vector<bool> touching;
  for (const auto& f : scene.fixels) touching.push_back(f.frame.touching());
  solvers::ModeParse mode = solvers::parse_mode(text, touching);
  if (mode.status != solvers::ModeStatus::kValid) throw exact::InputError(file, "--mode", mode.message);
  if (printed_separation)  // s at a touching fixel as Table 2 prints it: a_n >= 0 (the letter S)
    for (std::size_t i = 0; i < touching.size(); ++i)
      if (touching[i] && mode.mode.letters[i] == solvers::Interaction::kSeparate)
        mode.mode.letters[i] = solvers::Interaction::kSeparatePrinted;
  return mode.mode;
}

namespace {

/// The certificate of `cone --certificate` and, for a witness, the wrench g and the contact forces c of the
/// touching fixels that its z applies (solvers::contact_forces), for the views of queries/contact_forces.h.
struct ConeCertificateFile {
  json file;  ///< solvers::cone_certificate, with the witness's "contacts" and "acceleration" before "scene"
  bool witness = false;
  std::vector<Eigen::Index> touching;
  exact::Vec<Q> g, c;
};

ConeCertificateFile cone_certificate_file(const std::string& scene_text, const geometry::PlanarScene& scene,
                                          const solvers::ModeString& mode, const solvers::ConeForm<Q>& form) {
  solvers::ConeCertificate certificate = solvers::cone_certificate(scene_text, scene, mode);
  ConeCertificateFile out;
  out.witness = certificate.witness();
  if (!out.witness) {
    out.file = std::move(certificate.file);
    return out;
  }
  out.g = certificate.wrench;
  solvers::touching_scene(scene, &out.touching);
  out.c = solvers::contact_forces(form, out.touching, certificate.z);
  const json view = queries::witness_json(scene, out.touching, out.c, out.g);
  for (auto it = certificate.file.begin(); it != certificate.file.end(); ++it) {
    if (it.key() == "scene") {
      out.file["contacts"] = view.at("contacts");
      out.file["acceleration"] = view.at("acceleration");
    }
    out.file[it.key()] = it.value();
  }
  return out;
}

// --time-limit stops the double description and the LPs of route project (BudgetExceeded, exit 3).
geometry::DdBudget cone_budget(const ConeOptions& o) {
  geometry::DdBudget budget;
  budget.deadline = exact::Deadline::after(o.common.time_limit);
  return budget;
}

int run_exact(const ConeOptions& o, const std::string& text, const geometry::PlanarScene& scene,
              const solvers::ModeString& mode, solvers::Route route) {
  const solvers::WrenchCone<Q> c = solvers::wrench_cone<Q>(scene, mode, route, cone_budget(o));
  const geometry::NncForm<Q>& f = c.cone;
  const bool empty = c.status == solvers::ConeStatus::kEmpty;
  const geometry::Point2& com = scene.workpiece.com;
  if (!o.svg.empty()) {
    write_text_file(o.svg, cone_svg(scene, mode, c));
  }
  ConeCertificateFile certificate;
  if (!o.certificate.empty()) {
    certificate = cone_certificate_file(text, scene, mode, c.form);
    write_text_file(o.certificate, certificate.file.dump(1) + "\n");
  }
  if (o.common.json) {
    json j = cone_json(scene, mode, c, o.route, o.common.arith);
    if (!o.certificate.empty()) j["certificate"] = o.certificate;
    if (certificate.witness) j["witness"] = queries::witness_json(scene, certificate.touching, certificate.c, certificate.g);
    std::cout << j.dump() << "\n";
    return 0;
  }
  std::cout << "contactcert cone: " << o.file << ", mode '" << mode.text() << "' (route " << o.route << ", exact)\n";
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const auto& fx = scene.fixels[i];
    std::cout << "  fixel " << i << ": " << (fx.frame.touching() ? "touching at " : "gap, closest point ")
              << point_text(fx.frame.point) << ", n = " << point_text(fx.frame.normal)
              << ", mu_s = " << to_string(fx.mu_s) << ", mu_k = " << to_string(fx.mu_k) << ": "
              << static_cast<char>(mode.letters[i]) << " (" << interaction_name(mode.letters[i]) << ")\n";
  }
  std::cout << "  K z = P g, z >= 0 (eqs. 13-17): K is " << c.form.K.rows() << " x " << c.form.K.cols() << "; z = (";
  for (std::size_t i = 0; i < c.form.names.size(); ++i)
    std::cout << (i ? ", " : "") << c.form.names[i] << (c.form.strict[i] ? " > 0" : "");
  std::cout << ")\n";
  if (empty) {
    std::cout << "wrench cone: EMPTY (no external wrench is consistent with this mode)\n";
    if (!o.certificate.empty())
      std::cout << "certificate: " << o.certificate << " (a Motzkin vector: no wrench has the mode)\n";
    return 0;
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
  if (certificate.witness)
    std::cout << "certificate: " << o.certificate << "\n"
              << witness_text(scene, certificate.touching, certificate.c, certificate.g, "  ");
  if (!o.svg.empty()) std::cout << "picture: " << o.svg << "\n";
  return 0;
}

int run_float(const ConeOptions& o, const geometry::PlanarScene& scene, const solvers::ModeString& mode,
              solvers::Route route) {
  const solvers::WrenchCone<double> c = solvers::wrench_cone<double>(scene, mode, route, cone_budget(o));
  const bool empty = c.status == solvers::ConeStatus::kEmpty;
  if (o.common.json) {
    std::cout << cone_json(mode, c, o.route).dump() << "\n";
    return 0;
  }
  std::cout << "contactcert cone: " << o.file << ", mode '" << mode.text() << "' (route " << o.route
            << ", float: unchecked doubles)\n";
  if (empty) {
    std::cout << "wrench cone: EMPTY (float decision)\n";
    return 0;
  }
  std::cout << "wrench cone: non-empty; " << c.cone.face.inequalities.rows() << " closed faces, "
            << c.cone.face.strict.rows() << " strict, " << c.cone.closure.rays.rows() << " generators\n";
  for (Eigen::Index r = 0; r < c.cone.closure.rays.rows(); ++r)
    std::cout << "  g" << r + 1 << " ~ (" << c.cone.closure.rays(r, 0) << ", " << c.cone.closure.rays(r, 1) << ", "
              << c.cone.closure.rays(r, 2) << ")\n";
  return 0;
}

int run_cone(const ConeOptions& o) {
  const std::string text = read_scene_text(o.file, o.snap);
  const geometry::PlanarScene scene = geometry::read_planar_scene(exact::JsonInput::parse(text, o.file));
  const solvers::ModeString mode = cone_mode(scene, o.file, o.mode, o.table2 == "printed");
  const solvers::Route route = o.route == "paper" ? solvers::Route::kPaper : solvers::Route::kProject;
  if (!o.certificate.empty() && o.common.arith == "float")
    throw exact::InputError("command line", "--certificate", "a certificate needs --arith exact or verified");
  if (!o.svg.empty() && o.common.arith == "float")
    throw exact::InputError("command line", "--svg", "a picture needs --arith exact or verified");
  // The verified path is the exact one here: the cone's combinatorics are decided in rationals.
  return o.common.arith == "float" ? run_float(o, scene, mode, route) : run_exact(o, text, scene, mode, route);
}

}  // namespace

void register_cone(CLI::App& app, Action& action) {
  auto opts = std::make_shared<ConeOptions>();
  CLI::App* sub = app.add_subcommand("cone", "Wrench cone of an augmented contact mode (Balkcom, Trinkle 2002)");
  sub->add_option("FILE", opts->file, "Planar scene file (format: docs/formats.md, section 3)")->required();
  sub->add_option("--mode", opts->mode, "One letter per fixel from s a u l r n m (Table 2)")->required();
  sub->add_option("--route", opts->route, "paper: F = K^F P; project: facets by exact LPs in wrench space")
      ->check(CLI::IsMember({"paper", "project"}))
      ->capture_default_str();
  sub->add_option("--svg", opts->svg, "Write a picture: workpiece, fixels, friction cones, lines of force");
  sub->add_option("--table2", opts->table2,
                  "strict: s at a touching fixel is a_n > 0 (seeds errata); printed: a_n >= 0 as Table 2 prints it")
      ->check(CLI::IsMember({"strict", "printed"}))
      ->default_str("strict");
  sub->add_option("--certificate", opts->certificate,
                  "Write the evidence for `contactcert check`: a Motzkin vector (empty cone) or a witness wrench");
  add_snap_option(*sub, opts->snap);
  add_common_options(*sub, opts->common);
  sub->callback([opts, &action] { action = [opts] { return run_cone(*opts); }; });
}

}  // namespace contactcert::cli
