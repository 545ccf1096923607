// `contactcert design SCENE`: exact search for fixel placements (queries/design_query.h); the options, the text
// report and the exit codes. Under mpirun every rank runs the query; the root prints.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <limits>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/progress_line.h"
#include "exact/rational_text.h"
#include "queries/design_query.h"

namespace contactcert::cli {
namespace {

using exact::Q;

struct DesignOptions {
  CommonOptions common;
  std::string file;
  queries::DesignOptions query;
  std::string stable_under;
  std::string rank;
};

/// The text of one reported placement.
void print_placement(const queries::DesignReport& report, const queries::PlacementReport& p) {
  const solvers::DesignProblem& problem = report.problem;
  const solvers::PlacementEvidence& ev = p.evidence;
  std::string where;
  for (int i : p.ranked.placement)
    where += (where.empty() ? "" : " ") + point_text(problem.candidates[static_cast<std::size_t>(i)].point);
  std::cout << "  " << p.position << ". candidates " << queries::candidate_list_text(p.ranked.placement) << " at "
            << where << "\n     " << solvers::rank_name(problem.rank) << " " << exact::to_string(p.ranked.figure)
            << " (~" << p.ranked.figure.get_d() << ")";
  if (problem.rank == solvers::Rank::kMargin && !ev.margins.empty()) {
    const std::size_t worst = queries::worst_margin(ev);
    std::cout << " = squared stability margin of wrench " << worst + 1 << ", nearest: " << ev.margins[worst].nearest;
  }
  std::cout << "\n";
  for (std::size_t w = 0; w < ev.stability.size(); ++w)
    std::cout << "     wrench "
              << tuple_text(exact::Vec<Q>(problem.wrenches.rows.row(static_cast<Eigen::Index>(w)).transpose())) << ": "
              << solvers::verdict_name(ev.stability[w].verdict) << ", certificate " << p.stem << "_wrench_" << w + 1
              << ".cert.json\n";
  if (problem.wrenches.kind == solvers::WrenchSet::Kind::kCone)
    std::cout << "     the cone of these generators meets no moving mode's wrench cone (exact intersection)\n";
  if (problem.insertable) {
    std::optional<geometry::Point2> push;
    if (ev.goal_push_point >= 0) push = problem.pushes[static_cast<std::size_t>(ev.goal_push_point)].point;
    std::cout << "     G_goal non-empty, e.g. g = " << tuple_text(exact::primitive(ev.goal_witness))
              << (push ? " (the push at " + point_text(*push) + ")" : std::string()) << "; pushes at " << ev.goal_pushes
              << " of " << problem.pushes.size() << " push points seat it ("
              << exact::to_string(queries::goal_fraction(problem, ev)) << "), certificate " << p.stem
              << "_goal.cert.json\n";
    if (problem.goal_wrench.size() > 0)
      std::cout << "     G_goal contains " << tuple_text(problem.goal_wrench) << ", certificate " << p.stem
                << "_goal_wrench.cert.json\n";
  }
  std::cout << "     scene: " << p.stem << ".json\n";
}

void print_design(const queries::DesignReport& r) {
  std::cout << "design " << r.scene_name << ": " << r.problem.fixels << " fixels from " << r.problem.candidates.size()
            << " candidates (" << r.candidate_source << "), " << queries::requirement_text(r) << ", ranked by "
            << solvers::rank_name(r.problem.rank) << "\n"
            << "  " << r.placements << " placements, " << r.symmetries << " non-trivial symmetries; "
            << queries::statistics_text(r.statistics) << "\n";
  if (r.top.empty())
    std::cout << "  no placement meets the requirements\n";
  else
    std::cout << "best " << r.top.size() << ":\n";
  for (const queries::PlacementReport& p : r.top) print_placement(r, p);
  std::cout << "  picture: " << r.svg << "\n";
}

int run_design(DesignOptions& o) {
  o.query.common = o.common.query();
  if (!o.rank.empty()) o.query.rank = queries::parse_rank(o.rank, "--rank");
  const queries::SceneInput in = queries::load_scene(o.file);
  const std::unique_ptr<solvers::Distributor> dist = solvers::make_distributor();
  ProgressLine progress("design " + o.file);
  queries::DesignProgress show;
  if (progress.enabled()) show = [&progress](const std::string& text) { progress.update(text); };
  const queries::Limited<queries::DesignRun> limited = queries::run_design(in, o.query, *dist, show);
  progress.finish();
  if (!limited) return report_limit("design", limited.limit(), o.common.json);
  const queries::DesignRun& run = *limited;
  switch (run.status) {
    case queries::DesignStatus::kWorkerFinished:
      return 0;
    case queries::DesignStatus::kLimit:  // another rank: the root reports the limit
      return 3;
    case queries::DesignStatus::kRefused:
      if (!run.refusal.empty())  // one write: under mpirun, lines of other ranks cannot split it
        std::fputs(("contactcert: " + run.refusal + "\n").c_str(), stderr);
      return 2;
    case queries::DesignStatus::kFinished:
      break;
  }
  if (o.common.json)
    std::cout << queries::to_json(*run.report).dump() << "\n";
  else
    print_design(*run.report);
  return 0;
}

}  // namespace

void register_design(CLI::App& app, Action& action) {
  auto o = std::make_shared<DesignOptions>();
  CLI::App* sub =
      app.add_subcommand("design", "Fixture design: the best exact fixel placements among candidate points");
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Planar scene: the workpiece and mu (its fixels are otherwise ignored)")->required();
  sub->add_option("--candidates", o->query.candidates,
                  "N points equally spaced in arc length, or a JSON file {\"candidates\": [[x, y], ...]}");
  sub->add_option("--lattice", o->query.lattice,
                  "Candidates at the lattice points (i p, j p) on the boundary (modular fixturing)");
  sub->add_option("--fixels", o->query.fixels, "Fixels per placement: 2 or 3 (Table 5 covers three)")
      ->check(whole_number(2, 3))
      ->default_str("3");
  CLI::Option* stable = sub->add_option(
      "--stable-under", o->stable_under,
      "Wrenches to hold strongly stable: fx,fy,tz[;...] (a list) or cone:fx,fy,tz;... (a cone's generators)");
  sub->add_flag("--insertable", o->query.insertable, "Require a non-empty G_goal (sensorless insertion, Table 5)");
  sub->add_option(
         "--rank", o->rank,
         "margin (least squared stability margin) or goal-fraction (share of the push points whose push is in G_goal)")
      ->check(CLI::IsMember({"margin", "goal-fraction"}));
  sub->add_option("--top", o->query.top, "Report the K best placements")
      ->check(whole_number(1, queries::kMaxDesignTop))
      ->default_str("5");
  sub->add_option("--out", o->query.out, "Folder of the placement scenes, certificates and design.svg")
      ->default_str("contactcert-design");
  sub->add_option("--checkpoint", o->query.checkpoint, "Resume from and save progress to this file (atomic writes)");
  sub->add_option("--goal-wrench", o->query.goal_wrench,
                  "Require this wrench fx,fy,tz in G_goal (implies --insertable)");
  sub->add_flag("--goal-push", o->query.goal_push,
                "Require a frictionless finger push at one of the --push-points in G_goal (implies --insertable)");
  sub->add_option("--push-points", o->query.push_points,
                  "With --insertable: the goal fraction and --goal-push use the pushes at M points equally spaced in "
                  "arc length")
      ->check(whole_number<long>(1, queries::kMaxDesignCandidates))
      ->default_str("120");
  sub->add_option("--chunk-size", o->query.chunk_size, "Placements per unit of work handed to a rank")
      ->check(whole_number<long>(1, queries::kMaxDesignChunkSize))
      ->default_str("16");
  sub->add_option("--max-placements", o->query.max_placements,
                  "Budget: placements evaluated in this run, checked between chunks (exit 3 beyond)")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->default_str("100000000");
  sub->callback([o, stable, &action] {
    if (stable->count() > 0) o->query.stable_under = o->stable_under;
    action = [o] { return run_design(*o); };
  });
}

}  // namespace contactcert::cli
