// Scene.cone, Scene.modes and Scene.insertion (and their pictures).
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "cli/option_checks.h"
#include "cli/results.h"
#include "exact/arith.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "python/bindings.h"
#include "queries/json_out.h"
#include "queries/stability_svg.h"

namespace contactcert::python {
namespace {

using exact::Q;

solvers::Route parse_route(const std::string& route) {
  return route == "project" ? solvers::Route::kProject : solvers::Route::kPaper;
}

std::string cone(const Scene& s, const std::string& mode_text, const std::string& route, const std::string& arith) {
  const solvers::ModeString mode = cli::cone_mode(s.scene, s.name, mode_text);
  if (arith == "float")
    return cli::cone_json(mode, solvers::wrench_cone<double>(s.scene, mode, parse_route(route)), route).dump();
  return cli::cone_json(s.scene, mode, solvers::wrench_cone<Q>(s.scene, mode, parse_route(route)), route, arith).dump();
}

std::string cone_svg(const Scene& s, const std::string& mode_text, const std::string& route) {
  const solvers::ModeString mode = cli::cone_mode(s.scene, s.name, mode_text);
  return cli::cone_svg(s.scene, mode, solvers::wrench_cone<Q>(s.scene, mode, parse_route(route)));
}

std::string modes(const Scene& s, bool kinematic, const std::string& table2, bool unions, const std::string& arith,
                  const std::string& certificate) {
  const solvers::ContactModes m = cli::modes_of(s.scene, arith, table2, unions, 1L << 22, 0);
  if (!certificate.empty()) cli::write_text_file(certificate, solvers::modes_certificate(s.text, m));
  return cli::modes_json(m, kinematic, certificate).dump();
}

/// `insert FILE [--sweep-mu a,b,...]`.
std::string insertion(const Scene& s, const std::string& sweep_mu) {
  const std::vector<Q> mus = cli::sweep_mus(sweep_mu);
  const auto ins = cli::insertion_of(s.scene, s.name);
  cli::json j = cli::insertion_json(s.scene, ins, solvers::insertion_pushes<Q>(s.scene, ins));
  if (!mus.empty()) {
    cli::json sweep = cli::json::array();
    for (const Q& mu : mus) sweep.push_back(cli::sweep_entry_json(s.scene, mu));
    j["sweep"] = sweep;
  }
  return j.dump();
}
std::string insertion_svg(const Scene& s) {
  return cli::insertion_svg(s.scene, solvers::insertion_pushes<Q>(s.scene, cli::insertion_of(s.scene, s.name)));
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
