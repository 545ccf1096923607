#include "queries/cone_query.h"

#include <nlohmann/json.hpp>

#include "exact/input_error.h"
#include "exact/rational_text.h"
#include "queries/cone_svg.h"
#include "queries/contact_forces.h"
#include "solvers/stability/strong_stability.h"
#include "solvers/wrench_cone/cone_certificate.h"
#include "solvers/wrench_cone/line_of_force.h"

namespace contactcert::queries {
namespace {

using exact::Mat;
using exact::Q;
using exact::to_string;

/// The rows of M as JSON arrays, row r written as the entries of `row(r-th row of M)`.
template <class T, class Row>
nlohmann::json rows_json(const Mat<T>& M, Row row) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index r = 0; r < M.rows(); ++r) rows.push_back(row(exact::Vec<T>(M.row(r).transpose())));
  return rows;
}

nlohmann::json matrix_json(const Mat<Q>& M) {
  return rows_json(M, [](const exact::Vec<Q>& v) {
    std::vector<std::string> entries;
    for (Eigen::Index i = 0; i < v.size(); ++i) entries.push_back(to_string(v(i)));
    return entries;
  });
}

nlohmann::json matrix_json(const Mat<double>& M) {
  return rows_json(M, [](const exact::Vec<double>& v) { return std::vector<double>(v.data(), v.data() + v.size()); });
}

/// Rows as primitive integer direction vectors (SPEC section 1), as strings.
nlohmann::json directions_json(const Mat<Q>& M) {
  return rows_json(M, [](const exact::Vec<Q>& v) {
    std::vector<std::string> entries;
    for (const exact::Z& x : exact::primitive(v)) entries.push_back(x.get_str());
    return entries;
  });
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

nlohmann::json exact_cone_json(const ConeAnswer& a) {
  const solvers::WrenchCone<Q>& c = *a.cone;
  const geometry::NncForm<Q>& f = c.cone;
  const bool empty = a.empty();
  nlohmann::json j;
  j["mode"] = a.mode.text();
  j["empty"] = empty;
  j["route"] = route_name(a.options.route);
  j["arith"] = exact::arith_name(a.options.common.arith);
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
      lof.push_back(line_of_force_json(f.closure.rays.row(r).transpose(), a.scene.workpiece.com));
  j["lines_of_force"] = lof;
  return j;
}

nlohmann::json float_cone_json(const ConeAnswer& a) {
  const solvers::WrenchCone<double>& c = *a.cone_float;
  nlohmann::json j;
  j["mode"] = a.mode.text();
  j["empty"] = a.empty();
  j["route"] = route_name(a.options.route);
  j["arith"] = "float";
  j["decided_by"] = "float";
  j["face_approx"] = {{"inequalities", matrix_json(c.cone.face.inequalities)},
                      {"strict", matrix_json(c.cone.face.strict)},
                      {"equalities", matrix_json(c.cone.face.equalities)}};
  j["span_approx"] = {{"rays", matrix_json(c.cone.closure.rays)}, {"lines", matrix_json(c.cone.closure.lines)}};
  return j;
}

/// The certificate file of `cone --certificate` (solvers::cone_certificate) and, for a witness, its view: the
/// witness's "contacts" and "acceleration" are inserted before "scene".
json certificate_file(const SceneInput& input, ConeAnswer& a) {
  solvers::ConeCertificate certificate = solvers::cone_certificate(input.text, a.scene, a.mode);
  if (!certificate.witness()) return std::move(certificate.file);
  ConeWitness w;
  w.g = certificate.wrench;
  solvers::touching_scene(a.scene, &w.touching);
  w.c = solvers::contact_forces(a.cone->form, w.touching, certificate.z);
  const json view = witness_json(a.scene, w.touching, w.c, w.g);
  a.witness = std::move(w);
  json file;
  for (auto it = certificate.file.begin(); it != certificate.file.end(); ++it) {
    if (it.key() == "scene") {
      file["contacts"] = view.at("contacts");
      file["acceleration"] = view.at("acceleration");
    }
    file[it.key()] = it.value();
  }
  return file;
}

}  // namespace

bool ConeAnswer::empty() const { return (cone ? cone->status : cone_float->status) == solvers::ConeStatus::kEmpty; }

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

ConeAnswer cone_answer(const SceneInput& input, const ConeOptions& options) {
  ConeAnswer a{input.scene, options, {}, {}, {}, {}, {}};
  a.mode = cone_mode(input.scene, input.name, options.mode, options.table2 == Table2::kPrinted);
  const bool float_path = options.common.arith == exact::Arith::kFloat;
  if (!options.certificate.empty() && float_path)
    throw exact::InputError("command line", "--certificate", "a certificate needs --arith exact or verified");
  if (!options.svg.empty() && float_path)
    throw exact::InputError("command line", "--svg", "a picture needs --arith exact or verified");
  geometry::DdBudget budget;
  budget.deadline = options.common.deadline();
  if (float_path) {
    a.cone_float = solvers::wrench_cone<double>(input.scene, a.mode, options.route, budget);
    return a;
  }
  a.cone = solvers::wrench_cone<Q>(input.scene, a.mode, options.route, budget);
  if (!options.svg.empty()) write_text_file(options.svg, cone_svg(a));
  if (!options.certificate.empty()) {
    a.certificate_text = certificate_file(input, a).dump(1) + "\n";
    write_certificate_file("cone", options.certificate, a.certificate_text,
                           a.empty() ? "the cone is empty" : "the cone is not empty");
  }
  return a;
}

}  // namespace

Limited<ConeAnswer> run_cone(const SceneInput& input, const ConeOptions& options) {
  return with_limits(options.common.arith, [&] { return cone_answer(input, options); });
}

json to_json(const ConeAnswer& answer) {
  if (!answer.cone) return float_cone_json(answer);
  json j = exact_cone_json(answer);  // the cone's keys sorted, then the certificate's
  if (!answer.options.certificate.empty()) j["certificate"] = answer.options.certificate;
  if (answer.witness)
    j["witness"] = witness_json(answer.scene, answer.witness->touching, answer.witness->c, answer.witness->g);
  return j;
}

std::string cone_svg(const ConeAnswer& a) {
  const bool empty = a.empty();
  const geometry::NncForm<Q>& f = a.cone->cone;
  return wrench_cone_svg(a.scene, empty ? Mat<Q>(0, 3) : f.closure.rays, empty ? Mat<Q>(0, 3) : f.closure.lines,
                         "mode '" + a.mode.text() + "'" + (empty ? " (empty cone)" : ""));
}

std::string line_of_force_text(const exact::Vec<Q>& g, const geometry::Point2& com) {
  const solvers::LineOfForce l = solvers::line_of_force(g, com);
  if (l.kind == solvers::LineOfForce::Kind::kZero) return "zero wrench";
  if (l.kind == solvers::LineOfForce::Kind::kPureMoment)
    return std::string("pure moment, ") + (sgn(l.torque) > 0 ? "counter-clockwise" : "clockwise");
  return "force along " + geometry::point_text(l.direction) + " through " + geometry::point_text(l.through);
}

}  // namespace contactcert::queries
