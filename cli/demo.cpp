// `contactcert demo`: the main job. Reproduces both papers on the bundled scenes: the wrench cone of the
// section 4 example and the Figure 4 modes, strong stability (Figure 5), insertion (Figures 6, 10, 11),
// and Data Sets 1-4 and a small Table 1 of the quasistatic paper, every verdict exact and every "no"
// checked by the independent checker. Prints a summary and writes an HTML report with inline SVG.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <random>
#include <sstream>

#include "checker/assembly_check.h"
#include "checker/stability_check.h"
#include "checker/ucp_check.h"
#include "cli/command.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "queries/assembly_query.h"
#include "queries/assembly_svg.h"
#include "queries/boundary_fraction.h"
#include "queries/boundary_marks.h"
#include "queries/boundary_text.h"
#include "queries/cone_svg.h"
#include "queries/html_report.h"
#include "queries/insert_query.h"
#include "queries/json_out.h"
#include "queries/line_plot.h"
#include "queries/stability_svg.h"
#include "runtime/scenes.h"
#include "solvers/assembly/assembly_certificate.h"
#include "solvers/insertion/insertion.h"
#include "solvers/stability/stability_certificate.h"
#include "solvers/stability/stable_region.h"
#include "solvers/ucp/certificate.h"
#include "solvers/ucp/generate.h"
#include "solvers/ucp/solve.h"
#include "solvers/wrench_cone/wrench_cone.h"

namespace contactcert::cli {
namespace {

namespace fs = std::filesystem;
using exact::Q;

struct DemoOptions {
  std::string scenes;  ///< empty: the bundled scenes (runtime::bundled_scenes_dir)
  std::string out = "contactcert-out";
};

/// True when every named file is in the scenes folder (a section of the paper report runs only then).
bool has(const DemoOptions& o, std::initializer_list<const char*> files) {
  for (const char* f : files)
    if (!fs::exists(fs::path(o.scenes) / f)) return false;
  return true;
}

/// The scene files of the bundled paper examples (every other .json in the folder is the user's own).
bool is_paper_scene(const std::string& name) {
  return name.rfind("bt2002_", 0) == 0 || name.rfind("pang1994_dataset", 0) == 0;
}

std::string rows_text(const exact::Mat<Q>& M) {
  std::string s;
  for (Eigen::Index r = 0; r < M.rows(); ++r) s += (r ? ", " : "") + tuple_text(exact::Vec<Q>(M.row(r).transpose()));
  return s.empty() ? "none" : s;
}

/// Section 4 and Figure 4: the wrench cone of each bundled bt2002 scene's mode (named in the file name).
void wrench_cones(const DemoOptions& o, HtmlReport& rep) {
  rep.heading("Wrench cones (Balkcom and Trinkle 2002, sections 4-6)");
  rep.paragraph(
      "Each cone is computed exactly (F = K^F P, strict rows of Table 2 as exact limits). Generators are "
      "drawn as lines of force; the cone is the set of external wrenches consistent with the mode.");
  std::vector<std::vector<std::string>> rows;
  for (const char* name : {"bt2002_section4_disk.json:na", "bt2002_fig4a_lla.json:lla", "bt2002_fig4b_nnn.json:nnn",
                           "bt2002_fig4c_peg_lra.json:lra", "bt2002_fig4d_peg_nn.json:nn"}) {
    const std::string spec = name;
    const std::string file = spec.substr(0, spec.find(':')), mode_text = spec.substr(spec.find(':') + 1);
    const auto scene = geometry::load_planar_scene((fs::path(o.scenes) / file).string());
    std::vector<bool> touching;
    for (const auto& f : scene.fixels) touching.push_back(f.frame.touching());
    const auto mode = solvers::parse_mode(mode_text, touching).mode;
    const auto c = solvers::wrench_cone<Q>(scene, mode, solvers::Route::kPaper);
    const bool empty = c.status == solvers::ConeStatus::kEmpty;
    rows.push_back({file, mode_text, empty ? "empty" : std::to_string(c.cone.dimension()),
                    empty ? "-" : rows_text(c.cone.closure.rays), std::to_string(c.cone.open_faces.size())});
    rep.figure(wrench_cone_svg(scene, empty ? exact::Mat<Q>(0, 3) : c.cone.closure.rays,
                               empty ? exact::Mat<Q>(0, 3) : c.cone.closure.lines, "mode '" + mode_text + "'"),
               file + ", mode '" + mode_text + "'");
    std::cout << "  cone  " << file << " '" << mode_text
              << "': " << (empty ? "empty" : "generators " + rows_text(c.cone.closure.rays)) << "\n";
  }
  rep.table({"scene", "mode", "dimension", "generators (closure)", "open faces"}, rows);
}

/// Section 7: verdicts with certificates, the region picture and the finger pushes (Figure 5).
void stability(const DemoOptions& o, HtmlReport& rep) {
  rep.heading("Strong stability (section 7, Figure 5)");
  const std::string file = (fs::path(o.scenes) / "bt2002_section7_disk.json").string();
  const std::string text = exact::JsonInput::read_text(file);
  const auto scene = geometry::read_planar_scene(exact::JsonInput::parse(text, file));
  std::vector<std::vector<std::string>> rows;
  for (const char* w : {"0,-1,0", "1,0,0", "-1,-1,0", "0,1,0"}) {
    const exact::Vec<Q> g = parse_number_list(w, "wrench", 3);
    const auto r = solvers::strong_stability<Q>(scene, g);
    const std::string cert = solvers::stability_certificate(text, g, r);
    const auto check = checker::check_stability_certificate(exact::JsonInput::parse(cert, "certificate"));
    rows.push_back({tuple_text(g), solvers::verdict_name(r.verdict),
                    r.has_moving
                        ? "moves in mode '" + r.moving.mode.text() + "', vdot = " + tuple_text(r.moving.acceleration)
                        : std::to_string(r.proofs.size()) + " mode proofs",
                    check.valid ? "valid" : "INVALID: " + check.reason, std::to_string(r.lps)});
    std::cout << "  stability g = " << tuple_text(g) << ": " << solvers::verdict_name(r.verdict) << " (certificate "
              << (check.valid ? "valid" : "INVALID") << ")\n";
  }
  rep.table({"wrench g", "verdict", "evidence", "contactcert check", "LPs"}, rows);
  const auto region = solvers::stable_region<Q>(scene);
  int strong3 = 0;
  for (const auto& c : region.cells)
    strong3 += c.dimension == 3 && c.label == solvers::StabilityVerdict::kStronglyStable;
  exact::Vec<Q> gravity(3);
  gravity << 0, -1, 0;
  rep.figure(stability_sphere_svg(region, gravity),
             "Wrench directions for the disk on two fixels, mu = 1.2: " + std::to_string(region.cells.size()) +
                 " exact cells, " + std::to_string(strong3) + " open strongly stable regions; g = (0, -1, 0) marked.");
  std::cout << "  region: " << region.cells.size() << " exact cells, " << strong3 << " open strongly stable regions\n";
  const auto pushes = solvers::finger_pushes<Q>(scene, region);
  std::vector<std::vector<std::string>> prow;
  for (const auto& a : pushes.arcs)
    prow.push_back({arc_piece_text(a.from, a.to, a.from_closed, a.to_closed), solvers::verdict_name(a.label)});
  rep.paragraph(
      "Frictionless finger pushes along the inward normal, by arc of the boundary (directions from the "
      "centre, counter-clockwise):");
  rep.table({"piece of the boundary", "verdict"}, prow);
  rep.figure(
      wrench_cone_svg(scene, exact::Mat<Q>(0, 3), exact::Mat<Q>(0, 3), "finger pushes", verdict_marks(scene, pushes)),
      "Where a frictionless push along the inward normal is strongly stable (green), only weakly stable "
      "(yellow) or unstable (red): the dark line of Figure 5.");
}

/// Sections 8-9: G_goal and the friction sweep of Figure 11.
void insertion(const DemoOptions& o, HtmlReport& rep) {
  rep.heading("Sensorless insertion (sections 8-9, Figures 6, 10, 11)");
  std::vector<std::vector<std::string>> rows;
  std::vector<LineSeries> sweep;
  for (const char* file : {"bt2002_section7_disk.json", "bt2002_fig10_pentagon_insert.json"}) {
    sweep.push_back({file, {}});
    const auto base = geometry::load_planar_scene((fs::path(o.scenes) / file).string());
    for (const char* mu : {"0.01", "0.2", "0.4", "0.6"}) {
      auto scene = base;
      for (auto& f : scene.fixels) f.mu_s = f.mu_k = exact::parse_rational(mu);
      const auto ins = insertion_of(scene, (fs::path(o.scenes) / file).string());
      const auto p = solvers::insertion_pushes<Q>(scene, ins);
      if (std::string(mu) == "0.2")
        rep.figure(wrench_cone_svg(scene, exact::Mat<Q>(0, 3), exact::Mat<Q>(0, 3), std::string(file) + ", mu = 0.2",
                                   seating_marks(scene, p)),
                   std::string("Pushes that seat the workpiece from any contact state (green), mu = 0.2: ") + file);
      std::string where;
      for (const auto& e : p.edges)
        if (e.label)
          where +=
              (where.empty() ? "" : "; ") + edge_piece_text(scene, e.edge, e.from, e.to, e.from_closed, e.to_closed);
      for (const auto& a : p.arcs)
        if (a.label) where += (where.empty() ? "" : "; ") + arc_piece_text(a.from, a.to, a.from_closed, a.to_closed);
      sweep.back().points.emplace_back(exact::parse_rational(mu).get_d(), boundary_fraction(scene, p));
      std::size_t needed = 0;
      for (bool r : ins.redundant) needed += !r;
      rows.push_back({file, mu, std::to_string(ins.sets.size()) + " (" + std::to_string(needed) + " non-redundant)",
                      where.empty() ? "none" : where});
    }
  }
  rep.paragraph(
      "Finger pushes that seat the workpiece from any contact state, by friction coefficient: the set "
      "shrinks as friction grows (Figure 11).");
  rep.figure(line_plot_svg(sweep, "Figure 11: pushes that seat the part, by friction", "friction coefficient mu",
                           "fraction of the boundary"),
             "The fraction of the boundary (by length; by angle on the disk) where a frictionless push seats the "
             "workpiece from any contact state, against mu.");
  rep.table({"scene", "mu", "wrench cones in the union", "pushes in G_goal"}, rows);
  std::cout << "  insertion: " << rows.size() << " friction cases\n";
}

/// Pang, Trinkle, Lo: Data Sets 1-4 and a small Table 1.
void quasistatic(const DemoOptions& o, HtmlReport& rep) {
  rep.heading("Quasistatic contact problems (Pang, Trinkle and Lo 1994)");
  std::vector<std::vector<std::string>> rows;
  for (int ds = 1; ds <= 4; ++ds) {
    const std::string file = (fs::path(o.scenes) / ("pang1994_dataset" + std::to_string(ds) + ".json")).string();
    const auto problem = solvers::ucp::load_ucp_problem(file);
    const auto t0 = std::chrono::steady_clock::now();
    solvers::ucp::UcpOptions opts;
    const auto r = solvers::ucp::solve_ucp(problem, opts);
    const double secs = seconds_since(t0);
    std::string evidence;
    if (r.status == solvers::ucp::UcpStatus::kSolvable && r.physical) {
      evidence = "c_n = " + tuple_text(r.physical->c_n.to_q()) + ", q_dot = " + tuple_text(r.physical->q_dot.to_q()) +
                 (r.conditions && r.conditions->status == solvers::ucp::ConditionsStatus::kSatisfied
                      ? "; (2)-(10) hold exactly"
                      : "; (2)-(10) FAIL");
    } else if (r.status == solvers::ucp::UcpStatus::kJammed && r.proof) {
      const std::string cert = solvers::ucp::jammed_certificate(problem, *r.proof);
      const auto check = checker::check_ucp_certificate(exact::JsonInput::parse(cert, "certificate"));
      evidence = "certificate with " + std::to_string(r.proof->nodes) +
                 " nodes: " + (check.verdict == checker::CertificateVerdict::kValid ? "valid" : "INVALID");
    } else {
      evidence = r.reason;
    }
    rows.push_back({"Data Set " + std::to_string(ds), solvers::ucp::status_name(r.status),
                    r.status == solvers::ucp::UcpStatus::kSolvable && r.best_xTy ? exact::to_string(*r.best_xTy) : "-",
                    std::to_string(r.pairs), std::to_string(r.lps), evidence,
                    std::to_string(secs * 1000).substr(0, 6) + " ms"});
    std::cout << "  Data Set " << ds << ": " << solvers::ucp::status_name(r.status) << " (" << evidence << ")\n";
  }
  rep.table({"problem", "verdict", "x^T y", "pairs", "LPs", "evidence", "time"}, rows);

  rep.paragraph(
      "A small Table 1: random problems of section 5 (point fingers on a workpiece), the paper's algorithm "
      "and its modification against the complete exact search.");
  std::vector<std::vector<std::string>> t1;
  std::mt19937_64 rng(1994);
  const int sizes[][3] = {{3, 10, 0}, {10, 10, 0}, {10, 20, 0}, {15, 12, 1}, {18, 8, 9}, {20, 10, 10}};
  int k = 0;
  for (const auto& s : sizes) {
    solvers::ucp::RandomProblemOptions ro;
    ro.nc = s[0];
    ro.mu_max = Q(s[1], 10);
    ro.abar_size = s[2];
    const auto problem = solvers::ucp::generate_random_problem(ro, rng);
    std::vector<std::string> row{std::to_string(++k), std::to_string(s[0]), "(0, " + exact::to_string(ro.mu_max) + ")",
                                 std::to_string(s[2])};
    for (auto m : {solvers::ucp::Method::kPaper, solvers::ucp::Method::kModified, solvers::ucp::Method::kComplete}) {
      solvers::ucp::UcpOptions opts;
      opts.method = m;
      const auto t0 = std::chrono::steady_clock::now();
      const auto r = solvers::ucp::solve_ucp(problem, opts);
      row.push_back(std::string(solvers::ucp::status_name(r.status)) + " (" + std::to_string(r.pairs) + " pairs, " +
                    std::to_string(r.lps) + " LPs, " + std::to_string(seconds_since(t0) * 1000).substr(0, 6) + " ms)");
    }
    t1.push_back(row);
  }
  rep.table({"#", "n_c", "mu range", "|abar|", "paper", "modified", "complete (exact)"}, t1);
  std::cout << "  Table 1: " << t1.size() << " random problems\n";
}

/// An assembly of the scenes folder (docs/formats.md section 3a), its row and picture: a planar file's stability
/// under the bodies' loads with a checked certificate, a quasistatic_scene's quasistatic problem.
std::vector<std::string> assembly_row(const std::string& name, const std::string& kind, const std::string& text,
                                      const std::string& path, HtmlReport& rep) {
  const AssemblyInput in = parse_assembly(text, path);
  if (kind == "quasistatic_scene") {
    const Limited<AssemblyUcpAnswer> r = run_assembly_ucp(in, {});
    if (!r) return {name, "-", "budget exhausted", r.limit().what};
    const AssemblyUcpAnswer& a = *r;
    const char* status = solvers::ucp::status_name(a.report.status);
    rep.figure(to_svg(in, a), name + (a.forces.empty() ? ": the assembly" : ": the contact forces of the solution"));
    return {name, "assembly, quasistatic", status, a.report.reason};
  }
  const Limited<AssemblyStabilityAnswer> r = run_assembly_stability(in, {});
  if (!r) return {name, "-", "budget exhausted", r.limit().what};
  const AssemblyStabilityAnswer& a = *r;
  if (!a.decided()) return {name, "assembly", "budget exhausted", a.result.covered};
  const auto check = checker::check_assembly_certificate(
      exact::JsonInput::parse(solvers::assembly::assembly_certificate(text, a.result), "certificate"));
  const char* verdict = solvers::assembly::verdict_name(a.result.verdict);
  rep.figure(to_svg(in, a),
             name + ": " + (a.result.has_moving ? "a moving witness's" : "the resting") + " contact forces");
  return {name, "assembly", verdict,
          std::string("certificate ") + (check.valid ? "valid" : "INVALID: " + check.reason)};
}

/// Every scene of the folder that is not one of the papers' examples: a planar scene gets its verdict under
/// gravity g = (0, -1, 0) with a checked certificate, its region picture and its finger pushes; a quasistatic or
/// UCP problem its status with the evidence; an assembly as assembly_row says. A file that cannot be read is
/// listed with the reason.
void own_scenes(const DemoOptions& o, HtmlReport& rep) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(o.scenes))
    if (e.path().extension() == ".json" && !is_paper_scene(e.path().filename().string())) files.push_back(e.path());
  if (files.empty()) return;
  std::sort(files.begin(), files.end());
  rep.heading("Your scenes");
  rep.paragraph(
      "Planar scenes under gravity g = (0, -1, 0) (torque about the centre of mass); quasistatic "
      "problems solved exactly.");
  std::vector<std::vector<std::string>> rows;
  for (const auto& path : files) {
    const std::string name = path.filename().string();
    try {
      const std::string text = exact::JsonInput::read_text(path.string());
      const auto in = exact::JsonInput::parse(text, path.string());
      if (geometry::is_assembly(in)) {
        rows.push_back(assembly_row(name, in.at("kind").string(), text, path.string(), rep));
      } else if (in.at("kind").string() == "planar") {
        const auto scene = geometry::read_planar_scene(in);
        exact::Vec<Q> g(3);
        g << 0, -1, 0;
        const auto r = solvers::strong_stability<Q>(scene, g);
        const auto check = checker::check_stability_certificate(
            exact::JsonInput::parse(solvers::stability_certificate(text, g, r), "certificate"));
        const auto region = solvers::stable_region<Q>(scene);
        rep.figure(stability_sphere_svg(region, g), name + ": wrench directions, g = (0, -1, 0) marked");
        const auto pushes = solvers::finger_pushes<Q>(scene, region);
        rep.figure(wrench_cone_svg(scene, exact::Mat<Q>(0, 3), exact::Mat<Q>(0, 3), name, verdict_marks(scene, pushes)),
                   name + ": frictionless finger pushes (green strongly stable, yellow weakly, red unstable)");
        rows.push_back({name, "planar", solvers::verdict_name(r.verdict),
                        std::string("certificate ") + (check.valid ? "valid" : "INVALID: " + check.reason)});
      } else {
        const auto problem = solvers::ucp::read_ucp_problem(in);
        const auto r = solvers::ucp::solve_ucp(problem, solvers::ucp::UcpOptions{});
        rows.push_back({name, in.at("kind").string(), solvers::ucp::status_name(r.status), r.reason});
      }
    } catch (const exact::InputError& e) {
      rows.push_back({name, "-", "not read", e.what()});
    } catch (const exact::BudgetExceeded& e) {
      rows.push_back({name, "-", "budget exhausted", e.what()});
    }
    std::cout << "  your scene " << name << ": " << rows.back()[2] << "\n";
  }
  rep.table({"file", "kind", "verdict", "evidence"}, rows);
}

int run_demo(const DemoOptions& options) {
  DemoOptions o = options;
  if (o.scenes.empty()) o.scenes = runtime::bundled_scenes_dir();
  if (!fs::is_directory(o.scenes)) throw exact::InputError(o.scenes, "", "the scenes folder does not exist");
  create_output_dir(o.out);
  const auto t0 = std::chrono::steady_clock::now();
  HtmlReport rep("contactcert demo: both papers, exactly");
  rep.paragraph(
      "Every number below is exact (rational arithmetic); every 'no' carries a certificate that the "
      "independent checker verified in this run.");
  std::cout << "contactcert demo on " << o.scenes << "\n";
  if (has(o, {"bt2002_section4_disk.json", "bt2002_fig4a_lla.json", "bt2002_fig4b_nnn.json",
              "bt2002_fig4c_peg_lra.json", "bt2002_fig4d_peg_nn.json"}))
    wrench_cones(o, rep);
  if (has(o, {"bt2002_section7_disk.json"})) stability(o, rep);
  if (has(o, {"bt2002_section7_disk.json", "bt2002_fig10_pentagon_insert.json"})) insertion(o, rep);
  if (has(o, {"pang1994_dataset1.json", "pang1994_dataset2.json", "pang1994_dataset3.json", "pang1994_dataset4.json"}))
    quasistatic(o, rep);
  own_scenes(o, rep);
  const std::string path = rep.write(o.out);
  std::cout << "report: " << path << " (" << std::to_string(seconds_since(t0)).substr(0, 5) << " s)\n";
  return 0;
}

}  // namespace

void register_demo(CLI::App& app, Action& action) {
  auto opts = std::make_shared<DemoOptions>();
  CLI::App* sub = app.add_subcommand("demo", "Reproduce both papers' worked examples on the bundled scenes");
  sub->add_option("--scenes", opts->scenes,
                  "Folder of scene files: the papers' examples it holds, and every other scene in it (default: the "
                  "bundled scenes)");
  sub->add_option("--out", opts->out, "Folder for the report and pictures")->capture_default_str();
  sub->callback([opts, &action] { action = [opts] { return run_demo(*opts); }; });
}

}  // namespace contactcert::cli
