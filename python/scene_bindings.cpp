// Scene.cone, Scene.modes and Scene.insertion (and their pictures): the queries of `cone`, `modes` and `insert`
// (queries/cone_query.h, modes_query.h, insert_query.h), their option texts parsed as the CLI parses them.
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "python/bindings.h"
#include "queries/cone_query.h"
#include "queries/insert_query.h"
#include "queries/modes_query.h"

namespace contactcert::python {
namespace {

queries::ConeOptions cone_options(const std::string& mode, const std::string& route, const std::string& table2) {
  queries::ConeOptions o;
  o.mode = mode;
  o.route = queries::parse_route(route, "--route");
  o.table2 = queries::parse_table2(table2, "--table2");
  return o;
}

/// `cone FILE --mode MODE --route R --arith A --table2 T [--certificate F] [--time-limit S]`.
WithCertificate cone(const Scene& s, const std::string& mode, const std::string& route, const std::string& arith,
                     const std::string& table2, const std::string& certificate, double time_limit) {
  queries::ConeOptions o = cone_options(mode, route, table2);
  o.common = {queries::parse_arith(arith, "--arith"), time_limit};
  o.certificate = certificate;
  const queries::ConeAnswer a = answer(queries::run_cone(s, o));
  return {queries::to_json(a).dump(), a.certificate_text};
}

std::string cone_svg(const Scene& s, const std::string& mode, const std::string& route, const std::string& table2) {
  return queries::cone_svg(answer(queries::run_cone(s, cone_options(mode, route, table2))));
}

/// `modes FILE` with its options (a budget not given: the CLI's default).
WithCertificate modes(const Scene& s, bool kinematic, const std::string& table2, bool unions, const std::string& arith,
                      const std::string& certificate, std::optional<long> max_nodes, std::optional<long> max_modes,
                      double time_limit) {
  queries::ModesOptions o;
  o.common = {queries::parse_arith(arith, "--arith"), time_limit};
  o.kinematic = kinematic;
  o.unions = unions;
  o.table2 = queries::parse_table2(table2, "--table2");
  o.max_nodes = max_nodes.value_or(o.max_nodes);
  o.max_modes = max_modes.value_or(o.max_modes);
  o.certificate = certificate;
  const queries::ModesAnswer a = answer(queries::run_modes(s, o));
  return {queries::to_json(a).dump(), a.certificate_text};
}

queries::InsertOptions insert_options(const std::string& sweep_mu, const std::string& arith, double time_limit) {
  queries::InsertOptions o;
  o.common = {queries::parse_arith(arith, "--arith"), time_limit};
  o.sweep_mu = queries::parse_sweep_mu(sweep_mu);
  return o;
}

/// `insert FILE [--sweep-mu a,b,...] [--arith A] [--time-limit S]`.
std::string insertion(const Scene& s, const std::string& sweep_mu, const std::string& arith, double time_limit) {
  return queries::to_json(answer(queries::run_insert(s, insert_options(sweep_mu, arith, time_limit)))).dump();
}

std::string insertion_svg(const Scene& s) {
  const queries::InsertAnswer a = answer(queries::run_insert(s, insert_options("", "verified", 0)));
  return queries::insertion_svg(a.scene, a.pushes);
}

}  // namespace

void bind_scene_queries(py::class_<Scene>& scene) {
  scene.def("cone", &cone, Release())
      .def("cone_svg", &cone_svg, Release())
      .def("modes", &modes, Release())
      .def("insertion", &insertion, Release())
      .def("insertion_svg", &insertion_svg, Release());
}

}  // namespace contactcert::python
