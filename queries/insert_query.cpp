#include "queries/insert_query.h"

#include <algorithm>

#include "exact/input_error.h"
#include "queries/boundary_fraction.h"
#include "queries/boundary_marks.h"
#include "queries/cone_svg.h"

namespace contactcert::queries {
namespace {

using exact::Q;

json pieces_json(const solvers::BoundaryPieces<Q, bool>& p) {
  json edges = json::array(), arcs = json::array();
  for (const auto& e : p.edges)
    if (e.label)
      edges.push_back({{"edge", e.edge},
                       {"from", exact_json(e.from)},
                       {"to", exact_json(e.to)},
                       {"from_closed", e.from_closed},
                       {"to_closed", e.to_closed}});
  for (const auto& a : p.arcs)
    if (a.label)
      arcs.push_back({{"from_direction", primitive_json(a.from)},
                      {"to_direction", primitive_json(a.to)},
                      {"from_closed", a.from_closed},
                      {"to_closed", a.to_closed}});
  return {{"edges", edges}, {"arcs", arcs}};
}

/// The sweep's entry for mu: every fixel's mu_s = mu_k = mu.
SweepEntry sweep_entry(const geometry::PlanarScene& scene, const Q& mu) {
  geometry::PlanarScene s = scene;
  for (auto& f : s.fixels) f.mu_s = f.mu_k = mu;
  const auto ins = solvers::insertion<Q>(s);
  SweepEntry e{mu, solvers::insertion_pushes<Q>(s, ins), 0};
  e.boundary_fraction = boundary_fraction(s, e.pushes);
  return e;
}

}  // namespace

std::vector<Q> parse_sweep_mu(const std::string& text, const std::string& field) {
  std::vector<Q> mus;
  if (text.empty()) return mus;
  const exact::Vec<Q> v = parse_number_list(text, field, std::count(text.begin(), text.end(), ',') + 1);
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (sgn(v(i)) < 0) throw exact::InputError("command line", field, "friction coefficients must be >= 0");
    mus.push_back(v(i));
  }
  return mus;
}

solvers::Insertion<Q> insertion_of(const geometry::PlanarScene& scene, const std::string& file) {
  try {
    return solvers::insertion<Q>(scene);
  } catch (const exact::InputError& e) {  // the scene's fixels do not suit insertion: name the file
    throw exact::InputError(file, e.json_path, e.expected);
  }
}

namespace {

/// Stops between units of work (G_goal with its pushes, then each friction value of the sweep) once the time limit
/// has passed: the Limit names what was computed.
Limited<InsertAnswer> insert_answer(const SceneInput& input, const InsertOptions& options,
                                    const SweepProgress& progress) {
  refuse_float(options.common.arith, "insert is computed exactly (use exact or verified)");
  const exact::Deadline deadline = options.common.deadline();
  const auto stopped = [&](const std::string& covered) {
    return Limit{"insert " + input.name + ": " + deadline.reached_text(), covered, Limit::Kind::kStopped};
  };
  if (deadline.expired()) return stopped("nothing: G_goal not computed");
  InsertAnswer a{input.scene, insertion_of(input.scene, input.name), {}, 0, {}};
  a.pushes = solvers::insertion_pushes<Q>(a.scene, a.insertion);
  a.boundary_fraction = boundary_fraction(a.scene, a.pushes);
  for (const Q& mu : options.sweep_mu) {
    if (deadline.expired())
      return stopped("G_goal and its pushes, " + std::to_string(a.sweep.size()) + " of " +
                     std::to_string(options.sweep_mu.size()) + " friction values of the sweep");
    if (progress) progress(a.sweep.size(), options.sweep_mu.size(), mu);
    a.sweep.push_back(sweep_entry(a.scene, mu));
  }
  if (!options.svg.empty()) write_text_file(options.svg, insertion_svg(a.scene, a.pushes));
  return a;
}

}  // namespace

Limited<InsertAnswer> run_insert(const SceneInput& input, const InsertOptions& options, const SweepProgress& progress) {
  return with_limits(options.common.arith, [&] { return insert_answer(input, options, progress); });
}

json to_json(const InsertAnswer& a) {
  const solvers::Insertion<Q>& ins = a.insertion;
  json sets = json::array();
  for (std::size_t i = 0; i < ins.sets.size(); ++i)
    sets.push_back({{"state", ins.sets[i].state_text()},
                    {"mode", ins.sets[i].mode.text()},
                    {"redundant", static_cast<bool>(ins.redundant[i])},
                    {"empty", solvers::is_empty_cone<Q>(ins.cones[i])},
                    {"inequalities", exact_json(ins.cones[i].inequalities)},
                    {"equalities", exact_json(ins.cones[i].equalities)},
                    {"strict", exact_json(ins.cones[i].strict)}});
  json j;
  j["sets"] = sets;
  j["pushes"] = pieces_json(a.pushes);
  j["goal_boundary_fraction_approx"] = a.boundary_fraction;
  if (!a.sweep.empty()) {
    json sweep = json::array();
    for (const SweepEntry& e : a.sweep)
      sweep.push_back({{"mu", exact_json(e.mu)},
                       {"goal_boundary_fraction_approx", e.boundary_fraction},
                       {"pushes", pieces_json(e.pushes)}});
    j["sweep"] = sweep;
  }
  return j;
}

std::string insertion_svg(const geometry::PlanarScene& scene, const solvers::BoundaryPieces<Q, bool>& pushes) {
  return wrench_cone_svg(scene, exact::Mat<Q>(0, 3), exact::Mat<Q>(0, 3),
                         "green: frictionless pushes that seat the workpiece from any state",
                         seating_marks(scene, pushes));
}

}  // namespace contactcert::queries
