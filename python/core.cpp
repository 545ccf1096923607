// contactcert._core: the extension under the Python package python/contactcert. Each call runs the query the
// matching subcommand runs (queries/) and returns the JSON text that `--json` prints; the package wraps it in
// small result classes (the bindings of each family of queries: python/bindings.h). The work runs with the GIL
// released; InputError becomes ValueError with the CLI's message, a query's limit (python::answer) becomes
// contactcert.BudgetExceeded with the CLI's message: "budget exceeded: WHAT (covered: ...)".
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/snap.h"
#include "python/bindings.h"
#include "queries/options.h"
#include "queries/scene_input.h"
#include "runtime/memory.h"

namespace py = pybind11;
using namespace contactcert;
using python::Release;
using python::Scene;

PYBIND11_MODULE(_core, m) {
  m.doc() = "contactcert's C++ engine (use the package contactcert)";
  m.attr("__version__") = CONTACTCERT_VERSION;  // the project version (python/CMakeLists.txt)
  // GMP's block allocator of the CLI (runtime/memory.h), unless another library has replaced GMP's functions: modes
  // on 32 fixels in 0.69x the time. Not the CLI's heap policy: it would keep the interpreter's heap until exit, and
  // gains nothing measurable on these queries.
  m.attr("pooled_gmp_memory") = runtime::use_pooled_gmp_memory_if_default();
  static py::exception<python::LimitReached> budget(m, "BudgetExceeded", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const exact::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const python::LimitReached& e) {
      const queries::Limit& l = e.limit;
      budget((l.kind == queries::Limit::Kind::kUndecided
                  ? "undecided in floating point: " + l.what + "; rerun with arith=\"verified\" for an exact answer"
                  : "budget exceeded: " + l.text())
                 .c_str());
    }
  });

  py::class_<Scene> scene(m, "Scene");
  scene.def_static("load", [](const std::string& path) { return queries::load_scene(path); })
      .def_static(
          "parse", [](const std::string& text, const std::string& name) { return queries::parse_scene(text, name); },
          py::arg("text"), py::arg("name"))
      .def_readonly("name", &Scene::name)
      .def_readonly("text", &Scene::text)
      .def_property_readonly("fixels", [](const Scene& s) { return s.scene.fixels.size(); });
  python::bind_stability(m, scene);
  python::bind_scene_queries(scene);
  python::bind_ucp(m);
  python::bind_design(m);
  python::bind_simulate(m);
  python::bind_assembly(m);
  python::bind_spatial(m);
  python::bind_demo_bench(m);
  // geometry::snap_planar_scene: the snapped text and the snaps as (field, original, snapped, distance^2) texts.
  m.def(
      "snap_scene",
      [](const std::string& text, const std::string& name, const std::string& tol_text) {
        const geometry::SnappedScene s =
            geometry::snap_planar_scene(text, name, queries::parse_snap_tolerance(tol_text, name, "snap"));
        std::vector<std::tuple<std::string, std::string, std::string, std::string>> snaps;
        for (const geometry::Snap& x : s.snaps)
          snaps.emplace_back(x.field, x.original, x.snapped, exact::to_string(x.distance_squared));
        return std::make_pair(s.text, snaps);
      },
      Release());
  // A file's text through the CLI's reader: its size limit, and no blocking on a pipe without a writer.
  m.def("read_text", &exact::JsonInput::read_text, Release());
  m.attr("MAX_TIME_LIMIT") = queries::kMaxTimeLimit;
}
