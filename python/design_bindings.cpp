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

/// The options of `design` as Python passes them (texts parsed here by the query layer, as the CLI does).
struct DesignArgs {
  std::string candidates, lattice;
  int fixels = 3;
  std::optional<std::string> stable_under;
  bool insertable = false, goal_push = false;
  std::string goal_wrench, rank;
  int top = 5;
  std::string out, checkpoint;
  long chunk_size = 16, push_points = 120, max_placements = 100000000;
  std::string arith = "verified";
  double time_limit = 0;
};

/// `design SCENE ... --json` on one process: the --json text; a budget raises BudgetExceeded with what was
/// covered, a refused checkpoint ValueError naming the file and field.
std::string design(const Scene& s, const DesignArgs& a) {
  queries::DesignOptions o;
  o.common = {queries::parse_arith(a.arith, "arith"), a.time_limit};
  o.candidates = a.candidates;
  o.lattice = a.lattice;
  o.fixels = a.fixels;
  o.stable_under = a.stable_under;
  o.insertable = a.insertable;
  o.goal_push = a.goal_push;
  o.goal_wrench = a.goal_wrench;
  if (!a.rank.empty()) o.rank = queries::parse_rank(a.rank, "rank");
  o.top = a.top;
  o.out = a.out;
  o.checkpoint = a.checkpoint;
  o.chunk_size = a.chunk_size;
  o.push_points = a.push_points;
  o.max_placements = a.max_placements;
  const queries::DesignRun run = answer(queries::run_design(s, o, *solvers::serial_distributor()));
  if (run.status == queries::DesignStatus::kRefused) throw py::value_error(run.refusal);
  return queries::to_json(*run.report).dump();
}

}  // namespace

void bind_design(py::module_& m) {
  py::class_<DesignArgs>(m, "DesignArgs")
      .def(py::init<>())
      .def_readwrite("candidates", &DesignArgs::candidates)
      .def_readwrite("lattice", &DesignArgs::lattice)
      .def_readwrite("fixels", &DesignArgs::fixels)
      .def_readwrite("stable_under", &DesignArgs::stable_under)
      .def_readwrite("insertable", &DesignArgs::insertable)
      .def_readwrite("goal_push", &DesignArgs::goal_push)
      .def_readwrite("goal_wrench", &DesignArgs::goal_wrench)
      .def_readwrite("rank", &DesignArgs::rank)
      .def_readwrite("top", &DesignArgs::top)
      .def_readwrite("out", &DesignArgs::out)
      .def_readwrite("checkpoint", &DesignArgs::checkpoint)
      .def_readwrite("chunk_size", &DesignArgs::chunk_size)
      .def_readwrite("push_points", &DesignArgs::push_points)
      .def_readwrite("max_placements", &DesignArgs::max_placements)
      .def_readwrite("arith", &DesignArgs::arith)
      .def_readwrite("time_limit", &DesignArgs::time_limit);
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
