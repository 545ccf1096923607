// `contactcert insert FILE`: the wrenches G_goal that seat the workpiece from any contact state
// (wrench cone paper, sections 8-9, eq. 21 and Table 5) and the frictionless finger pushes inside it.
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>

#include "cli/command.h"
#include "cli/progress_line.h"
#include "cli/results.h"
#include "cli/snap_option.h"
#include "exact/input_error.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "queries/boundary_fraction.h"
#include "queries/boundary_marks.h"
#include "queries/boundary_text.h"
#include "queries/contact_notes.h"
#include "queries/json_out.h"
#include "solvers/insertion/insertion.h"

namespace contactcert::cli {
namespace {

using exact::Q;

struct InsertOptions {
  CommonOptions common;
  std::string file;
  std::string snap;  ///< --snap TOL ("" = none)
  std::string sweep_mu;
  std::string svg;
};

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

}  // namespace

json insertion_json(const geometry::PlanarScene& scene, const solvers::Insertion<Q>& ins,
                    const solvers::BoundaryPieces<Q, bool>& pushes) {
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
  j["pushes"] = pieces_json(pushes);
  j["goal_boundary_fraction_approx"] = boundary_fraction(scene, pushes);
  return j;
}

std::vector<Q> sweep_mus(const std::string& text) {
  std::vector<Q> mus;
  if (text.empty()) return mus;
  const exact::Vec<Q> v = parse_number_list(text, "--sweep-mu", std::count(text.begin(), text.end(), ',') + 1);
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (sgn(v(i)) < 0) throw exact::InputError("command line", "--sweep-mu", "friction coefficients must be >= 0");
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

json sweep_entry_json(const geometry::PlanarScene& scene, const Q& mu) {
  geometry::PlanarScene s = scene;
  for (auto& f : s.fixels) f.mu_s = f.mu_k = mu;
  const auto ins = solvers::insertion<Q>(s);
  const auto pushes = solvers::insertion_pushes<Q>(s, ins);
  return {{"mu", exact_json(mu)},
          {"goal_boundary_fraction_approx", boundary_fraction(s, pushes)},
          {"pushes", pieces_json(pushes)}};
}

std::string insertion_svg(const geometry::PlanarScene& scene, const solvers::BoundaryPieces<Q, bool>& pushes) {
  return wrench_cone_svg(scene, exact::Mat<Q>(0, 3), exact::Mat<Q>(0, 3),
                         "green: frictionless pushes that seat the workpiece from any state",
                         seating_marks(scene, pushes));
}

namespace {

int run_insert(const InsertOptions& o) {
  const geometry::PlanarScene scene =
      geometry::read_planar_scene(exact::JsonInput::parse(read_scene_text(o.file, o.snap), o.file));
  if (exact::parse_arith(o.common.arith) == exact::Arith::kFloat)
    throw exact::InputError("command line", "--arith", "insert is computed exactly (use exact or verified)");
  const std::vector<Q> mus = sweep_mus(o.sweep_mu);
  auto analyse = [&](const geometry::PlanarScene& s) {
    auto ins = insertion_of(s, o.file);
    auto pushes = solvers::insertion_pushes<Q>(s, ins);
    return std::make_pair(std::move(ins), std::move(pushes));
  };
  const auto [ins, pushes] = analyse(scene);
  if (!o.svg.empty()) write_text_file(o.svg, insertion_svg(scene, pushes));
  json sweep = json::array();
  std::vector<std::pair<std::string, double>> sweep_rows;
  ProgressLine progress("insert " + o.file + " --sweep-mu");
  for (const Q& mu : mus) {
    progress.update("mu = " + exact::to_string(mu) + " (" + std::to_string(sweep_rows.size() + 1) + " of " +
                    std::to_string(mus.size()) + ")");
    sweep.push_back(sweep_entry_json(scene, mu));
    sweep_rows.emplace_back(exact::to_string(mu), sweep.back()["goal_boundary_fraction_approx"].get<double>());
  }
  progress.finish();
  if (o.common.json) {
    json j = insertion_json(scene, ins, pushes);
    if (!mus.empty()) j["sweep"] = sweep;
    std::cout << j.dump() << "\n";
    return 0;
  }
  std::size_t needed = 0;
  for (bool r : ins.redundant) needed += !r;
  std::cout << "G_goal of " << o.file << ": complement of the union of " << ins.sets.size() << " wrench cones ("
            << needed << " non-redundant)\n"
            << tiny_gap_notes(scene, "  ");
  for (std::size_t i = 0; i < ins.sets.size(); ++i)
    std::cout << "  state " << ins.sets[i].state_text() << "  mode " << ins.sets[i].mode.text()
              << (solvers::is_empty_cone<Q>(ins.cones[i]) ? "  empty" : "") << (ins.redundant[i] ? "  (redundant)" : "")
              << "\n";
  std::cout << "finger pushes that seat the workpiece from any state (fraction of the boundary ~"
            << boundary_fraction(scene, pushes) << "):\n";
  std::cout << pieces_text(
      scene, pushes, "  ", [](bool in) { return in; }, [](bool) { return std::string(); });
  if (!sweep_rows.empty()) {
    std::cout << "friction sweep (Figure 11):\n      mu   boundary fraction in G_goal\n";
    for (const auto& [mu, frac] : sweep_rows) std::printf("  %6s   %.4f\n", mu.c_str(), frac);
  }
  return 0;
}

}  // namespace

void register_insert(CLI::App& app, Action& action) {
  auto o = std::make_shared<InsertOptions>();
  CLI::App* sub = app.add_subcommand("insert", "Wrenches that seat the workpiece from any contact state (G_goal)");
  add_snap_option(*sub, o->snap);
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Planar scene in its goal configuration (every fixel touching)")->required();
  sub->add_option("--svg", o->svg, "Picture of the workpiece with the seating pushes in green");
  sub->add_option("--sweep-mu", o->sweep_mu, "Friction values to sweep, e.g. 0.01,0.2,0.4,0.6 (Figure 11)")
      ->check(CLI::Validator([](std::string& s) { return s.empty() ? std::string("expected a list of numbers") : ""; },
                             "LIST"));
  sub->callback([o, &action] { action = [o] { return run_insert(*o); }; });
}

}  // namespace contactcert::cli
