#include "queries/stability_query.h"

#include <cmath>

#include "exact/input_error.h"
#include "queries/contact_forces.h"
#include "queries/stability_certificate_file.h"
#include "solvers/stability/stable_region.h"

namespace contactcert::queries {
namespace {

using exact::Q;
using solvers::StabilityResult;

/// The moving witness: its mode, contact forces and acceleration (exact with their float view, or doubles).
template <class T>
json moving_json(const solvers::MotionWitness<T>& w) {
  json j;
  j["mode"] = w.mode.text();
  if constexpr (std::is_same_v<T, Q>) {
    j["forces"] = exact_json(w.forces);
    j["acceleration"] = exact_json(w.acceleration);
    j["acceleration_approx"] = approx_json(w.acceleration);
  } else {
    j["forces_approx"] = approx_json(w.forces);
    j["acceleration_approx"] = approx_json(w.acceleration);
  }
  return j;
}

template <class T>
json result_json(const StabilityAnswer& a, const StabilityResult<T>& r) {
  json j;
  j["verdict"] = solvers::verdict_name(r.verdict);
  j["wrench"] = exact_json(a.wrench);
  j["arith"] = exact::arith_name(a.arith);
  json touching = json::array();
  for (auto i : r.touching) touching.push_back(i);
  j["touching_fixels"] = touching;
  json w;
  auto contacts = [&](const exact::Vec<T>& c) {
    return a.frames ? contacts_json(*a.frames, r.touching, c) : contacts_json(a.scene, r.touching, c);
  };
  if (r.has_resting) {
    w["resting_forces"] = vector_json(r.resting_forces);
    w["resting_contacts"] = contacts(r.resting_forces);
  }
  if (r.has_moving) {
    w["moving"] = moving_json(r.moving);
    w["moving"]["contacts"] = contacts(r.moving.forces);
  }
  j["witness"] = w;
  put_search_counts(j, r);
  if (!a.certificate.empty()) j["certificate"] = a.certificate;
  if (a.margin && !a.margin->nearest.empty())
    j["margin"] = {{"squared_radius", exact_json(a.margin->squared_radius)},
                   {"radius_approx", std::sqrt(a.margin->squared_radius.get_d())},
                   {"nearest", a.margin->nearest}};
  return j;
}

}  // namespace

solvers::StabilityOptions stability_options(exact::Arith arith, const exact::Deadline& deadline) {
  solvers::StabilityOptions s;
  s.arith = scene_arith(arith);
  s.deadline = deadline;
  return s;
}

namespace {

StabilityAnswer stability_answer(const SceneInput& input, const StabilityQueryOptions& options) {
  const exact::Arith arith = scene_arith(options.common.arith);
  const exact::Vec<Q>& g = options.wrench;
  const exact::Deadline deadline = options.common.deadline();
  StabilityAnswer a{input.scene, g, arith, StabilityResult<Q>{}, std::nullopt, "", "", nullptr};
  if (arith == exact::Arith::kFloat) {
    if (!options.certificate.empty())
      throw exact::InputError("command line", "--certificate", "certificates need --arith exact or verified");
    if (options.margin)
      throw exact::InputError("command line", "--margin", "the margin is computed exactly (use exact or verified)");
    a.outcome = solvers::strong_stability<double>(input.scene, exact::to_double(g), stability_options(arith, deadline));
    return a;
  }
  const auto& r = a.outcome.emplace<StabilityResult<Q>>(
      solvers::strong_stability<Q>(input.scene, g, stability_options(arith, deadline)));
  if (!options.certificate.empty()) {
    a.certificate_text = stability_certificate_file(input.text, input.scene, g, r);
    write_certificate_file("stability", options.certificate, a.certificate_text,
                           std::string("the verdict is ") + solvers::verdict_name(r.verdict));
    a.certificate = options.certificate;
  }
  if (options.margin && r.verdict == solvers::StabilityVerdict::kStronglyStable) {
    solvers::ModeTreeOptions tree;  // the region's mode tree: its default arithmetic and budget, the run's deadline
    tree.deadline = deadline;
    a.margin = solvers::stability_margin<Q>(solvers::stable_region<Q>(input.scene, solvers::Route::kPaper, tree), g);
  }
  return a;
}

}  // namespace

Limited<StabilityAnswer> run_stability(const SceneInput& input, const StabilityQueryOptions& options) {
  return with_limits(options.common.arith, [&] { return stability_answer(input, options); });
}

json to_json(const StabilityAnswer& answer) {
  return std::visit([&](const auto& r) { return result_json(answer, r); }, answer.outcome);
}

}  // namespace contactcert::queries
