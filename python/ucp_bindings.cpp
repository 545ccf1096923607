// The class Ucp (a quasistatic or plain UCP problem) with solve, generate and check.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "cli/option_checks.h"
#include "cli/results.h"
#include "exact/arith.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "python/bindings.h"
#include "queries/json_out.h"

namespace contactcert::python {
namespace {

using exact::Q;

Ucp parse_ucp(const std::string& text, const std::string& name) {
  return {name, solvers::ucp::read_ucp_problem(exact::JsonInput::parse(text, name))};
}

/// `ucp FILE` with its options (a budget not given: the CLI's default); `certificate`: the file to write, or empty.
WithCertificate solve(const Ucp& u, const std::string& method, const std::string& arith, std::uint64_t seed,
                      std::optional<long> max_nodes, std::optional<long> max_bases, double time_limit,
                      const std::string& certificate) {
  cli::refuse_ignored_budgets(method, max_nodes.has_value(), max_bases.has_value());
  solvers::ucp::UcpOptions opts;
  opts.method = solvers::ucp::parse_method(method);
  opts.arith = exact::parse_arith(arith);
  opts.seed = seed;
  opts.max_nodes = max_nodes.value_or(opts.max_nodes);
  opts.max_bases = max_bases.value_or(opts.max_bases);
  opts.time_limit = time_limit;
  if (!certificate.empty() && opts.arith == exact::Arith::kFloat)
    throw exact::InputError("command line", "--certificate", "a certificate needs --arith exact or verified");
  const solvers::ucp::UcpReport r = solvers::ucp::solve_ucp(u.problem, opts);
  std::string text;
  if (!certificate.empty()) {
    text = solvers::ucp::certificate_text(u.problem, r);
    if (!text.empty()) cli::write_text_file(certificate, text);
  }
  return {cli::ucp_json(r, text.empty() ? "" : certificate).dump(), text};
}

/// `check FILE [--problem PROBLEM]` on texts; an empty `problem_text` means no --problem.
std::string check(const std::string& text, const std::string& name, const std::string& problem_text,
                  const std::string& problem_name) {
  const exact::JsonInput cert = exact::JsonInput::parse(text, name);
  if (problem_text.empty()) return cli::check_json(cert).dump();
  const exact::JsonInput problem = exact::JsonInput::parse(problem_text, problem_name);
  return cli::check_json(cert, &problem).dump();
}

}  // namespace

void bind_ucp(py::module_& m) {
  py::class_<Ucp>(m, "Ucp")
      .def_static("load", [](const std::string& path) { return parse_ucp(exact::JsonInput::read_text(path), path); })
      .def_static("parse", &parse_ucp, py::arg("text"), py::arg("name"))
      .def_readonly("name", &Ucp::name)
      .def("text", [](const Ucp& u) { return solvers::ucp::to_json_text(u.problem); })
      .def("solve", &solve, Release());

  m.def(
      "generate",
      [](const std::string& kind, std::uint64_t seed, int nc, const std::string& mu_max, int abar, int rows, int cols,
         bool planted) {
        return Ucp{"generated", cli::generated_problem(kind, seed, nc, mu_max, abar, rows, cols, planted)};
      },
      Release());
  m.def("check", &check, Release());
}

}  // namespace contactcert::python
