// demo (both papers' worked examples) and bench (speed against error on the hard-case families): each returns the
// --json text and the readable report the CLI prints.
#include <pybind11/stl.h>

#include <string>
#include <utility>

#include "python/bindings.h"
#include "queries/bench_query.h"
#include "queries/demo_query.h"

namespace contactcert::python {

void bind_demo_bench(py::module_& m) {
  m.def(
      "demo",
      [](const std::string& scenes, const std::string& out, double time_limit) {
        const queries::DemoAnswer a = answer(queries::run_demo({scenes, out, time_limit}));
        return std::make_pair(queries::to_json(a).dump(), queries::demo_text(a));
      },
      Release());
  m.def(
      "bench",
      [](const std::string& suite, bool quick, const std::string& rungs, const std::string& out, double time_limit) {
        queries::BenchOptions o;
        o.family = queries::parse_bench_suite(suite, "--suite");
        o.quick = quick;
        o.rungs = queries::parse_bench_rungs(rungs, "--rungs");
        o.out = out;
        o.time_limit = time_limit;
        const queries::BenchAnswer a = answer(queries::run_bench(o));
        return std::make_pair(queries::to_json(a).dump(), queries::to_text(a));
      },
      Release());
}

}  // namespace contactcert::python
