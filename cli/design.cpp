// `contactcert design SCENE`: exact search for fixel placements (wrench cone paper, sections 7-10: "the intended
// use of our algorithm was fixture design"). Every choice of --fixels among the candidate boundary points is
// decided exactly (solvers/design/evaluate.h), the best --top K are reported with their figures and a
// certificate per verdict; under mpirun the placements are shared out dynamically (solvers/design/distribute.h).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/progress_line.h"
#include "cli/results.h"
#include "exact/deadline.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "exact/sha256.h"
#include "geometry/scene_json.h"
#include "queries/design_svg.h"
#include "queries/json_out.h"
#include "solvers/design/checkpoint.h"
#include "solvers/design/distribute.h"
#include "solvers/design/goal_certificate.h"

namespace contactcert::cli {
namespace {

using exact::InputError;
using exact::Q;
using solvers::DesignProblem;
using solvers::Placement;
using solvers::PlacementStatus;

/// Budget on the candidate set (each candidate is a few hundred bytes and one membership test per placement).
constexpr long kMaxCandidates = 100000;
/// Most placements reported with --top (each writes its scene and certificates).
constexpr int kMaxTop = 1000;
/// Largest --chunk-size (a chunk is the unit of work of one rank and of the checkpoint).
constexpr long kMaxChunkSize = 1000000000;

struct DesignOptions {
  CommonOptions common;
  std::string file;
  std::string candidates;
  std::string lattice;
  int fixels = 3;
  std::string stable_under;
  bool insertable = false;
  bool goal_push = false;
  std::string rank;
  int top = 5;
  std::string out = "contactcert-design";
  std::string checkpoint;
  long chunk_size = 16;
  long push_points = 120;
  std::string goal_wrench;
  long max_placements = 100000000;
  bool stable_under_given = false;
};

/// "fx,fy,tz;fx,fy,tz;..." (a list) or "cone:..." (generators of a cone).
solvers::WrenchSet parse_wrench_set(const std::string& text) {
  solvers::WrenchSet w;
  std::string list = text;
  w.kind = solvers::WrenchSet::Kind::kList;
  if (list.rfind("cone:", 0) == 0) {
    w.kind = solvers::WrenchSet::Kind::kCone;
    list = list.substr(5);
  }
  std::vector<exact::Vec<Q>> rows;
  std::size_t at = 0;
  while (at <= list.size()) {
    const std::size_t end = std::min(list.find(';', at), list.size());
    const std::string item = list.substr(at, end - at);
    if (item.find_first_not_of(" ") != std::string::npos) {
      exact::Vec<Q> g = parse_number_list(item, "--stable-under", 3);
      if (g.isZero()) throw InputError("command line", "--stable-under", "non-zero wrenches (got 0,0,0)");
      rows.push_back(g);
    }
    at = end + 1;
  }
  if (rows.empty())
    throw InputError("command line", "--stable-under",
                     "a non-empty wrench set: fx,fy,tz[;fx,fy,tz...] or cone:fx,fy,tz;... (got \"" + text + "\")");
  w.rows = exact::Mat<Q>(static_cast<Eigen::Index>(rows.size()), 3);
  for (std::size_t r = 0; r < rows.size(); ++r) w.rows.row(static_cast<Eigen::Index>(r)) = rows[r].transpose();
  return w;
}

/// Candidate points from --candidates N, --candidates FILE ({"candidates": [[x, y], ...]}) or --lattice PITCH.
std::vector<solvers::Candidate> read_candidates(const DesignOptions& o, const geometry::Shape& shape,
                                                std::string* how) {
  if (o.candidates.empty() == o.lattice.empty())
    throw InputError("command line", "--candidates", "exactly one of --candidates N|FILE and --lattice PITCH");
  if (!o.lattice.empty()) {
    const Q pitch = parse_number_list(o.lattice, "--lattice", 1)(0);
    if (sgn(pitch) <= 0) throw InputError("command line", "--lattice", "a pitch > 0");
    *how = "lattice of pitch " + exact::to_string(pitch);
    const long count = solvers::lattice_candidate_count(shape, pitch);  // before any candidate is stored
    if (count > kMaxCandidates)
      throw InputError("command line", "--lattice",
                       "a coarser pitch: " + exact::to_string(pitch) + " makes " + std::to_string(count) +
                           " candidates, more than the limit of " + std::to_string(kMaxCandidates));
    return solvers::lattice_candidates(shape, pitch);
  }
  if (o.candidates.find_first_not_of("0123456789") == std::string::npos) {
    if (o.candidates.size() > 6 || std::stol(o.candidates) > kMaxCandidates)
      throw InputError("command line", "--candidates", "at most " + std::to_string(kMaxCandidates) + " candidates");
    *how = "equally spaced in arc length";
    return solvers::arc_length_candidates(shape, std::stol(o.candidates));
  }
  *how = "from " + o.candidates;
  const exact::JsonInput root = exact::JsonInput::load(o.candidates);
  root.expect_keys({"candidates", "description"});
  const exact::JsonInput list = root.at("candidates");
  if (list.is_array() && list.size() > static_cast<std::size_t>(kMaxCandidates))  // before any per-point work
    list.fail("at most " + std::to_string(kMaxCandidates) + " candidates (found " + std::to_string(list.size()) + ")");
  std::vector<solvers::Candidate> out;
  std::set<std::pair<Q, Q>> seen;
  for (const exact::JsonInput& e : list.elements()) {
    const exact::Vec<Q> p = e.rational_vector(2);
    const solvers::CandidateCheck c = solvers::candidate_at(shape, {p(0), p(1)});
    if (!c.message.empty()) e.fail(c.message);
    if (!seen.emplace(p(0), p(1)).second) e.fail("distinct candidate points (this one is repeated)");
    out.push_back(c.candidate);
  }
  return out;
}

/// SHA-256 of the problem's description: the identity a checkpoint must match.
std::string problem_key(const std::string& scene_text, const DesignOptions& o, const DesignProblem& p) {
  std::string d = scene_text + "|" + std::to_string(p.fixels) + "|" + o.stable_under + "|" +
                  std::to_string(p.insertable) + std::to_string(p.goal_push) + "|" + solvers::rank_name(p.rank) + "|" +
                  std::to_string(o.top) + "|" + std::to_string(p.pushes.size()) + "|" + o.goal_wrench + "|";
  for (const auto& c : p.candidates) d += exact::to_string(c.point.x) + "," + exact::to_string(c.point.y) + ";";
  return exact::sha256_hex(d);
}

std::string duration_text(double s) {
  char buf[32];
  if (s < 120)
    std::snprintf(buf, sizeof buf, "%.0f s", s);
  else if (s < 7200)
    std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
  else
    std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  return buf;
}

json point_json(const geometry::Point2& p) { return json::array({exact::to_string(p.x), exact::to_string(p.y)}); }

json statistics_json(const solvers::DesignStatistics& s) {
  json j;
  j["evaluated"] = s.evaluated();
  for (int i = 0; i < solvers::kPlacementStatusCount; ++i)
    j[solvers::placement_status_name(static_cast<PlacementStatus>(i))] = s.by_status[static_cast<std::size_t>(i)];
  j["lps"] = s.lps;
  return j;
}

std::string statistics_text(const solvers::DesignStatistics& s) {
  std::string t = "evaluated " + std::to_string(s.evaluated());
  for (int i = 0; i < solvers::kPlacementStatusCount; ++i)
    t += ", " + std::string(solvers::placement_status_name(static_cast<PlacementStatus>(i))) + " " +
         std::to_string(s.by_status[static_cast<std::size_t>(i)]);
  return t + ", LPs " + std::to_string(s.lps);
}

/// One reported placement: re-decided with its evidence, files written, described.
json report_placement(const DesignProblem& problem, const solvers::CandidateSymmetry& symmetry, const DesignOptions& o,
                      std::size_t position, const solvers::Ranked& r, std::string* caption, std::ostream& text) {
  solvers::PlacementEvidence ev;
  const solvers::Evaluation again = solvers::evaluate_placement(problem, symmetry, r.placement, &ev);
  if (again.status != PlacementStatus::kAccepted || again.figure != r.figure)
    throw std::logic_error("design: a ranked placement re-decides differently");
  const std::string stem = o.out + "/placement_" + std::to_string(position);
  const std::string scene_text = solvers::placement_scene_text(
      problem, r.placement, "design placement " + std::to_string(position) + " of " + o.file);
  const geometry::PlanarScene placement = solvers::placement_scene(problem, r.placement);
  write_text_file(stem + ".json", scene_text);
  json j;
  j["rank"] = position;
  j["candidates"] = r.placement;
  json points = json::array(), normals = json::array();
  std::string where;
  for (int i : r.placement) {
    const auto& c = problem.candidates[static_cast<std::size_t>(i)];
    points.push_back(point_json(c.point));
    normals.push_back(point_json(c.normal));
    where += (where.empty() ? "" : " ") + point_text(c.point);
  }
  j["points"] = points;
  j["normals"] = normals;
  j["figure"] = exact_json(r.figure);
  j["figure_approx"] = r.figure.get_d();
  j["scene_file"] = stem + ".json";
  std::string cand;
  for (int i : r.placement) cand += (cand.empty() ? "" : ", ") + std::to_string(i);
  text << "  " << position << ". candidates " << cand << " at " << where << "\n     "
       << solvers::rank_name(problem.rank) << " " << exact::to_string(r.figure) << " (~" << r.figure.get_d() << ")";
  char approx[32];
  std::snprintf(approx, sizeof approx, "%.4g", r.figure.get_d());
  *caption = "candidates " + cand + ": " + (problem.rank == solvers::Rank::kMargin ? "margin^2 " : "goal ") + approx;
  if (problem.rank == solvers::Rank::kMargin && !ev.margins.empty()) {
    std::size_t worst = 0;
    for (std::size_t m = 1; m < ev.margins.size(); ++m)
      if (ev.margins[m].squared_radius < ev.margins[worst].squared_radius) worst = m;
    text << " = squared stability margin of wrench " << worst + 1 << ", nearest: " << ev.margins[worst].nearest;
    j["nearest"] = ev.margins[worst].nearest;
  }
  text << "\n";
  json verdicts = json::array();
  for (std::size_t w = 0; w < ev.stability.size(); ++w) {
    const exact::Vec<Q> g = problem.wrenches.rows.row(static_cast<Eigen::Index>(w)).transpose();
    const std::string cert = stem + "_wrench_" + std::to_string(w + 1) + ".cert.json";
    write_text_file(cert, stability_certificate_file(scene_text, placement, g, ev.stability[w]));
    json v = {
        {"wrench", exact_json(g)}, {"verdict", solvers::verdict_name(ev.stability[w].verdict)}, {"certificate", cert}};
    if (w < ev.margins.size()) v["squared_margin"] = exact_json(ev.margins[w].squared_radius);
    verdicts.push_back(v);
    text << "     wrench " << tuple_text(g) << ": " << solvers::verdict_name(ev.stability[w].verdict)
         << ", certificate " << cert << "\n";
  }
  if (problem.wrenches.kind == solvers::WrenchSet::Kind::kCone)
    text << "     the cone of these generators meets no moving mode's wrench cone (exact intersection)\n";
  j["verdicts"] = verdicts;
  if (problem.insertable) {
    Q frac(ev.goal_pushes, static_cast<long>(problem.pushes.size()));
    frac.canonicalize();
    std::optional<geometry::Point2> push;
    if (ev.goal_push_point >= 0) push = problem.pushes[static_cast<std::size_t>(ev.goal_push_point)].point;
    const std::string goal_cert = stem + "_goal.cert.json";
    write_text_file(goal_cert, solvers::goal_certificate(scene_text, placement, ev.goal_witness, push));
    j["goal_witness"] = primitive_json(ev.goal_witness);
    if (push) j["goal_push_point"] = point_json(*push);
    j["goal_pushes"] = ev.goal_pushes;
    j["goal_fraction"] = exact_json(frac);
    j["goal_certificate"] = goal_cert;
    text << "     G_goal non-empty, e.g. g = " << tuple_text(exact::primitive(ev.goal_witness))
         << (push ? " (the push at " + point_text(*push) + ")" : std::string()) << "; pushes at " << ev.goal_pushes
         << " of " << problem.pushes.size() << " push points seat it (" << exact::to_string(frac) << "), certificate "
         << goal_cert << "\n";
    if (problem.goal_wrench.size() > 0) {
      const std::string wrench_cert = stem + "_goal_wrench.cert.json";
      write_text_file(wrench_cert, solvers::goal_certificate(scene_text, placement, problem.goal_wrench, {}));
      j["goal_wrench_certificate"] = wrench_cert;
      text << "     G_goal contains " << tuple_text(problem.goal_wrench) << ", certificate " << wrench_cert << "\n";
    }
  }
  text << "     scene: " << stem << ".json\n";
  return j;
}

DesignProblem build_problem(const DesignOptions& o, const std::string& scene_text, std::string* how) {
  const geometry::PlanarScene scene = geometry::read_planar_scene(exact::JsonInput::parse(scene_text, o.file));
  if (exact::parse_arith(o.common.arith) == exact::Arith::kFloat)
    throw InputError("command line", "--arith", "design is decided exactly (use exact or verified)");
  DesignProblem p;
  p.workpiece = scene.workpiece;
  p.mu_s = scene.fixels.front().mu_s;
  p.mu_k = scene.fixels.front().mu_k;
  p.fixels = o.fixels;
  p.goal_push = o.goal_push;
  p.insertable = o.insertable || !o.goal_wrench.empty() || o.goal_push;
  if (!o.goal_wrench.empty()) p.goal_wrench = parse_number_list(o.goal_wrench, "--goal-wrench", 3);
  if (o.stable_under_given) p.wrenches = parse_wrench_set(o.stable_under);
  if (!o.stable_under_given && !p.insertable)
    throw InputError("command line", "--stable-under", "a requirement: --stable-under W and/or --insertable");
  const std::string rank = o.rank.empty() ? (o.stable_under_given ? "margin" : "goal-fraction") : o.rank;
  p.rank = rank == "margin" ? solvers::Rank::kMargin : solvers::Rank::kGoalFraction;
  if (p.rank == solvers::Rank::kMargin && !o.stable_under_given)
    throw InputError("command line", "--rank", "--rank margin needs --stable-under W");
  if (p.rank == solvers::Rank::kGoalFraction && !p.insertable)
    throw InputError("command line", "--rank", "--rank goal-fraction needs --insertable");
  p.candidates = read_candidates(o, p.workpiece.shape, how);
  if (static_cast<long>(p.candidates.size()) > kMaxCandidates)
    throw InputError(o.candidates.empty() ? "command line" : o.candidates,
                     o.candidates.empty() ? "--lattice" : "$.candidates",
                     "at most " + std::to_string(kMaxCandidates) + " candidates");
  if (p.candidates.size() < 2 || static_cast<int>(p.candidates.size()) < p.fixels)
    throw InputError(o.candidates.find_first_not_of("0123456789") == std::string::npos ? "command line" : o.candidates,
                     o.candidates.empty() ? "--lattice" : "--candidates",
                     "at least " + std::to_string(std::max(2, p.fixels)) + " candidate points (got " +
                         std::to_string(p.candidates.size()) + ")");
  if (p.insertable) p.pushes = solvers::arc_length_candidates(p.workpiece.shape, o.push_points);
  return p;
}

/// The root's bookkeeping while chunks finish: merged result, checkpoint, progress line, budgets.
struct RootState {
  solvers::DesignCheckpoint checkpoint;
  long total = 0;
  long chunks_before = 0, chunks_now = 0;          ///< chunks done by earlier runs / this run
  long placements_before = 0, placements_now = 0;  ///< their placements
  exact::Deadline deadline;
  long max_placements = 0;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now(), last_write = start;
  bool budget_hit = false;
  long placements_done() const { return placements_before + placements_now; }
};

/// The report of a finished search: the top K re-decided with their evidence, files, text or JSON.
int report_design(const DesignOptions& o, const DesignProblem& problem, const solvers::CandidateSymmetry& symmetry,
                  const solvers::ChunkResult& result, long total, const std::string& how) {
  const long n = static_cast<long>(problem.candidates.size());
  std::ostringstream text;
  json top = json::array();
  std::vector<std::string> captions;
  for (std::size_t i = 0; i < result.top.items().size(); ++i) {
    std::string caption;
    top.push_back(report_placement(problem, symmetry, o, i + 1, result.top.items()[i], &caption, text));
    captions.push_back(caption);
  }
  const std::string svg = o.out + "/design.svg";
  write_text_file(svg,
                  design_svg(problem, result.top.items(), captions,
                             "contactcert design " + o.file + ": best " + std::to_string(result.top.items().size()) +
                                 " placements by " + solvers::rank_name(problem.rank)));
  const std::string requirement =
      (problem.wrenches.kind == solvers::WrenchSet::Kind::kNone ? std::string()
                                                                : "strongly stable under " + o.stable_under) +
      (problem.insertable ? std::string(problem.wrenches.kind == solvers::WrenchSet::Kind::kNone ? "" : ", ") +
                                "insertable (G_goal non-empty" +
                                (problem.goal_wrench.size() ? ", containing " + tuple_text(problem.goal_wrench) : "") +
                                (problem.goal_push ? ", containing a push at one of " +
                                                         std::to_string(problem.pushes.size()) + " push points"
                                                   : "") +
                                ")"
                          : "");
  if (o.common.json) {
    json j;
    j["scene"] = o.file;
    j["fixels"] = problem.fixels;
    json cands = json::array();
    for (const auto& c : problem.candidates) cands.push_back(point_json(c.point));
    j["candidates"] = {{"source", how}, {"count", n}, {"points", cands}};
    j["requirements"] = {{"stable_under", o.stable_under_given ? json(o.stable_under) : json(nullptr)},
                         {"insertable", problem.insertable},
                         {"goal_wrench", problem.goal_wrench.size() ? exact_json(problem.goal_wrench) : json(nullptr)},
                         {"goal_push", problem.goal_push}};
    j["rank"] = solvers::rank_name(problem.rank);
    j["placements"] = total;
    j["symmetries"] = symmetry.permutations.size();
    j["statistics"] = statistics_json(result.statistics);
    j["top"] = top;
    j["svg"] = svg;
    std::cout << j.dump() << "\n";
    return 0;
  }
  std::cout << "design " << o.file << ": " << problem.fixels << " fixels from " << n << " candidates (" << how << "), "
            << requirement << ", ranked by " << solvers::rank_name(problem.rank) << "\n"
            << "  " << total << " placements, " << symmetry.permutations.size() << " non-trivial symmetries; "
            << statistics_text(result.statistics) << "\n";
  if (result.top.items().empty())
    std::cout << "  no placement meets the requirements\n";
  else
    std::cout << "best " << result.top.items().size() << ":\n" << text.str();
  std::cout << "  picture: " << svg << "\n";
  return 0;
}

/// The checkpoint to resume from (root), decided on the root and shared: 0 when the search may start (from
/// `*resumed` if set), else the exit code every rank ends with (2: the root prints the refusal, naming the file and
/// field); the others learn of it through the broadcast instead of waiting for work that never comes.
int resume(const DesignOptions& o, const DesignProblem& problem, const solvers::CandidateSymmetry& symmetry,
           solvers::Distributor& dist, long total, const std::string& key,
           std::optional<solvers::DesignCheckpoint>* resumed) {
  std::exception_ptr failure;
  std::string refusal;
  int code = 0;
  if (dist.is_root() && !o.checkpoint.empty()) {
    try {
      *resumed = solvers::read_checkpoint(o.checkpoint, key, problem, symmetry, o.chunk_size, total,
                                          static_cast<std::size_t>(o.top));
    } catch (const InputError& e) {
      refusal = std::string("contactcert: ") + e.what() + "\n";
      code = 2;
    } catch (...) {
      failure = std::current_exception();
      code = 1;
    }
  }
  code = std::stoi(dist.from_root(std::to_string(code)));
  if (failure) std::rethrow_exception(failure);
  std::fputs(refusal.c_str(), stderr);  // one write: under mpirun, lines of other ranks cannot split it
  return code;
}

/// The distributed search and, on the root, the report.
int search(const DesignOptions& o, const DesignProblem& problem, const solvers::CandidateSymmetry& symmetry,
           solvers::Distributor& dist, long total, const std::string& key, const std::string& how,
           std::optional<solvers::DesignCheckpoint> resumed) {
  const std::size_t K = static_cast<std::size_t>(o.top);
  const long chunks = solvers::chunk_count(total, o.chunk_size);
  RootState st;
  st.total = total;
  st.deadline = exact::Deadline::after(o.common.time_limit);
  st.max_placements = o.max_placements;
  st.checkpoint =
      resumed ? std::move(*resumed) : solvers::DesignCheckpoint{key, o.chunk_size, chunks, {}, {solvers::TopK(K), {}}};
  for (const auto& [first, last] : st.checkpoint.done.ranges()) st.chunks_before += last - first + 1;
  st.placements_before = solvers::placements_in(st.checkpoint.done, o.chunk_size, total);
  long cursor = 0;  // chunks are handed out in increasing order, skipping those done before
  auto next = [&]() -> std::optional<long> {
    cursor = st.checkpoint.done.next_missing(cursor);
    if (cursor >= chunks) return std::nullopt;
    return cursor++;
  };
  ProgressLine progress("design " + o.file);
  auto save = [&] {
    if (!o.checkpoint.empty()) solvers::write_checkpoint(o.checkpoint, st.checkpoint);
    st.last_write = std::chrono::steady_clock::now();
  };
  auto record = [&](long chunk, const std::string& text) {
    st.checkpoint.result.merge(solvers::parse_chunk_result(text, K));
    st.checkpoint.done.insert(chunk);
    ++st.chunks_now;
    st.placements_now += solvers::chunk_length(chunk, o.chunk_size, total);
    if (seconds_since(st.last_write) >= 1.0) save();
  };
  auto keep_going = [&] {
    const double t = seconds_since(st.start);
    if (progress.enabled() && t > 0) {
      const double rate = static_cast<double>(st.placements_now) / t;
      const long left = total - st.placements_done();
      progress.update(std::to_string(st.placements_done()) + " of " + std::to_string(total) + " placements, " +
                      std::to_string(static_cast<long>(rate)) + "/s on " + std::to_string(dist.size()) + " ranks" +
                      (rate > 0 ? ", about " + duration_text(static_cast<double>(left) / rate) + " left" : ""));
    }
    if (st.deadline.expired() || st.placements_now >= st.max_placements) st.budget_hit = true;
    return !st.budget_hit;
  };
  auto work = [&](long chunk, const std::function<bool()>& between) -> std::optional<std::string> {
    bool complete = false;
    const solvers::ChunkResult r =
        solvers::run_chunk(problem, symmetry, chunk, o.chunk_size, total, K, between, &complete);
    if (!complete) return std::nullopt;
    return solvers::chunk_result_text(r);
  };
  const bool ran_out = dist.run(next, work, record, keep_going);
  if (!dist.is_root()) return ran_out ? 0 : 3;
  const bool finished = ran_out || st.checkpoint.done.next_missing(0) >= chunks;  // a budget met by the last chunk
  progress.finish();
  save();
  const solvers::ChunkResult& result = st.checkpoint.result;
  if (!finished) {
    std::cerr << "contactcert: design " << o.file << ": "
              << (st.deadline.expired() ? st.deadline.reached_text() : "placement budget --max-placements reached")
              << " (covered: " << st.placements_done() << " of " << total << " placements in "
              << (st.chunks_before + st.chunks_now) << " of " << chunks << " chunks; "
              << statistics_text(result.statistics)
              << (o.checkpoint.empty() ? "" : "; resume with --checkpoint " + o.checkpoint) << ")\n";
    return 3;
  }
  return report_design(o, problem, symmetry, result, total, how);
}

int run_design(const DesignOptions& o) {
  const std::string scene_text = exact::JsonInput::read_text(o.file);
  std::string how;
  const DesignProblem problem = build_problem(o, scene_text, &how);
  const long n = static_cast<long>(problem.candidates.size());
  const long total = solvers::placement_count(n, problem.fixels);
  if (total < 0) throw InputError("command line", "--candidates", "fewer candidates (C(N, k) exceeds 2^62)");
  const solvers::CandidateSymmetry symmetry = solvers::candidate_symmetry(problem);
  const std::string key = problem_key(scene_text, o, problem);
  if (!o.out.empty()) create_output_dir(o.out);

  const std::unique_ptr<solvers::Distributor> dist = solvers::make_distributor();
  dist->agree(key);
  std::optional<solvers::DesignCheckpoint> resumed;
  if (const int code = resume(o, problem, symmetry, *dist, total, key, &resumed)) return code;
  try {
    return search(o, problem, symmetry, *dist, total, key, how, std::move(resumed));
  } catch (const exact::InputError& e) {
    dist->abort_all(e.what(), 2);
    throw;
  } catch (const exact::BudgetExceeded& e) {
    dist->abort_all(std::string("budget exceeded: ") + e.what() + " (covered: " + e.covered + ")", 3);
    throw;
  } catch (const std::exception& e) {
    dist->abort_all(std::string("internal error: ") + e.what(), 1);
    throw;
  }
}

}  // namespace

void register_design(CLI::App& app, Action& action) {
  auto o = std::make_shared<DesignOptions>();
  CLI::App* sub =
      app.add_subcommand("design", "Fixture design: the best exact fixel placements among candidate points");
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Planar scene: the workpiece and mu (its fixels are otherwise ignored)")->required();
  sub->add_option("--candidates", o->candidates,
                  "N points equally spaced in arc length, or a JSON file {\"candidates\": [[x, y], ...]}");
  sub->add_option("--lattice", o->lattice,
                  "Candidates at the lattice points (i p, j p) on the boundary (modular fixturing)");
  sub->add_option("--fixels", o->fixels, "Fixels per placement: 2 or 3 (Table 5 covers three)")
      ->check(whole_number(2, 3))
      ->default_str("3");
  CLI::Option* stable = sub->add_option(
      "--stable-under", o->stable_under,
      "Wrenches to hold strongly stable: fx,fy,tz[;...] (a list) or cone:fx,fy,tz;... (a cone's generators)");
  sub->add_flag("--insertable", o->insertable, "Require a non-empty G_goal (sensorless insertion, Table 5)");
  sub->add_option(
         "--rank", o->rank,
         "margin (least squared stability margin) or goal-fraction (share of the push points whose push is in G_goal)")
      ->check(CLI::IsMember({"margin", "goal-fraction"}));
  sub->add_option("--top", o->top, "Report the K best placements")->check(whole_number(1, kMaxTop))->default_str("5");
  sub->add_option("--out", o->out, "Folder of the placement scenes, certificates and design.svg")
      ->default_str("contactcert-design");
  sub->add_option("--checkpoint", o->checkpoint, "Resume from and save progress to this file (atomic writes)");
  sub->add_option("--goal-wrench", o->goal_wrench, "Require this wrench fx,fy,tz in G_goal (implies --insertable)");
  sub->add_flag("--goal-push", o->goal_push,
                "Require a frictionless finger push at one of the --push-points in G_goal (implies --insertable)");
  sub->add_option("--push-points", o->push_points,
                  "With --insertable: the goal fraction and --goal-push use the pushes at M points equally spaced in "
                  "arc length")
      ->check(whole_number<long>(1, kMaxCandidates))
      ->default_str("120");
  sub->add_option("--chunk-size", o->chunk_size, "Placements per unit of work handed to a rank")
      ->check(whole_number<long>(1, kMaxChunkSize))
      ->default_str("16");
  sub->add_option("--max-placements", o->max_placements,
                  "Budget: placements evaluated in this run, checked between chunks (exit 3 beyond)")
      ->check(whole_number<long>(1, std::numeric_limits<long>::max()))
      ->default_str("100000000");
  sub->callback([o, stable, &action] {
    o->stable_under_given = stable->count() > 0;
    action = [o] { return run_design(*o); };
  });
}

}  // namespace contactcert::cli
