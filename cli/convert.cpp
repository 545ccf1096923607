// `contactcert convert FILE`: span <-> face conversion of a cone (SPEC sections 4 and 6).
// Span in: the minimal face form out (and the minimal span form). Face in (strict rows allowed): the
// closure's generators out, with the open faces, and the minimal face form of the cone itself.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "exact/json_input.h"
#include "exact/number.h"
#include "geometry/canonical.h"
#include "geometry/cone_json.h"
#include "geometry/double_description.h"
#include "geometry/nnc_cone.h"

namespace contactcert::cli {
namespace {

using exact::Mat;
using exact::Q;
using geometry::FaceCone;
using geometry::SpanCone;

struct ConvertOptions {
  std::string file;
  CommonOptions common;
};

nlohmann::json float_rows(const Mat<double>& M) {
  nlohmann::json a = nlohmann::json::array();
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < M.cols(); ++j) row.push_back(M(i, j));
    a.push_back(std::move(row));
  }
  return a;
}

void print_rows(std::ostream& os, const char* title, const Mat<Q>& M, const char* rel) {
  if (M.rows() == 0) return;
  os << title << ":\n";
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    os << "  [";
    for (Eigen::Index j = 0; j < M.cols(); ++j) os << (j ? " " : "") << M(i, j).get_str();
    os << "]" << rel << "\n";
  }
}

int run_float(const geometry::ConeInput& in, const ConvertOptions& opts, const geometry::DdBudget& budget) {
  nlohmann::json j;
  if (in.form == geometry::ConeInput::Form::kSpan) {
    const auto s =
        SpanCone<double>::from_rows(in.span.dim, exact::to_double(in.span.rays), exact::to_double(in.span.lines));
    const FaceCone<double> f = geometry::canonical(geometry::to_face(s, budget));
    j = {{"input", "span"},
         {"arith", "float"},
         {"dim", f.dim},
         {"face_approx", {{"inequalities", float_rows(f.inequalities)}, {"equalities", float_rows(f.equalities)}}}};
  } else {
    const auto c = FaceCone<double>::from_rows(in.face.dim, exact::to_double(in.face.inequalities),
                                               exact::to_double(in.face.equalities), exact::to_double(in.face.strict));
    const geometry::NncForm<double> n = geometry::nnc_form(c, budget);
    j = {{"input", "face"},
         {"arith", "float"},
         {"dim", c.dim},
         {"empty", n.status == geometry::NncStatus::kEmpty},
         {"span_approx", {{"rays", float_rows(n.closure.rays)}, {"lines", float_rows(n.closure.lines)}}},
         {"open_faces", n.open_faces}};
  }
  if (opts.common.json) {
    std::cout << j.dump() << "\n";
  } else {
    std::cout << j.dump(2) << "\n";
  }
  return 0;
}

int run_convert(const ConvertOptions& opts) {
  const geometry::ConeInput in = geometry::read_cone(exact::JsonInput::load(opts.file));
  geometry::DdBudget budget;
  budget.deadline = exact::Deadline::after(opts.common.time_limit);  // checked inside the conversion: exit 3
  if (opts.common.arith == "float") return run_float(in, opts, budget);
  // Exact (the verified path has nothing to check here: the conversion is exact and cheap in R^d).
  const geometry::NncForm<Q> n = in.form == geometry::ConeInput::Form::kSpan ? geometry::nnc_form(in.span, budget)
                                                                             : geometry::nnc_form(in.face, budget);
  if (opts.common.json) {
    nlohmann::json j = geometry::nnc_to_json(n);
    j["input"] = in.form == geometry::ConeInput::Form::kSpan ? "span" : "face";
    std::cout << j.dump() << "\n";
    return 0;
  }
  std::ostream& os = std::cout;
  os << "cone in R^" << n.face.dim << ", given in " << (in.form == geometry::ConeInput::Form::kSpan ? "span" : "face")
     << " form\n";
  if (n.status == geometry::NncStatus::kEmpty) {
    os << "empty\n";
    return 0;
  }
  os << "dimension " << n.dimension() << (n.open_faces.empty() ? ", closed" : ", not closed") << "\n";
  os << "face form (f . g <= 0, s . g < 0, e . g = 0):\n";
  print_rows(os, " inequalities", n.face.inequalities, " . g <= 0");
  print_rows(os, " strict", n.face.strict, " . g < 0");
  print_rows(os, " equalities", n.face.equalities, " . g = 0");
  os << "span form" << (n.open_faces.empty() ? "" : " of the closure") << ":\n";
  print_rows(os, " rays", n.closure.rays, "");
  print_rows(os, " lines", n.closure.lines, "");
  for (const auto& f : n.open_faces) {
    os << " open face (missing from the cone): rays {";
    for (size_t i = 0; i < f.size(); ++i) os << (i ? ", " : "") << f[i];
    os << "}" << (f.empty() ? " (the lineality space / origin)" : "") << "\n";
  }
  return 0;
}

}  // namespace

void register_convert(CLI::App& app, Action& action) {
  auto opts = std::make_shared<ConvertOptions>();
  CLI::App* sub =
      app.add_subcommand("convert", "Span <-> face conversion of a cone (format: docs/formats.md, section 4)");
  sub->add_option("FILE", opts->file, "Cone file: {dim, rays, lines} or {dim, inequalities, strict, equalities}")
      ->required();
  add_common_options(*sub, opts->common);
  sub->callback([opts, &action] { action = [opts] { return run_convert(*opts); }; });
}

}  // namespace contactcert::cli
