// Scene.stability, the Oracle of many verdicts, Scene.region and Scene.finger (and their pictures): the queries of
// `contactcert stability` (queries/stability_query.h, wrenches_query.h, region_query.h, finger_query.h), with their
// options parsed from Python's strings by the same functions as the CLI's.
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "python/bindings.h"
#include "python/stability_objects.h"
#include "queries/finger_query.h"
#include "queries/json_out.h"
#include "queries/region_query.h"
#include "queries/stability_query.h"
#include "queries/wrenches_query.h"

namespace contactcert::python {
namespace {

using exact::Q;

queries::CommonOptions common(const std::string& arith, double time_limit) {
  return {queries::parse_arith(arith, "--arith"), time_limit};
}

/// `stability --wrench`: its JSON and the certificate's text ("" if none); `certificate`: the file to write, or "".
WithCertificate stability(const Scene& s, const std::string& wrench, const std::string& arith, bool margin,
                          const std::string& certificate, double time_limit) {
  const auto a = answer(queries::run_stability(
      s, {common(arith, time_limit), queries::parse_number_list(wrench, "--wrench", 3), margin, certificate}));
  return {queries::to_json(a).dump(), a.certificate_text};
}

/// The verdicts of one batch, with the oracle that answers for them (the scene and arithmetic of their objects).
struct Batch {
  std::shared_ptr<const queries::StabilityVerdicts> oracle;
  std::vector<exact::Vec<Q>> wrenches;
  std::vector<queries::StabilityOutcome> verdicts;
};

/// One verdict of a batch: its `stability --wrench` JSON object, built (as json.loads would build it from the text,
/// stability_object) only when Python first reads more than the verdict.
class Verdict {
 public:
  Verdict(std::shared_ptr<const Batch> batch, std::size_t i) : batch_(std::move(batch)), i_(i) {}
  py::object object() const { return stability_object(*batch_->oracle, batch_->wrenches[i_], batch_->verdicts[i_]); }

 private:
  std::shared_ptr<const Batch> batch_;
  std::size_t i_;
};

/// Many verdicts on one scene from one prepared oracle (`stability --wrenches`): per wrench its verdict's name and
/// its Verdict.
class Oracle {
 public:
  Oracle(const Scene& s, const std::string& arith, double time_limit)
      : common_(common(arith, time_limit)),
        verdicts_(std::make_shared<const queries::StabilityVerdicts>(answer(
            queries::with_limits(common_.arith, [&] { return queries::StabilityVerdicts(s.scene, common_); })))) {}
  std::vector<std::pair<std::string, Verdict>> verdicts(const std::vector<std::string>& wrenches) const {
    auto batch = std::make_shared<Batch>();
    batch->oracle = verdicts_;
    {
      const py::gil_scoped_release release;
      answer(queries::with_limits(common_.arith, [&] {
        batch->wrenches.reserve(wrenches.size());
        for (std::size_t i = 0; i < wrenches.size(); ++i)
          batch->wrenches.push_back(queries::parse_number_list(wrenches[i], "wrenches[" + std::to_string(i) + "]", 3));
        batch->verdicts = verdicts_->verdicts(batch->wrenches);
        for (auto& v : batch->verdicts)  // the JSON object shows no proof: only the batch's memory would hold them
          std::visit([](auto& r) { r.proofs.clear(); }, v);
        return true;
      }));
    }
    std::vector<std::pair<std::string, Verdict>> out;
    out.reserve(batch->verdicts.size());
    for (std::size_t i = 0; i < batch->verdicts.size(); ++i)
      out.emplace_back(std::visit([](const auto& r) { return solvers::verdict_name(r.verdict); }, batch->verdicts[i]),
                       Verdict(batch, i));
    return out;
  }

 private:
  queries::CommonOptions common_;
  std::shared_ptr<const queries::StabilityVerdicts> verdicts_;
};

/// `stability --region [--wrench g]` ("" = no g), always exact.
queries::RegionAnswer region_answer(const Scene& s, const std::string& wrench, double time_limit) {
  queries::RegionOptions o{{.time_limit = time_limit}, std::nullopt, ""};
  if (!wrench.empty()) o.wrench = queries::parse_number_list(wrench, "--wrench", 3);
  return answer(queries::run_region(s, o));
}
std::string region(const Scene& s, const std::string& wrench, double time_limit) {
  return queries::to_json(region_answer(s, wrench, time_limit)).dump();
}
std::string region_svg(const Scene& s, const std::string& wrench, double time_limit) {
  return queries::region_svg(region_answer(s, wrench, time_limit));
}

/// `stability --finger`, always exact.
queries::FingerAnswer finger_answer(const Scene& s, double time_limit) {
  return answer(queries::run_finger(s, {{.time_limit = time_limit}, ""}));
}
std::string finger(const Scene& s, double time_limit) { return queries::to_json(finger_answer(s, time_limit)).dump(); }
std::string finger_svg(const Scene& s, double time_limit) { return queries::finger_svg(finger_answer(s, time_limit)); }

}  // namespace

void bind_stability(py::module_& m, py::class_<Scene>& scene) {
  scene.def("stability", &stability, Release())
      .def("region", &region, Release())
      .def("region_svg", &region_svg, Release())
      .def("finger", &finger, Release())
      .def("finger_svg", &finger_svg, Release());
  py::class_<Verdict>(m, "Verdict").def("object", &Verdict::object);
  py::class_<Oracle>(m, "Oracle")
      .def(py::init<const Scene&, const std::string&, double>(), Release())
      .def("verdicts", &Oracle::verdicts);  // the verdicts without the GIL, their objects with it
}

}  // namespace contactcert::python
