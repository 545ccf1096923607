// The class Ucp (a quasistatic or plain UCP problem) with solve, generate and check: the queries of `ucp` and
// `check` (queries/ucp_query.h, queries/check.h), their options parsed from Python's strings as the CLI parses them.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>

#include "exact/json_input.h"
#include "python/bindings.h"
#include "queries/check.h"
#include "queries/ucp_query.h"

namespace contactcert::python {
namespace {

/// `ucp FILE` with its options (a budget not given: the default); `certificate`: the file to write, or empty;
/// `uniqueness`: --all, with its budget and certificate file.
WithCertificate solve(const Ucp& u, const std::string& method, const std::string& arith, std::uint64_t seed,
                      std::optional<long> max_nodes, std::optional<long> max_bases, double time_limit,
                      const std::string& certificate, bool uniqueness, std::optional<long> max_modes,
                      const std::string& uniqueness_certificate) {
  queries::UcpQueryOptions o;
  o.common = {queries::parse_arith(arith, "--arith"), time_limit};
  o.method = queries::parse_method(method, "--method");
  o.seed = seed;
  o.max_nodes = max_nodes;
  o.max_bases = max_bases;
  o.certificate = certificate;
  o.uniqueness = {uniqueness, max_modes, uniqueness_certificate};
  const queries::UcpAnswer a = answer(queries::run_ucp(u, o));
  return {exact::json_text(queries::to_json(a)), a.certificate_text};
}

/// `ucp --generate KIND` with its options: the problem as the CLI's file holds it, read back as `ucp FILE` reads it.
Ucp generate(const std::string& kind, std::uint64_t seed, int nc, const std::string& mu_max, int abar, int rows,
             int cols, bool planted) {
  queries::UcpGenerateOptions o;
  o.generator = queries::parse_generator(kind, "--generate");
  o.seed = seed;
  o.nc = nc;
  o.mu_max = queries::parse_exact_option(mu_max, "--mu-max");
  o.abar = abar;
  o.rows = rows;
  o.cols = cols;
  o.planted = planted;
  return queries::parse_ucp(solvers::ucp::to_json_text(queries::generate_ucp(o)), "generated");
}

/// `check FILE [--problem PROBLEM]` on texts (an empty `problem_text`: no --problem): the JSON `check --json`
/// prints and the readable lines of the evidence.
std::pair<std::string, std::string> check(const std::string& text, const std::string& name,
                                          const std::string& problem_text, const std::string& problem_name) {
  std::optional<exact::JsonInput> problem;
  if (!problem_text.empty()) problem = exact::JsonInput::parse(problem_text, problem_name);
  const queries::CheckResult c = answer(queries::with_limits(
      exact::Arith::kExact, [&] { return queries::check_text(text, name, problem ? &*problem : nullptr); }));
  return {queries::to_json(c).dump(), c.text};
}

}  // namespace

void bind_ucp(py::module_& m) {
  py::class_<Ucp>(m, "Ucp")
      .def_static("load", &queries::load_ucp)
      .def_static("parse", &queries::parse_ucp, py::arg("text"), py::arg("name"))
      .def_readonly("name", &Ucp::name)
      .def_readonly("file_text", &Ucp::text)
      .def("text", [](const Ucp& u) { return solvers::ucp::to_json_text(u.problem); })
      .def("solve", &solve, Release());
  m.def("generate", &generate, Release());
  m.def("check", &check, Release());
}

}  // namespace contactcert::python
