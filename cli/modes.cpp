// `contactcert modes FILE`: every kinematically feasible augmented contact mode of a planar scene from rest
// (wrench cone paper, Table 2), each with a witness, found by the prefix tree of solvers/stability/mode_tree.h,
// and with --certificate the tree as a completeness proof for `contactcert check`.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <limits>

#include "cli/assembly_answers.h"
#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/snap_option.h"
#include "exact/input_error.h"
#include "queries/modes_query.h"

namespace contactcert::cli {
namespace {

struct ModesCliOptions {
  CommonOptions common;
  std::string file;
  std::string snap;  ///< --snap TOL ("" = none)
  bool kinematic = false;
  bool unions = false;
  std::string table2 = "strict";
  long max_nodes = ModesOptions{}.max_nodes;
  long max_modes = ModesOptions{}.max_modes;
  std::string certificate;
  std::string svg;  ///< --svg FILE: a spatial scene's picture ("" = none)
};

void print_modes(const std::string& file, const ModesAnswer& a) {
  const solvers::ContactModes& m = a.modes;
  const std::vector<bool>& touching = m.alphabet.rules.touching;
  const auto& tree = m.tree;
  const long k = static_cast<long>(touching.size()), t = std::count(touching.begin(), touching.end(), true);
  std::cout << "contact modes of " << file << ": " << tree.modes.size() << " feasible modes of " << k << " fixels ("
            << t << " touching, " << k - t << " with a gap), from rest, s "
            << (a.options.table2 == Table2::kPrinted ? "as Table 2 prints it (a_n >= 0)"
                                                     : "strictly separating (a_n > 0)")
            << "\n"
            << "  prefix tree: " << tree.nodes << " prefixes visited, " << tree.dead.size() << " proven infeasible, "
            << tree.lps << " LPs (of 4^" << t << " x 2^" << k - t << " mode strings)\n";
  if (!a.options.kinematic)
    std::cout << "  each mode's wrench cone contains M vdot (all contact forces zero fit every letter), so the\n"
                 "  dynamic list equals the kinematic one\n";
  for (const auto& [group, count] : mode_counts(m)) {
    std::cout << "  " << group << " (" << count << "):\n";
    for (std::size_t i = 0; i < tree.modes.size(); ++i) {
      if (solvers::mode_group(tree.modes[i], touching) != group) continue;
      std::cout << "    " << tree.modes[i].text() << "  vdot = " << tuple_text(tree.accelerations[i]);
      if (!a.options.kinematic) std::cout << ", wrench " << tuple_text(m.wrench(i));
      std::cout << "\n";
    }
  }
  if (tree.modes.empty()) std::cout << "  none\n";
  if (!a.options.certificate.empty()) std::cout << "  certificate written to " << a.options.certificate << "\n";
}

/// `modes ASSEMBLY`: the modes of N bodies (queries/assembly_modes_query.h); its letters are s l r n with s strict.
int run_assembly_modes_command(const ModesCliOptions& o, const AssemblyInput& in) {
  if (o.unions) throw exact::InputError("command line", "--unions", "an assembly's modes are over s l r n only");
  if (o.table2 != "strict")
    throw exact::InputError("command line", "--table2", "an assembly's modes read s strictly (a_n > 0)");
  AssemblyModesOptions q{o.common.query(), o.max_nodes, o.max_modes, o.certificate};
  return print_assembly_answer(run_assembly_modes(in, q), o.file, o.common.json, "modes");
}

/// `modes SPATIAL`: the modes of a body in space (queries/spatial_modes_query.h); its letters are s, f and the sliding
/// letters of each friction pyramid, always listed with their accelerations only.
int run_spatial_modes_command(const ModesCliOptions& o, const SpatialInput& in) {
  if (o.unions) throw exact::InputError("command line", "--unions", "a spatial scene's modes have no union letters");
  if (o.table2 != "strict")
    throw exact::InputError("command line", "--table2", "a spatial scene's modes read s strictly (a_n > 0)");
  const Limited<SpatialModesAnswer> r =
      run_spatial_modes(in, {o.common.query(), o.max_nodes, o.max_modes, o.certificate, o.svg});
  if (!r) return report_limit("modes", r.limit(), o.common.json);
  std::cout << (o.common.json ? to_json(*r).dump() + "\n" : to_text(*r, o.file));
  return 0;
}

int run_modes_command(const ModesCliOptions& o) {
  ModesOptions options;
  options.common = o.common.query();
  options.kinematic = o.kinematic;
  options.unions = o.unions;
  options.table2 = parse_table2(o.table2, "--table2");
  options.max_nodes = o.max_nodes;
  options.max_modes = o.max_modes;
  options.certificate = o.certificate;
  // The default time budget of the enumerations that can be exponential has the watchdog of an explicit
  // --time-limit too: a single LP over thousands of rows is not interrupted by the tree's deadline.
  if (options.default_time_budget())
    start_watchdog("modes (the default budget of --unions and --table2 printed; --time-limit sets another)",
                   kModesDefaultSeconds);
  SceneOrAssembly input = read_scene_or_assembly(o.file, o.snap);
  if (!o.svg.empty() && !std::holds_alternative<SpatialInput>(input))
    throw exact::InputError("command line", "--svg", "modes draws a picture of a spatial scene only");
  if (const auto* assembly = std::get_if<AssemblyInput>(&input)) return run_assembly_modes_command(o, *assembly);
  if (const auto* spatial = std::get_if<SpatialInput>(&input)) return run_spatial_modes_command(o, *spatial);
  const Limited<ModesAnswer> r = run_modes(std::get<SceneInput>(input), options);
  if (!r) return report_limit("modes", r.limit(), o.common.json);
  const ModesAnswer& a = *r;
  if (o.common.json)
    std::cout << to_json(a).dump() << "\n";
  else
    print_modes(o.file, a);
  return 0;
}

}  // namespace

void register_modes(CLI::App& app, Action& action) {
  auto o = std::make_shared<ModesCliOptions>();
  CLI::App* sub = app.add_subcommand("modes", "Every kinematically feasible contact mode of a scene, with a proof");
  add_snap_option(*sub, o->snap);
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file,
                  "Planar scene file (docs/formats.md), an assembly (section 3a) or a spatial scene (3b)")
      ->required();
  sub->add_flag("--kinematic", o->kinematic, "List the modes with their accelerations only (no witness wrench)");
  sub->add_flag("--unions", o->unions, "Also the letters m (l, r or n) and u (s or a), whose modes overlap");
  sub->add_option(
         "--table2", o->table2,
         "strict: s at a touching fixel is a_n > 0 (the physical modes); printed: a_n >= 0 as Table 2 prints it")
      ->check(CLI::IsMember({"strict", "printed"}))
      ->default_str("strict");
  sub->add_option("--max-nodes", o->max_nodes, "Budget on the prefixes the tree visits (exit 3 beyond it)")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->default_str(std::to_string(o->max_nodes));
  sub->add_option("--max-modes", o->max_modes,
                  "Budget on the modes listed (exit 3 beyond it; with --unions or --table2 printed the list can be "
                  "exponential in the fixels)")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->default_str(std::to_string(o->max_modes));
  sub->add_option("--certificate", o->certificate, "Write the completeness proof for `contactcert check` here");
  sub->add_option(
      "--svg", o->svg,
      "A spatial scene's picture here: isometric view of the box, com, contacts, normals, friction pyramids");
  sub->callback([o, &action] { action = [o] { return run_modes_command(*o); }; });
}

}  // namespace contactcert::cli
