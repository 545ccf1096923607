// `contactcert insert FILE`: the wrenches G_goal that seat the workpiece from any contact state
// (wrench cone paper, sections 8-9, eq. 21 and Table 5) and the frictionless finger pushes inside it.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "cli/command.h"
#include "cli/progress_line.h"
#include "cli/snap_option.h"
#include "exact/rational_text.h"
#include "queries/boundary_text.h"
#include "queries/contact_notes.h"
#include "queries/insert_query.h"

namespace contactcert::cli {
namespace {

using exact::Q;

struct InsertCliOptions {
  CommonOptions common;
  std::string file;
  std::string snap;  ///< --snap TOL ("" = none)
  std::string sweep_mu;
  std::string svg;
};

void print_insertion(const std::string& file, const InsertAnswer& a) {
  const solvers::Insertion<Q>& ins = a.insertion;
  std::size_t needed = 0;
  for (bool r : ins.redundant) needed += !r;
  std::cout << "G_goal of " << file << ": complement of the union of " << ins.sets.size() << " wrench cones (" << needed
            << " non-redundant)\n"
            << tiny_gap_notes(a.scene, "  ");
  for (std::size_t i = 0; i < ins.sets.size(); ++i)
    std::cout << "  state " << ins.sets[i].state_text() << "  mode " << ins.sets[i].mode.text()
              << (solvers::is_empty_cone<Q>(ins.cones[i]) ? "  empty" : "") << (ins.redundant[i] ? "  (redundant)" : "")
              << "\n";
  std::cout << "finger pushes that seat the workpiece from any state (fraction of the boundary ~" << a.boundary_fraction
            << "):\n";
  std::cout << pieces_text(
      a.scene, a.pushes, "  ", [](bool in) { return in; }, [](bool) { return std::string(); });
  if (!a.sweep.empty()) {
    std::cout << "friction sweep (Figure 11):\n      mu   boundary fraction in G_goal\n";
    for (const SweepEntry& e : a.sweep)
      std::printf("  %6s   %.4f\n", exact::to_string(e.mu).c_str(), e.boundary_fraction);
  }
}

int run_insert_command(const InsertCliOptions& o) {
  const SceneInput input = read_scene(o.file, o.snap);
  InsertOptions options;
  options.common = o.common.query();
  options.sweep_mu = parse_sweep_mu(o.sweep_mu);
  options.svg = o.svg;
  ProgressLine progress("insert " + o.file + " --sweep-mu");
  const Limited<InsertAnswer> r =
      run_insert(input, options, [&progress](std::size_t index, std::size_t total, const Q& mu) {
        progress.update("mu = " + exact::to_string(mu) + " (" + std::to_string(index + 1) + " of " +
                        std::to_string(total) + ")");
      });
  progress.finish();
  if (!r) return report_limit("insert", r.limit(), o.common.json);
  const InsertAnswer& a = *r;
  if (o.common.json)
    std::cout << to_json(a).dump() << "\n";
  else
    print_insertion(o.file, a);
  return 0;
}

}  // namespace

void register_insert(CLI::App& app, Action& action) {
  auto o = std::make_shared<InsertCliOptions>();
  CLI::App* sub = app.add_subcommand("insert", "Wrenches that seat the workpiece from any contact state (G_goal)");
  add_snap_option(*sub, o->snap);
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Planar scene in its goal configuration (every fixel touching)")->required();
  sub->add_option("--svg", o->svg, "Picture of the workpiece with the seating pushes in green");
  sub->add_option("--sweep-mu", o->sweep_mu, "Friction values to sweep, e.g. 0.01,0.2,0.4,0.6 (Figure 11)")
      ->check(CLI::Validator([](std::string& s) { return s.empty() ? std::string("expected a list of numbers") : ""; },
                             "LIST"));
  sub->callback([o, &action] { action = [o] { return run_insert_command(*o); }; });
}

}  // namespace contactcert::cli
