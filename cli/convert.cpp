// `contactcert convert FILE`: span <-> face conversion of a cone (queries/convert_query.h): the options and the
// text report.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "cli/command.h"
#include "exact/json_input.h"
#include "queries/convert_query.h"

namespace contactcert::cli {
namespace {

struct ConvertOptions {
  std::string file;
  CommonOptions common;
};

void print_rows(std::ostream& os, const char* title, const exact::Mat<exact::Q>& M, const char* rel) {
  if (M.rows() == 0) return;
  os << title << ":\n";
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    os << "  [";
    for (Eigen::Index j = 0; j < M.cols(); ++j) os << (j ? " " : "") << M(i, j).get_str();
    os << "]" << rel << "\n";
  }
}

int run_convert(const ConvertOptions& opts) {
  const queries::Limited<queries::ConvertAnswer> r =
      queries::run_convert(exact::JsonInput::load(opts.file), {opts.common.query()});
  if (!r) return report_limit("convert", r.limit(), opts.common.json);
  const queries::ConvertAnswer& a = *r;
  if (opts.common.json || !a.exact) {  // the float answer is printed as its JSON, indented without --json
    std::cout << (opts.common.json ? queries::to_json(a).dump() : queries::to_json(a).dump(2)) << "\n";
    return 0;
  }
  const geometry::NncForm<exact::Q>& n = *a.exact;
  std::ostream& os = std::cout;
  os << "cone in R^" << n.face.dim << ", given in " << (a.input == geometry::ConeInput::Form::kSpan ? "span" : "face")
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
