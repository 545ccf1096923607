// `demo`'s orchestration (queries/demo_query.h): each worked example computed, its row kept in the answer and
// drawn in the HTML report, its line passed to the progress callback as soon as it is known.
#include "queries/demo_query.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <random>

#include "checker/assembly_check.h"
#include "checker/spatial_modes_check.h"
#include "checker/stability_check.h"
#include "checker/ucp_check.h"
#include "exact/deadline.h"
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
#include "queries/line_plot.h"
#include "queries/simulate_query.h"
#include "queries/stability_svg.h"
#include "runtime/scenes.h"
#include "solvers/assembly/assembly_certificate.h"
#include "solvers/insertion/insertion.h"
#include "solvers/spatial/spatial_modes.h"
#include "solvers/spatial/spatial_modes_certificate.h"
#include "solvers/motion/motion_scene.h"
#include "solvers/stability/stability_certificate.h"
#include "solvers/stability/stable_region.h"
#include "solvers/ucp/certificate.h"
#include "solvers/ucp/generate.h"
#include "solvers/wrench_cone/wrench_cone.h"

namespace contactcert::queries {
namespace {

namespace fs = std::filesystem;
using exact::Q;

/// What the sections share: the folder, the report being written, the answer being filled, where its lines go
/// and the time limit.
struct Demo {
  const std::string& scenes;
  HtmlReport& rep;
  DemoAnswer& answer;
  const DemoProgress& progress;
  exact::Deadline deadline;

  void say(const std::string& line) const {
    if (progress) progress(line);
  }
  /// BudgetExceeded once the time limit has passed, with what the answer covers so far.
  void check_time() const {
    if (!deadline.expired()) return;
    const std::string covered =
        std::to_string(answer.cones.size()) + " cones, " + std::to_string(answer.stability.size()) +
        " stability verdicts, " + std::to_string(answer.insertion.size()) + " insertion cases, " +
        std::to_string(answer.data_sets.size()) + " Data Sets, " + std::to_string(answer.table1.size()) +
        " Table 1 problems, " + std::to_string(answer.scenes_of_folder.size()) + " scenes of the folder";
    throw exact::BudgetExceeded("demo: " + deadline.reached_text(), covered);
  }
  /// True when every named file is in the scenes folder (a section of the paper report runs only then).
  bool has(std::initializer_list<const char*> files) const {
    for (const char* f : files)
      if (!fs::exists(fs::path(scenes) / f)) return false;
    return true;
  }
  std::string path(const std::string& file) const { return (fs::path(scenes) / file).string(); }
};

/// The scene files of the bundled paper examples (every other .json in the folder is the user's own).
bool is_paper_scene(const std::string& name) {
  return name.rfind("bt2002_", 0) == 0 || name.rfind("pang1994_dataset", 0) == 0;
}

/// Section 4 and Figure 4: the wrench cone of each bundled bt2002 scene's mode (named in the file name).
void wrench_cones(const Demo& d) {
  d.rep.heading("Wrench cones (Balkcom and Trinkle 2002, sections 4-6)");
  d.rep.paragraph(
      "Each cone is computed exactly (F = K^F P, strict rows of Table 2 as exact limits). Generators are "
      "drawn as lines of force; the cone is the set of external wrenches consistent with the mode.");
  std::vector<std::vector<std::string>> rows;
  for (const char* name : {"bt2002_section4_disk.json:na", "bt2002_fig4a_lla.json:lla", "bt2002_fig4b_nnn.json:nnn",
                           "bt2002_fig4c_peg_lra.json:lra", "bt2002_fig4d_peg_nn.json:nn"}) {
    d.check_time();
    const std::string spec = name;
    const std::string file = spec.substr(0, spec.find(':')), mode_text = spec.substr(spec.find(':') + 1);
    const auto scene = geometry::load_planar_scene(d.path(file));
    std::vector<bool> touching;
    for (const auto& f : scene.fixels) touching.push_back(f.frame.touching());
    const auto mode = solvers::parse_mode(mode_text, touching).mode;
    const auto c = solvers::wrench_cone<Q>(scene, mode, solvers::Route::kPaper);
    DemoCone row{file, mode_text, c.status == solvers::ConeStatus::kEmpty, -1, exact::Mat<Q>(0, 3), 0};
    if (!row.empty) {
      row.dimension = static_cast<long>(c.cone.dimension());
      row.generators = c.cone.closure.rays;
      row.open_faces = c.cone.open_faces.size();
    }
    rows.push_back({file, mode_text, row.empty ? "empty" : std::to_string(row.dimension),
                    row.empty ? "-" : generators_text(row.generators), std::to_string(c.cone.open_faces.size())});
    d.rep.figure(wrench_cone_svg(scene, row.generators, row.empty ? exact::Mat<Q>(0, 3) : c.cone.closure.lines,
                                 "mode '" + mode_text + "'"),
                 file + ", mode '" + mode_text + "'");
    d.answer.cones.push_back(row);
    d.say(demo_line(row));
  }
  d.rep.table({"scene", "mode", "dimension", "generators (closure)", "open faces"}, rows);
}

/// Section 7: verdicts with certificates, the region picture and the finger pushes (Figure 5).
void stability(const Demo& d) {
  d.rep.heading("Strong stability (section 7, Figure 5)");
  const std::string file = d.path("bt2002_section7_disk.json");
  const std::string text = exact::JsonInput::read_text(file);
  const auto scene = geometry::read_planar_scene(exact::JsonInput::parse(text, file));
  std::vector<std::vector<std::string>> rows;
  for (const char* w : {"0,-1,0", "1,0,0", "-1,-1,0", "0,1,0"}) {
    d.check_time();
    const exact::Vec<Q> g = parse_number_list(w, "wrench", 3);
    const auto r = solvers::strong_stability<Q>(scene, g);
    const std::string cert = solvers::stability_certificate(text, g, r);
    const auto check = checker::check_stability_certificate(exact::JsonInput::parse(cert, "certificate"));
    const DemoStability row{
        g,
        r.verdict,
        r.has_moving ? "moves in mode '" + r.moving.mode.text() + "', vdot = " + tuple_text(r.moving.acceleration)
                     : std::to_string(r.proofs.size()) + " mode proofs",
        check.valid,
        check.valid ? "" : check.reason,
        r.lps};
    rows.push_back({tuple_text(g), solvers::verdict_name(r.verdict), row.evidence,
                    check.valid ? "valid" : "INVALID: " + check.reason, std::to_string(r.lps)});
    d.answer.stability.push_back(row);
    d.say(demo_line(row));
  }
  d.rep.table({"wrench g", "verdict", "evidence", "contactcert check", "LPs"}, rows);
  d.check_time();
  const auto region = solvers::stable_region<Q>(scene);
  DemoRegion out;
  out.cells = region.cells.size();
  for (const auto& c : region.cells)
    out.strongly_stable_regions += c.dimension == 3 && c.label == solvers::StabilityVerdict::kStronglyStable;
  exact::Vec<Q> gravity(3);
  gravity << 0, -1, 0;
  d.rep.figure(stability_sphere_svg(region, gravity),
               "Wrench directions for the disk on two fixels, mu = 1.2: " + std::to_string(out.cells) +
                   " exact cells, " + std::to_string(out.strongly_stable_regions) +
                   " open strongly stable regions; g = (0, -1, 0) marked.");
  const auto pushes = solvers::finger_pushes<Q>(scene, region);
  std::vector<std::vector<std::string>> prow;
  for (const auto& a : pushes.arcs) {
    out.pushes.push_back({arc_piece_text(a.from, a.to, a.from_closed, a.to_closed), a.label});
    prow.push_back({out.pushes.back().piece, solvers::verdict_name(a.label)});
  }
  d.answer.region = out;
  d.say(demo_line(out));
  d.rep.paragraph(
      "Frictionless finger pushes along the inward normal, by arc of the boundary (directions from the "
      "centre, counter-clockwise):");
  d.rep.table({"piece of the boundary", "verdict"}, prow);
  d.rep.figure(
      wrench_cone_svg(scene, exact::Mat<Q>(0, 3), exact::Mat<Q>(0, 3), "finger pushes", verdict_marks(scene, pushes)),
      "Where a frictionless push along the inward normal is strongly stable (green), only weakly stable "
      "(yellow) or unstable (red): the dark line of Figure 5.");
}

/// Sections 8-9: G_goal and the friction sweep of Figure 11.
void insertion(const Demo& d) {
  d.rep.heading("Sensorless insertion (sections 8-9, Figures 6, 10, 11)");
  std::vector<std::vector<std::string>> rows;
  std::vector<LineSeries> sweep;
  for (const char* file : {"bt2002_section7_disk.json", "bt2002_fig10_pentagon_insert.json"}) {
    sweep.push_back({file, {}});
    const auto base = geometry::load_planar_scene(d.path(file));
    for (const char* mu : {"0.01", "0.2", "0.4", "0.6"}) {
      d.check_time();
      auto scene = base;
      for (auto& f : scene.fixels) f.mu_s = f.mu_k = exact::parse_rational(mu);
      const auto ins = insertion_of(scene, d.path(file));
      const auto p = solvers::insertion_pushes<Q>(scene, ins);
      if (std::string(mu) == "0.2")
        d.rep.figure(wrench_cone_svg(scene, exact::Mat<Q>(0, 3), exact::Mat<Q>(0, 3), std::string(file) + ", mu = 0.2",
                                     seating_marks(scene, p)),
                     std::string("Pushes that seat the workpiece from any contact state (green), mu = 0.2: ") + file);
      DemoInsertion row{file, mu, ins.sets.size(), 0, {}, boundary_fraction(scene, p)};
      for (const auto& e : p.edges)
        if (e.label) row.pushes.push_back(edge_piece_text(scene, e.edge, e.from, e.to, e.from_closed, e.to_closed));
      for (const auto& a : p.arcs)
        if (a.label) row.pushes.push_back(arc_piece_text(a.from, a.to, a.from_closed, a.to_closed));
      std::string where;
      for (const std::string& piece : row.pushes) where += (where.empty() ? "" : "; ") + piece;
      sweep.back().points.emplace_back(exact::parse_rational(mu).get_d(), row.boundary_fraction);
      for (bool r : ins.redundant) row.non_redundant += !r;
      rows.push_back({file, mu,
                      std::to_string(row.cones) + " (" + std::to_string(row.non_redundant) + " non-redundant)",
                      where.empty() ? "none" : where});
      d.answer.insertion.push_back(row);
    }
  }
  d.rep.paragraph(
      "Finger pushes that seat the workpiece from any contact state, by friction coefficient: the set "
      "shrinks as friction grows (Figure 11).");
  d.rep.figure(line_plot_svg(sweep, "Figure 11: pushes that seat the part, by friction", "friction coefficient mu",
                             "fraction of the boundary"),
               "The fraction of the boundary (by length; by angle on the disk) where a frictionless push seats the "
               "workpiece from any contact state, against mu.");
  d.rep.table({"scene", "mu", "wrench cones in the union", "pushes in G_goal"}, rows);
  d.say(demo_insertion_line(d.answer.insertion));
}

std::string milliseconds_text(double seconds) { return std::to_string(seconds * 1000).substr(0, 6) + " ms"; }

/// Pang, Trinkle, Lo: Data Sets 1-4 and a small Table 1.
void quasistatic(const Demo& d) {
  d.rep.heading("Quasistatic contact problems (Pang, Trinkle and Lo 1994)");
  std::vector<std::vector<std::string>> rows;
  for (int ds = 1; ds <= 4; ++ds) {
    d.check_time();
    const std::string file = d.path("pang1994_dataset" + std::to_string(ds) + ".json");
    const auto problem = solvers::ucp::load_ucp_problem(file);
    const auto t0 = std::chrono::steady_clock::now();
    solvers::ucp::UcpOptions opts;
    const auto r = solvers::ucp::solve_ucp(problem, opts);
    DemoDataSet row{ds, r.status, std::nullopt, r.pairs, r.lps, "", seconds_since(t0)};
    if (r.status == solvers::ucp::UcpStatus::kSolvable && r.best_xTy) row.xTy = *r.best_xTy;
    if (r.status == solvers::ucp::UcpStatus::kSolvable && r.physical) {
      row.evidence = "c_n = " + tuple_text(r.physical->c_n.to_q()) +
                     ", q_dot = " + tuple_text(r.physical->q_dot.to_q()) +
                     (r.conditions && r.conditions->status == solvers::ucp::ConditionsStatus::kSatisfied
                          ? "; (2)-(10) hold exactly"
                          : "; (2)-(10) FAIL");
    } else if (r.status == solvers::ucp::UcpStatus::kJammed && r.proof) {
      const std::string cert = solvers::ucp::jammed_certificate(problem, *r.proof);
      const auto check = checker::check_ucp_certificate(exact::JsonInput::parse(cert, "certificate"));
      row.evidence = "certificate with " + std::to_string(r.proof->nodes) +
                     " nodes: " + (check.verdict == checker::CertificateVerdict::kValid ? "valid" : "INVALID");
    } else {
      row.evidence = r.reason;
    }
    rows.push_back({"Data Set " + std::to_string(ds), solvers::ucp::status_name(r.status),
                    row.xTy ? exact::to_string(*row.xTy) : "-", std::to_string(r.pairs), std::to_string(r.lps),
                    row.evidence, milliseconds_text(row.seconds)});
    d.answer.data_sets.push_back(row);
    d.say(demo_line(row));
  }
  d.rep.table({"problem", "verdict", "x^T y", "pairs", "LPs", "evidence", "time"}, rows);

  d.rep.paragraph(
      "A small Table 1: random problems of section 5 (point fingers on a workpiece), the paper's algorithm "
      "and its modification against the complete exact search.");
  std::vector<std::vector<std::string>> t1;
  std::mt19937_64 rng(1994);
  const int sizes[][3] = {{3, 10, 0}, {10, 10, 0}, {10, 20, 0}, {15, 12, 1}, {18, 8, 9}, {20, 10, 10}};
  for (const auto& s : sizes) {
    d.check_time();
    solvers::ucp::RandomProblemOptions ro;
    ro.nc = s[0];
    ro.mu_max = Q(s[1]) / 10;  // in lowest terms (Q(n, d) is not reduced)
    ro.abar_size = s[2];
    const auto problem = solvers::ucp::generate_random_problem(ro, rng);
    DemoRandomProblem row{s[0], s[2], ro.mu_max, {}};
    std::vector<std::string> cells{std::to_string(d.answer.table1.size() + 1), std::to_string(s[0]),
                                   "(0, " + exact::to_string(ro.mu_max) + ")", std::to_string(s[2])};
    std::size_t k = 0;
    for (auto m : {solvers::ucp::Method::kPaper, solvers::ucp::Method::kModified, solvers::ucp::Method::kComplete}) {
      solvers::ucp::UcpOptions opts;
      opts.method = m;
      const auto t0 = std::chrono::steady_clock::now();
      const auto r = solvers::ucp::solve_ucp(problem, opts);
      const DemoRandomProblem::Run run{m, r.status, r.pairs, r.lps, seconds_since(t0)};
      row.runs[k++] = run;
      cells.push_back(std::string(solvers::ucp::status_name(r.status)) + " (" + std::to_string(r.pairs) + " pairs, " +
                      std::to_string(r.lps) + " LPs, " + milliseconds_text(run.seconds) + ")");
    }
    t1.push_back(cells);
    d.answer.table1.push_back(row);
  }
  d.rep.table({"#", "n_c", "mu range", "|abar|", "paper", "modified", "complete (exact)"}, t1);
  d.say(demo_table1_line(d.answer.table1));
}

/// An assembly of the scenes folder (docs/formats.md section 3a), its row and picture: a planar file's stability
/// under the bodies' loads with a checked certificate, a quasistatic_scene's quasistatic problem.
DemoScene assembly_row(const std::string& name, const std::string& kind, const std::string& text,
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

/// A motion scene of the folder (docs/motion.md): its first steps of `simulate` (at most kDemoMotionSteps, to keep
/// the demo short; each step exact, as `simulate` makes them) and how the run stands after them.
constexpr long kDemoMotionSteps = 3;

DemoScene motion_row(const std::string& name, const std::string& text, const std::string& path) {
  const MotionInput in = parse_motion(text, path);
  SimulateOptions o;
  o.steps = std::min(kDemoMotionSteps, in.scene.steps);
  const Limited<SimulateAnswer> r = run_simulate(in, o);
  if (!r) return {name, "motion", "budget exhausted", r.limit().what};
  return {name, "motion", solvers::motion::run_status_name(run_status(*r)),
          std::to_string(steps_done(*r)) + " of its " + std::to_string(in.scene.steps) +
              " steps simulated (dt = " + exact::to_string(in.scene.dt) + "): " + run_reason(*r)};
}

/// A scene of the folder that is not one of the papers' examples: a planar scene gets its verdict under gravity
/// g = (0, -1, 0) with a checked certificate, its region picture and its finger pushes; a quasistatic or UCP
/// problem its status with the evidence; an assembly as assembly_row says, a motion scene as motion_row. A file that
/// cannot be read is listed with the reason.
DemoScene own_scene(const fs::path& path, HtmlReport& rep) {
  const std::string name = path.filename().string();
  try {
    const std::string text = exact::JsonInput::read_text(path.string());
    const auto in = exact::JsonInput::parse(text, path.string());
    if (geometry::is_assembly(in)) return assembly_row(name, in.at("kind").string(), text, path.string(), rep);
    if (geometry::is_spatial_scene(in)) {  // a body in space: its contact modes from rest, checked
      namespace sp = solvers::spatial;
      const sp::SpatialModeTree t = sp::spatial_modes(sp::spatial_model(geometry::read_spatial_scene(in)));
      const std::string certificate = sp::spatial_modes_certificate(text, t);  // the lines read it in place
      const auto check = checker::check_spatial_modes_certificate(checker::CertificateLines(certificate, "certificate"));
      return {name, "spatial", std::to_string(t.modes.size()) + " contact modes",
              std::string("certificate ") + (check.valid ? "valid" : "INVALID: " + check.reason)};
    }
    if (solvers::motion::is_motion_scene(in)) return motion_row(name, text, path.string());
    if (in.at("kind").string() == "planar") {
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
      return {name, "planar", solvers::verdict_name(r.verdict),
              std::string("certificate ") + (check.valid ? "valid" : "INVALID: " + check.reason)};
    }
    const auto problem = solvers::ucp::read_ucp_problem(in);
    const auto r = solvers::ucp::solve_ucp(problem, solvers::ucp::UcpOptions{});
    return {name, in.at("kind").string(), solvers::ucp::status_name(r.status), r.reason};
  } catch (const exact::InputError& e) {
    return {name, "-", "not read", e.what()};
  } catch (const exact::BudgetExceeded& e) {
    return {name, "-", "budget exhausted", e.what()};
  }
}

/// Every scene of the folder that is not one of the papers' examples (own_scene), in name order.
void own_scenes(const Demo& d) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(d.scenes))
    if (e.path().extension() == ".json" && !is_paper_scene(e.path().filename().string())) files.push_back(e.path());
  if (files.empty()) return;
  std::sort(files.begin(), files.end());
  d.rep.heading("Your scenes");
  d.rep.paragraph(
      "Planar scenes under gravity g = (0, -1, 0) (torque about the centre of mass); quasistatic "
      "problems solved exactly; motion scenes simulated for their first steps.");
  std::vector<std::vector<std::string>> rows;
  for (const auto& path : files) {
    d.check_time();
    const DemoScene row = own_scene(path, d.rep);
    rows.push_back({row.file, row.kind, row.verdict, row.evidence});
    d.answer.scenes_of_folder.push_back(row);
    d.say(demo_line(row));
  }
  d.rep.table({"file", "kind", "verdict", "evidence"}, rows);
}

DemoAnswer demo_answer(const DemoOptions& options, const DemoProgress& progress) {
  DemoAnswer answer;
  answer.scenes = options.scenes.empty() ? runtime::bundled_scenes_dir() : options.scenes;
  if (!fs::is_directory(answer.scenes)) throw exact::InputError(answer.scenes, "", "the scenes folder does not exist");
  create_output_dir(options.out);
  const auto t0 = std::chrono::steady_clock::now();
  HtmlReport rep("contactcert demo: both papers, exactly");
  rep.paragraph(
      "Every number below is exact (rational arithmetic); every 'no' carries a certificate that the "
      "independent checker verified in this run.");
  const Demo d{answer.scenes, rep, answer, progress, exact::Deadline::after(options.time_limit)};
  d.say(demo_header_line(answer.scenes));
  if (d.has({"bt2002_section4_disk.json", "bt2002_fig4a_lla.json", "bt2002_fig4b_nnn.json", "bt2002_fig4c_peg_lra.json",
             "bt2002_fig4d_peg_nn.json"}))
    wrench_cones(d);
  if (d.has({"bt2002_section7_disk.json"})) stability(d);
  if (d.has({"bt2002_section7_disk.json", "bt2002_fig10_pentagon_insert.json"})) insertion(d);
  if (d.has({"pang1994_dataset1.json", "pang1994_dataset2.json", "pang1994_dataset3.json", "pang1994_dataset4.json"}))
    quasistatic(d);
  own_scenes(d);
  answer.report = rep.write(options.out);
  answer.seconds = seconds_since(t0);
  d.say(demo_report_line(answer));
  return answer;
}

}  // namespace

Limited<DemoAnswer> run_demo(const DemoOptions& options, const DemoProgress& progress) {
  return with_limits(exact::Arith::kVerified, [&] { return demo_answer(options, progress); });
}

}  // namespace contactcert::queries
