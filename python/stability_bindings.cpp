// Scene.stability, the Oracle of many verdicts, Scene.region and Scene.finger (and their pictures).
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

std::string region(const Scene& s) { return cli::region_json(solvers::stable_region<Q>(s.scene)).dump(); }
std::string region_svg(const Scene& s) { return cli::stability_sphere_svg(solvers::stable_region<Q>(s.scene)); }

std::string finger(const Scene& s) {
  return cli::finger_json(solvers::finger_pushes<Q>(s.scene, solvers::stable_region<Q>(s.scene))).dump();
}
std::string finger_svg(const Scene& s) {
  return cli::finger_svg(s.scene, solvers::finger_pushes<Q>(s.scene, solvers::stable_region<Q>(s.scene)));
}

}  // namespace

void bind_stability(py::module_& m, py::class_<Scene>& scene) {
  scene.def("stability", &stability, Release())
      .def("region", &region, Release())
      .def("region_svg", &region_svg, Release())
      .def("finger", &finger, Release())
      .def("finger_svg", &finger_svg, Release());
  py::class_<Oracle>(m, "Oracle")
      .def(py::init<const Scene&, std::string>(), Release())
      .def("verdicts", &Oracle::verdicts, Release());
}

}  // namespace contactcert::python
