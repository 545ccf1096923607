#include "queries/convert_query.h"

#include "geometry/canonical.h"
#include "geometry/double_description.h"

namespace contactcert::queries {
namespace {

/// A float matrix as rows of doubles (approx_json), in the sorted-key JSON of the cone formats.
nlohmann::json float_rows(const exact::Mat<double>& M) { return nlohmann::json(approx_json(M)); }

const char* form_name(geometry::ConeInput::Form f) { return f == geometry::ConeInput::Form::kSpan ? "span" : "face"; }

ConvertAnswer convert_answer(const exact::JsonInput& file, const ConvertOptions& o) {
  const geometry::ConeInput in = geometry::read_cone(file);
  geometry::DdBudget budget;
  budget.deadline = o.common.deadline();  // checked inside the conversion
  ConvertAnswer a;
  a.input = in.form;
  const bool span = in.form == geometry::ConeInput::Form::kSpan;
  if (o.common.arith != exact::Arith::kFloat) {
    a.exact = span ? geometry::nnc_form(in.span, budget) : geometry::nnc_form(in.face, budget);
  } else if (span) {
    const auto s = geometry::SpanCone<double>::from_rows(in.span.dim, exact::to_double(in.span.rays),
                                                         exact::to_double(in.span.lines));
    a.float_face = geometry::canonical(geometry::to_face(s, budget));
  } else {
    const auto c =
        geometry::FaceCone<double>::from_rows(in.face.dim, exact::to_double(in.face.inequalities),
                                              exact::to_double(in.face.equalities), exact::to_double(in.face.strict));
    a.float_closure = geometry::nnc_form(c, budget);
  }
  return a;
}

}  // namespace

Limited<ConvertAnswer> run_convert(const exact::JsonInput& file, const ConvertOptions& o) {
  return with_limits(o.common.arith, [&] { return convert_answer(file, o); });
}

nlohmann::json to_json(const ConvertAnswer& a) {
  if (a.exact) {
    nlohmann::json j = geometry::nnc_to_json(*a.exact);
    j["input"] = form_name(a.input);
    return j;
  }
  if (a.float_face)
    return nlohmann::json{{"input", "span"},
                          {"arith", "float"},
                          {"dim", a.float_face->dim},
                          {"face_approx",
                           {{"inequalities", float_rows(a.float_face->inequalities)},
                            {"equalities", float_rows(a.float_face->equalities)}}}};
  const geometry::NncForm<double>& n = *a.float_closure;
  return nlohmann::json{{"input", "face"},
                        {"arith", "float"},
                        {"dim", n.face.dim},
                        {"empty", n.status == geometry::NncStatus::kEmpty},
                        {"span_approx", {{"rays", float_rows(n.closure.rays)}, {"lines", float_rows(n.closure.lines)}}},
                        {"open_faces", n.open_faces}};
}

}  // namespace contactcert::queries
