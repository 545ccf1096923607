// contactcert._core: the extension under the Python package python/contactcert. Each call runs the code the
// matching subcommand runs (cli/results.h) and returns the JSON text that `--json` prints; the package wraps
// it in small result classes. The work runs with the GIL released; InputError becomes ValueError with the
// CLI's message, BudgetExceeded becomes contactcert.BudgetExceeded.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "cli/json_out.h"
#include "cli/option_checks.h"
#include "cli/results.h"
#include "cli/stability_svg.h"
#include "exact/arith.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "geometry/snap.h"
#include "runtime/memory.h"
#include "solvers/stability/stability_certificate.h"
#include "solvers/ucp/problem.h"

namespace py = pybind11;
using namespace contactcert;
using exact::Q;

namespace {

using Release = py::call_guard<py::gil_scoped_release>;
/// A result's JSON text and, where the CLI writes one, the certificate text (empty if none).
using WithCertificate = std::pair<std::string, std::string>;

/// A planar scene with its text (a stability certificate embeds it) and the name its messages use.
struct Scene {
  std::string name, text;
  geometry::PlanarScene scene;
};

Scene parse_scene(const std::string& text, const std::string& name) {
  return {name, text, geometry::read_planar_scene(exact::JsonInput::parse(text, name))};
}

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

/// `stability --wrench` (its adaptive runs as verified); `certificate`: the file to write, or empty.
WithCertificate stability(const Scene& s, const std::string& wrench, std::string arith, bool margin,
                          const std::string& certificate) {
  if (arith == "adaptive") arith = "verified";
  const exact::Vec<Q> g = cli::parse_number_list(wrench, "--wrench", 3);
  const exact::Arith a = exact::parse_arith(arith);
  if (a == exact::Arith::kFloat) {
    if (!certificate.empty())
      throw exact::InputError("command line", "--certificate", "certificates need --arith exact or verified");
    if (margin)
      throw exact::InputError("command line", "--margin", "the margin is computed exactly (use exact or verified)");
    return {cli::stability_json(s.scene, g, solvers::strong_stability<double>(s.scene, exact::to_double(g), {a}), arith,
                                "", std::nullopt)
                .dump(),
            ""};
  }
  const auto r = solvers::strong_stability<Q>(s.scene, g, {a});
  std::string text;
  if (!certificate.empty()) {
    text = cli::stability_certificate_file(s.text, s.scene, g, r);
    cli::write_text_file(certificate, text);
  }
  std::optional<solvers::Margin<Q>> m;
  if (margin && r.verdict == solvers::StabilityVerdict::kStronglyStable)
    m = solvers::stability_margin<Q>(solvers::stable_region<Q>(s.scene), g);
  return {cli::stability_json(s.scene, g, r, arith, certificate, m).dump(), text};
}

/// Many verdicts on one scene: a StabilityOracle prepared once (exact and verified in Q, float in double).
class Oracle {
 public:
  Oracle(const Scene& s, std::string arith)
      : scene_(s.scene), arith_(arith == "adaptive" ? "verified" : std::move(arith)) {
    const exact::Arith a = exact::parse_arith(arith_);
    if (a == exact::Arith::kFloat)
      floating_.emplace(s.scene, solvers::StabilityOptions{a});
    else
      exact_.emplace(s.scene, solvers::StabilityOptions{a});
  }
  std::vector<std::string> verdicts(const std::vector<std::string>& wrenches) const {
    std::vector<std::string> out;
    out.reserve(wrenches.size());
    for (std::size_t i = 0; i < wrenches.size(); ++i) {
      const exact::Vec<Q> g = cli::parse_number_list(wrenches[i], "wrenches[" + std::to_string(i) + "]", 3);
      out.push_back(
          (floating_ ? cli::stability_json(scene_, g, floating_->verdict(exact::to_double(g)), arith_, "", std::nullopt)
                     : cli::stability_json(scene_, g, exact_->verdict(g), arith_, "", std::nullopt))
              .dump());
    }
    return out;
  }

 private:
  geometry::PlanarScene scene_;  ///< for the witnesses' world forces
  std::string arith_;
  std::optional<solvers::StabilityOracle<Q>> exact_;
  std::optional<solvers::StabilityOracle<double>> floating_;
};

std::string modes(const Scene& s, bool kinematic, const std::string& table2, bool unions, const std::string& arith,
                  const std::string& certificate) {
  const solvers::ContactModes m = cli::modes_of(s.scene, arith, table2, unions, 1L << 22, 0);
  if (!certificate.empty()) cli::write_text_file(certificate, solvers::modes_certificate(s.text, m));
  return cli::modes_json(m, kinematic, certificate).dump();
}

std::string region(const Scene& s) { return cli::region_json(solvers::stable_region<Q>(s.scene)).dump(); }
std::string region_svg(const Scene& s) { return cli::stability_sphere_svg(solvers::stable_region<Q>(s.scene)); }

std::string finger(const Scene& s) {
  return cli::finger_json(solvers::finger_pushes<Q>(s.scene, solvers::stable_region<Q>(s.scene))).dump();
}
std::string finger_svg(const Scene& s) {
  return cli::finger_svg(s.scene, solvers::finger_pushes<Q>(s.scene, solvers::stable_region<Q>(s.scene)));
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

/// A quasistatic (or plain UCP) problem file, with the name its messages use.
struct Ucp {
  std::string name;
  solvers::ucp::UcpProblem problem;
};

Ucp parse_ucp(const std::string& text, const std::string& name) {
  return {name, solvers::ucp::read_ucp_problem(exact::JsonInput::parse(text, name))};
}

/// `ucp FILE` with its options (a budget not given: the CLI's default); `certificate`: the file to write, or empty.
WithCertificate solve(const Ucp& u, const std::string& method, const std::string& arith, std::uint64_t seed,
                      std::optional<long> max_nodes, std::optional<long> max_bases, double time_limit,
                      const std::string& certificate) {
  cli::refuse_ignored_budgets(method, max_nodes.has_value(), max_bases.has_value());
  solvers::ucp::UcpOptions opts;
  opts.method = solvers::ucp::parse_method(method);
  opts.arith = exact::parse_arith(arith);
  opts.seed = seed;
  opts.max_nodes = max_nodes.value_or(opts.max_nodes);
  opts.max_bases = max_bases.value_or(opts.max_bases);
  opts.time_limit = time_limit;
  if (!certificate.empty() && opts.arith == exact::Arith::kFloat)
    throw exact::InputError("command line", "--certificate", "a certificate needs --arith exact or verified");
  const solvers::ucp::UcpReport r = solvers::ucp::solve_ucp(u.problem, opts);
  std::string text;
  if (!certificate.empty()) {
    text = solvers::ucp::certificate_text(u.problem, r);
    if (!text.empty()) cli::write_text_file(certificate, text);
  }
  return {cli::ucp_json(r, text.empty() ? "" : certificate).dump(), text};
}

/// `check FILE [--problem PROBLEM]` on texts; an empty `problem_text` means no --problem.
std::string check(const std::string& text, const std::string& name, const std::string& problem_text,
                  const std::string& problem_name) {
  const exact::JsonInput cert = exact::JsonInput::parse(text, name);
  if (problem_text.empty()) return cli::check_json(cert).dump();
  const exact::JsonInput problem = exact::JsonInput::parse(problem_text, problem_name);
  return cli::check_json(cert, &problem).dump();
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "contactcert's C++ engine (use the package contactcert)";
  m.attr("__version__") = CONTACTCERT_VERSION;  // the project version (python/CMakeLists.txt)
  // GMP's block allocator of the CLI (runtime/memory.h), unless another library has replaced GMP's functions: modes
  // on 32 fixels in 0.69x the time. Not the CLI's heap policy: it would keep the interpreter's heap until exit, and
  // gains nothing measurable on these queries.
  m.attr("pooled_gmp_memory") = runtime::use_pooled_gmp_memory_if_default();
  static py::exception<exact::BudgetExceeded> budget(m, "BudgetExceeded", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const exact::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const exact::BudgetExceeded& e) {
      budget(("budget exceeded: " + std::string(e.what()) + " (covered: " + e.covered + ")").c_str());
    }
  });

  py::class_<Scene>(m, "Scene")
      .def_static("load", [](const std::string& path) { return parse_scene(exact::JsonInput::read_text(path), path); })
      .def_static("parse", &parse_scene, py::arg("text"), py::arg("name"))
      .def_readonly("name", &Scene::name)
      .def_readonly("text", &Scene::text)
      .def_property_readonly("fixels", [](const Scene& s) { return s.scene.fixels.size(); })
      .def("cone", &cone, Release())
      .def("cone_svg", &cone_svg, Release())
      .def("stability", &stability, Release())
      .def("modes", &modes, Release())
      .def("region", &region, Release())
      .def("region_svg", &region_svg, Release())
      .def("finger", &finger, Release())
      .def("finger_svg", &finger_svg, Release())
      .def("insertion", &insertion, Release())
      .def("insertion_svg", &insertion_svg, Release());

  py::class_<Oracle>(m, "Oracle")
      .def(py::init<const Scene&, std::string>(), Release())
      .def("verdicts", &Oracle::verdicts, Release());

  py::class_<Ucp>(m, "Ucp")
      .def_static("load", [](const std::string& path) { return parse_ucp(exact::JsonInput::read_text(path), path); })
      .def_static("parse", &parse_ucp, py::arg("text"), py::arg("name"))
      .def_readonly("name", &Ucp::name)
      .def("text", [](const Ucp& u) { return solvers::ucp::to_json_text(u.problem); })
      .def("solve", &solve, Release());

  m.def(
      "generate",
      [](const std::string& kind, std::uint64_t seed, int nc, const std::string& mu_max, int abar, int rows, int cols,
         bool planted) {
        return Ucp{"generated", cli::generated_problem(kind, seed, nc, mu_max, abar, rows, cols, planted)};
      },
      Release());
  m.def("check", &check, Release());
  // geometry::snap_planar_scene: the snapped text and the snaps as (field, original, snapped, distance^2) texts.
  m.def(
      "snap_scene",
      [](const std::string& text, const std::string& name, const std::string& tol_text) {
        Q tol;
        if (!exact::parse_rational_into(tol_text, tol) || sgn(tol) <= 0)
          throw exact::InputError(name, "snap", "a tolerance > 0 such as 1e-9, got " + exact::quoted_excerpt(tol_text));
        const geometry::SnappedScene s = geometry::snap_planar_scene(text, name, tol);
        std::vector<std::tuple<std::string, std::string, std::string, std::string>> snaps;
        for (const geometry::Snap& x : s.snaps)
          snaps.emplace_back(x.field, x.original, x.snapped, exact::to_string(x.distance_squared));
        return std::make_pair(s.text, snaps);
      },
      Release());
  // A file's text through the CLI's reader: its size limit, and no blocking on a pipe without a writer.
  m.def("read_text", &exact::JsonInput::read_text, Release());
  m.attr("MAX_TIME_LIMIT") = cli::kMaxTimeLimit;
}
