// The class Motion (a motion scene, docs/motion.md) whose start gives a run in progress (the class Run: one step at a
// time, or finished), whose answer (the class Simulation) gives the trajectory's JSON (what `contactcert simulate
// --json` prints) and its animated picture.
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>

#include "exact/json_input.h"
#include "python/bindings.h"
#include "queries/simulate_query.h"
#include "queries/trajectory_svg.h"

namespace contactcert::python {
namespace {

/// `simulate FILE` with its options, started: steps and budgets not given take the scene's and the query's defaults,
/// dt "" the scene's; `certificates` (a folder) and `svg` (a file) are written if not empty.
std::unique_ptr<queries::SimulateRun> start(const queries::MotionInput& input, std::optional<long> steps,
                                            const std::string& dt, const std::string& arith, bool compare,
                                            bool uniqueness, std::optional<long> max_nodes,
                                            std::optional<long> max_modes, double time_limit,
                                            const std::string& certificates, const std::string& svg) {
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
  return answer(queries::with_limits(o.common.arith, [&] { return std::make_unique<queries::SimulateRun>(input, o); }));
}

}  // namespace

void bind_simulate(py::module_& m) {
  // Simulation and Run first: the signatures of Run.finish and Motion.start name them.
  py::class_<queries::SimulateAnswer>(m, "Simulation")
      .def("json", [](const queries::SimulateAnswer& a) { return exact::json_text(queries::to_json(a)); })
      .def("svg", &queries::trajectory_svg, Release());
  py::class_<queries::SimulateRun>(m, "Run")
      .def("next",
           [](queries::SimulateRun& r) -> std::optional<std::string> {
             std::optional<queries::json> step;
             {
               const py::gil_scoped_release release;
               step = answer(queries::with_limits(r.options().common.arith, [&] { return r.next(); }));
             }
             if (!step) return std::nullopt;
             return exact::json_text(*step);
           })
      .def(
          "finish",
          [](queries::SimulateRun& r) {
            return answer(queries::with_limits(r.options().common.arith, [&] { return r.finish(); }));
          },
          Release());
  py::class_<queries::MotionInput>(m, "Motion")
      .def_static("load", &queries::load_motion)
      .def_static("parse", &queries::parse_motion, py::arg("text"), py::arg("name"))
      .def_readonly("name", &queries::MotionInput::name)
      .def_readonly("text", &queries::MotionInput::text)
      .def("start", &start, Release());
}

}  // namespace contactcert::python
