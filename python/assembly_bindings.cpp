// The class Assembly (several bodies, docs/formats.md section 3a): stability from rest, the quasistatic problem, the
// contact modes and the picture, through the query layer (queries/assembly_query.h) as `contactcert assembly` runs
// them.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <tuple>

#include "python/bindings.h"
#include "queries/assembly_modes_query.h"
#include "queries/assembly_query.h"
#include "queries/assembly_svg.h"

namespace contactcert::python {
namespace {

using Assembly = queries::AssemblyInput;
/// The --json object's text, the certificate's text ("" if none) and the picture's SVG text.
using Answer = std::tuple<std::string, std::string, std::string>;

/// The options every question on an assembly takes: --arith, --time-limit, --max-nodes (not given: the query's
/// default) and --certificate.
template <class Options>
Options options(const std::string& arith, double time_limit, std::optional<long> max_nodes,
                const std::string& certificate) {
  Options o;
  o.common = {queries::parse_arith(arith, "--arith"), time_limit};
  o.max_nodes = max_nodes.value_or(o.max_nodes);
  o.certificate = certificate;
  return o;
}

/// `assembly FILE [--max-nodes N] [--certificate F]` (a budget not given: the query's default).
Answer stability(const Assembly& a, const std::string& arith, double time_limit, std::optional<long> max_nodes,
                 const std::string& certificate) {
  const auto o = options<queries::AssemblyStabilityOptions>(arith, time_limit, max_nodes, certificate);
  const queries::AssemblyStabilityAnswer ans = answer(queries::run_assembly_stability(a, o));
  return {queries::to_json(ans).dump(), ans.certificate_text, queries::to_svg(a, ans)};
}

/// `assembly FILE --ucp [--max-nodes N] [--max-bases N] [--certificate F]`; `uniqueness`: --all, with its budget
/// (--max-modes) and certificate file (--uniqueness-certificate).
Answer ucp(const Assembly& a, const std::string& arith, double time_limit, std::optional<long> max_nodes,
           std::optional<long> max_bases, const std::string& certificate, bool uniqueness,
           std::optional<long> max_modes, const std::string& uniqueness_certificate) {
  auto o = options<queries::AssemblyUcpOptions>(arith, time_limit, max_nodes, certificate);
  o.max_bases = max_bases.value_or(o.max_bases);
  o.uniqueness = {uniqueness, max_modes, uniqueness_certificate};
  const queries::AssemblyUcpAnswer ans = answer(queries::run_assembly_ucp(a, o));
  return {queries::to_json(ans).dump(), ans.certificate_text, queries::to_svg(a, ans)};
}

/// `modes ASSEMBLY [--max-nodes N] [--max-modes N] [--certificate F]`: the --json text and the certificate's.
WithCertificate modes(const Assembly& a, const std::string& arith, double time_limit, std::optional<long> max_nodes,
                      std::optional<long> max_modes, const std::string& certificate) {
  auto o = options<queries::AssemblyModesOptions>(arith, time_limit, max_nodes, certificate);
  o.max_modes = max_modes.value_or(o.max_modes);
  const queries::AssemblyModesAnswer ans = answer(queries::run_assembly_modes(a, o));
  return {queries::to_json(ans).dump(), ans.certificate_text};
}

}  // namespace

void bind_assembly(py::module_& m) {
  py::class_<Assembly>(m, "Assembly")
      .def_static("load", [](const std::string& path) { return queries::load_assembly(path); })
      .def_static("parse", &queries::parse_assembly, py::arg("text"), py::arg("name"))
      .def_readonly("name", &Assembly::name)
      .def_readonly("text", &Assembly::text)
      .def_property_readonly("bodies", [](const Assembly& a) { return a.assembly.bodies.size(); })
      .def_property_readonly("contacts", [](const Assembly& a) { return a.assembly.contacts.size(); })
      .def("stability", &stability, Release())
      .def("ucp", &ucp, Release())
      .def("modes", &modes, Release())
      .def(
          "svg", [](const Assembly& a) { return queries::assembly_svg(a.assembly, {}, a.name); }, Release());
}

}  // namespace contactcert::python
