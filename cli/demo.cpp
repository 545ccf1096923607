// `contactcert demo`: the main job. Reproduces both papers on the bundled scenes (the query:
// queries/demo_query.h): prints each worked example's line as it is computed, or with --json the answer, and
// writes an HTML report with inline SVG.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "cli/command.h"
#include "queries/demo_query.h"

namespace contactcert::cli {
namespace {

struct DemoArgs {
  DemoOptions query;
  bool json = false;
};

int demo_command(const DemoArgs& a) {
  // The readable report is printed line by line as it is computed; --json prints the answer once at the end.
  const Limited<DemoAnswer> r =
      a.json ? run_demo(a.query) : run_demo(a.query, [](const std::string& line) { std::cout << line; });
  if (!r) return report_limit("demo", r.limit(), a.json);
  if (a.json) std::cout << to_json(*r).dump() << "\n";
  return 0;
}

}  // namespace

void register_demo(CLI::App& app, Action& action) {
  auto opts = std::make_shared<DemoArgs>();
  CLI::App* sub = app.add_subcommand("demo", "Reproduce both papers' worked examples on the bundled scenes");
  sub->add_option("--scenes", opts->query.scenes,
                  "Folder of scene files: the papers' examples it holds, and every other scene in it (default: the "
                  "bundled scenes)");
  sub->add_option("--out", opts->query.out, "Folder for the report and pictures")->capture_default_str();
  sub->add_flag("--json", opts->json, "Machine output: one JSON object on stdout (each worked example's result)");
  add_time_limit(*sub, opts->query.time_limit);
  sub->callback([opts, &action] { action = [opts] { return demo_command(*opts); }; });
}

}  // namespace contactcert::cli
