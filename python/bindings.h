// The pieces of contactcert._core (python/core.cpp), one file per family of queries: each binds the query layer's
// functions (queries/) on the classes declared here and returns the JSON text that the CLI's --json prints.
#pragma once

#include <pybind11/pybind11.h>

#include <exception>
#include <string>
#include <utility>

#include "queries/limit.h"
#include "queries/scene_input.h"
#include "queries/ucp_query.h"

namespace contactcert::python {

namespace py = pybind11;

/// The work of a call runs with the GIL released.
using Release = py::call_guard<py::gil_scoped_release>;
/// A result's JSON text and, where the CLI writes one, the certificate text (empty if none).
using WithCertificate = std::pair<std::string, std::string>;

/// A query's limit on its way out of a call: core.cpp's translator raises it as contactcert.BudgetExceeded.
struct LimitReached : std::exception {
  explicit LimitReached(queries::Limit l) : limit(std::move(l)) {}
  const char* what() const noexcept override { return "a query's limit"; }
  queries::Limit limit;
};

/// The answer of a query, or (for its limit) LimitReached.
template <class A>
A answer(queries::Limited<A> limited) {
  if (!limited) throw LimitReached(limited.limit());
  return *std::move(limited);
}

/// A planar scene with its text (a stability certificate embeds it) and the name its messages use.
using Scene = queries::SceneInput;

/// A quasistatic (or plain UCP) problem with its text and the name its messages use.
using Ucp = queries::UcpInput;

/// Scene.stability, .region, .region_svg, .finger, .finger_svg and the class Oracle (stability_bindings.cpp).
void bind_stability(py::module_& m, py::class_<Scene>& scene);
/// Scene.cone, .cone_svg, .modes, .insertion, .insertion_svg (scene_bindings.cpp).
void bind_scene_queries(py::class_<Scene>& scene);
/// The class Ucp, generate and check (ucp_bindings.cpp).
void bind_ucp(py::module_& m);
/// design and convert (design_bindings.cpp).
void bind_design(py::module_& m);
/// The classes Motion (a motion scene, with simulate) and Simulation (its answer) (simulate_bindings.cpp).
void bind_simulate(py::module_& m);
/// The class Assembly: stability, ucp and svg (assembly_bindings.cpp).
void bind_assembly(py::module_& m);
void bind_spatial(py::module_& m);
/// demo and bench (bench_bindings.cpp).
void bind_demo_bench(py::module_& m);

}  // namespace contactcert::python
