// The class SpatialScene (a body in space, docs/formats.md section 3b): its contact modes from rest and its strong
// stability under a wrench through the query layer (queries/spatial_modes_query.h, spatial_stability_query.h), as
// `contactcert modes SPATIAL` and `stability SPATIAL --wrench ...` run them.
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "python/bindings.h"
#include "queries/spatial_cone_query.h"
#include "queries/spatial_modes_query.h"
#include "queries/spatial_stability_query.h"

namespace contactcert::python {
namespace {

using Spatial = queries::SpatialInput;

/// `modes SPATIAL [--max-nodes N] [--max-modes N] [--certificate F] [--svg F]`: the --json text and the
/// certificate's.
WithCertificate modes(const Spatial& s, const std::string& arith, double time_limit, std::optional<long> max_nodes,
                      std::optional<long> max_modes, const std::string& certificate, const std::string& svg) {
  queries::SpatialModesOptions o;
  o.common = {queries::parse_arith(arith, "--arith"), time_limit};
  o.max_nodes = max_nodes.value_or(o.max_nodes);
  o.max_modes = max_modes.value_or(o.max_modes);
  o.certificate = certificate;
  o.svg = svg;
  const queries::SpatialModesAnswer ans = answer(queries::run_spatial_modes(s, o));
  return {queries::to_json(ans).dump(), ans.certificate_text};
}

/// `stability SPATIAL --wrench fx,fy,fz,tx,ty,tz [--certificate F]`: the --json text and the certificate's.
WithCertificate stability(const Spatial& s, const std::string& wrench, const std::string& arith, double time_limit,
                          const std::string& certificate) {
  queries::SpatialStabilityOptions o;
  o.common = {queries::parse_arith(arith, "--arith"), time_limit};
  o.wrench = queries::parse_number_list(wrench, "--wrench", 6);
  o.certificate = certificate;
  const queries::SpatialStabilityAnswer ans = answer(queries::run_spatial_stability(s, o));
  return {queries::to_json(ans).dump(), ans.certificate_text};
}

/// `cone SPATIAL --mode M [--certificate F]`: the --json text and the certificate's.
WithCertificate cone(const Spatial& s, const std::string& mode, const std::string& arith, double time_limit,
                     const std::string& certificate) {
  const queries::SpatialConeAnswer ans =
      answer(queries::run_spatial_cone(s, {{queries::parse_arith(arith, "--arith"), time_limit}, mode, certificate}));
  return {queries::to_json(ans).dump(), ans.certificate_text};
}

}  // namespace

void bind_spatial(py::module_& m) {
  py::class_<Spatial>(m, "SpatialScene")
      .def_static(
          "load",
          [](const std::string& path) { return queries::parse_spatial(exact::JsonInput::read_text(path), path); })
      .def_static("parse", &queries::parse_spatial, py::arg("text"), py::arg("name"))
      .def_readonly("name", &Spatial::name)
      .def_readonly("text", &Spatial::text)
      .def_property_readonly("contacts", [](const Spatial& s) { return s.scene.contacts.size(); })
      .def("modes", &modes, py::arg("arith"), py::arg("time_limit"), py::arg("max_nodes"), py::arg("max_modes"),
           py::arg("certificate"), py::arg("svg") = "", Release())
      .def("stability", &stability, Release())
      .def("cone", &cone, Release());
}

}  // namespace contactcert::python
