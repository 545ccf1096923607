// design (fixture design on a scene, serial in-process) and convert (a cone's other form).
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "exact/input_error.h"
#include "python/bindings.h"
#include "queries/convert_query.h"
#include "queries/design_query.h"

namespace contactcert::python {
namespace {

/// `design SCENE ... --json` on one process: the --json text; a budget raises BudgetExceeded with what was
/// covered, a refused checkpoint ValueError naming the file and field.
std::string design(const Scene& s, const queries::DesignOptions& o) {
  const queries::DesignRun run = answer(queries::run_design(s, o, *solvers::serial_distributor()));
  if (run.status == queries::DesignStatus::kRefused) throw py::value_error(run.refusal);
  return queries::to_json(*run.report).dump();
}

}  // namespace

void bind_design(py::module_& m) {
  // queries::DesignOptions itself; the texts of rank and arith are parsed by the query layer as the CLI's are.
  using Options = queries::DesignOptions;
  py::class_<Options>(m, "DesignOptions")
      .def(py::init<>())
      .def_readwrite("candidates", &Options::candidates)
      .def_readwrite("lattice", &Options::lattice)
      .def_readwrite("fixels", &Options::fixels)
      .def_readwrite("stable_under", &Options::stable_under)
      .def_readwrite("insertable", &Options::insertable)
      .def_readwrite("goal_push", &Options::goal_push)
      .def_readwrite("goal_wrench", &Options::goal_wrench)
      .def_property(
          "rank",
          [](const Options& o) {
            return o.rank ? std::optional<std::string>(solvers::rank_name(*o.rank)) : std::nullopt;
          },
          [](Options& o, const std::optional<std::string>& text) {
            o.rank = text ? std::optional(queries::parse_rank(*text, "rank")) : std::nullopt;
          })
      .def_readwrite("top", &Options::top)
      .def_readwrite("out", &Options::out)
      .def_readwrite("checkpoint", &Options::checkpoint)
      .def_readwrite("chunk_size", &Options::chunk_size)
      .def_readwrite("push_points", &Options::push_points)
      .def_readwrite("max_placements", &Options::max_placements)
      .def_property(
          "arith", [](const Options& o) { return std::string(exact::arith_name(o.common.arith)); },
          [](Options& o, const std::string& text) { o.common.arith = queries::parse_arith(text, "arith"); })
      .def_property(
          "time_limit", [](const Options& o) { return o.common.time_limit; },
          [](Options& o, double seconds) { o.common.time_limit = seconds; });
  m.def("design", &design, Release());
  m.def(
      "convert",
      [](const std::string& text, const std::string& name, const std::string& arith, double time_limit) {
        return queries::to_json(answer(queries::run_convert(exact::JsonInput::parse(text, name),
                                                            {{queries::parse_arith(arith, "arith"), time_limit}})))
            .dump();
      },
      Release());
}

}  // namespace contactcert::python
