#include "geometry/cone_json.h"

#include <nlohmann/json.hpp>

#include "exact/rational_text.h"

namespace contactcert::geometry {
namespace {

using Index = Eigen::Index;

nlohmann::json rows_json(const Mat<Q>& M) {
  nlohmann::json a = nlohmann::json::array();
  for (Index i = 0; i < M.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Index j = 0; j < M.cols(); ++j) row.push_back(exact::to_string(M(i, j)));
    a.push_back(std::move(row));
  }
  return a;
}

Mat<Q> read_rows(const exact::JsonInput& node, std::string_view key, Index dim) {
  const auto m = node.find(key);
  if (!m) return Mat<Q>(0, dim);
  if (!m->is_array()) m->fail("expected an array of rows of " + std::to_string(dim) + " numbers");
  for (const auto& row : m->elements())
    if (!row.is_array()) row.fail("expected a row: an array of " + std::to_string(dim) + " numbers");
  return m->rational_matrix(std::nullopt, static_cast<std::size_t>(dim));
}

bool is_empty_encoding(const FaceCone<Q>& c) {
  for (Index i = 0; i < c.strict.rows(); ++i)
    if (c.strict.row(i).isZero()) return true;
  return false;
}

}  // namespace

ConeInput read_cone(const exact::JsonInput& node) {
  if (!node.is_object()) node.fail("expected a cone object {\"dim\": d, ...} (SPEC section 4)");
  node.expect_keys({"dim", "rays", "lines", "inequalities", "strict", "equalities"});
  const Index dim = node.at("dim").integer(1, 10000);
  const bool span = node.find("rays") || node.find("lines");
  const bool face = node.find("inequalities") || node.find("strict") || node.find("equalities");
  if (span && face)
    node.fail(
        "expected either the span form (rays, lines) or the face form (inequalities, strict, equalities), not both");
  if (!span && !face)
    node.fail("expected \"rays\"/\"lines\" (span form) or \"inequalities\"/\"strict\"/\"equalities\" (face form)");
  ConeInput in;
  if (span) {
    in.form = ConeInput::Form::kSpan;
    in.span = SpanCone<Q>::from_rows(dim, read_rows(node, "rays", dim), read_rows(node, "lines", dim));
  } else {
    in.form = ConeInput::Form::kFace;
    in.face = FaceCone<Q>::from_rows(dim, read_rows(node, "inequalities", dim), read_rows(node, "equalities", dim),
                                     read_rows(node, "strict", dim));
  }
  return in;
}

nlohmann::json span_to_json(const SpanCone<Q>& cone) {
  return {{"dim", cone.dim}, {"rays", rows_json(cone.rays)}, {"lines", rows_json(cone.lines)}};
}

nlohmann::json face_to_json(const FaceCone<Q>& cone) {
  if (is_empty_encoding(cone)) return {{"dim", cone.dim}, {"empty", true}};
  return {{"dim", cone.dim},
          {"empty", false},
          {"inequalities", rows_json(cone.inequalities)},
          {"strict", rows_json(cone.strict)},
          {"equalities", rows_json(cone.equalities)}};
}

nlohmann::json nnc_to_json(const NncForm<Q>& form) {
  nlohmann::json j;
  j["dim"] = form.face.dim;
  j["empty"] = form.status == NncStatus::kEmpty;
  j["dimension"] = form.dimension();
  j["face"] = face_to_json(form.face);
  if (form.status == NncStatus::kEmpty) return j;
  j["span"] = span_to_json(form.closure);
  j["closed"] = form.open_faces.empty();
  nlohmann::json open = nlohmann::json::array();
  for (const auto& f : form.open_faces) open.push_back(f);
  j["open_faces"] = open;
  return j;
}

}  // namespace contactcert::geometry
