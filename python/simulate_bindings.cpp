// The class Motion (a motion scene, docs/motion.md) with simulate, whose answer (the class Simulation) gives the
// trajectory's JSON (what `contactcert simulate --json` prints) and its animated picture.
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "exact/json_input.h"
#include "python/bindings.h"
#include "queries/simulate_query.h"
#include "queries/trajectory_svg.h"

namespace contactcert::python {
namespace {

/// `simulate FILE` with its options: steps and budgets not given take the scene's and the query's defaults, dt ""
/// the scene's; `certificates` (a folder) and `svg` (a file) are written if not empty.
queries::SimulateAnswer simulate(const queries::MotionInput& input, std::optional<long> steps, const std::string& dt,
                                 const std::string& arith, bool compare, bool uniqueness, std::optional<long> max_nodes,
                                 std::optional<long> max_modes, double time_limit, const std::string& certificates,
                                 const std::string& svg) {
  queries::SimulateOptions o;
  o.common = {queries::parse_arith(arith, "--arith"), time_limit};
  o.steps = steps;
  if (!dt.empty()) o.dt = queries::parse_dt(dt, "--dt");
  o.compare = compare;
  o.uniqueness = uniqueness;
  o.max_nodes = max_nodes.value_or(o.max_nodes);
  o.max_modes = max_modes.value_or(o.max_modes);
  o.certificates = certificates;
  o.svg = svg;
  return queries::run_simulate(input, o);
}

}  // namespace

void bind_simulate(py::module_& m) {
  // Simulation first: Motion.simulate's signature names it.
  py::class_<queries::SimulateAnswer>(m, "Simulation")
      .def("json", [](const queries::SimulateAnswer& a) { return exact::json_text(queries::to_json(a)); })
      .def("svg", &queries::trajectory_svg, Release());
  py::class_<queries::MotionInput>(m, "Motion")
      .def_static("load", &queries::load_motion)
      .def_static("parse", &queries::parse_motion, py::arg("text"), py::arg("name"))
      .def_readonly("name", &queries::MotionInput::name)
      .def_readonly("text", &queries::MotionInput::text)
      .def("simulate", &simulate, Release());
}

}  // namespace contactcert::python
