#include "queries/design_query.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <set>
#include <stdexcept>

#include "exact/deadline.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/nearest_double.h"
#include "exact/rational_text.h"
#include "exact/sha256.h"
#include "queries/design_svg.h"
#include "queries/stability_certificate_file.h"
#include "solvers/design/checkpoint.h"
#include "solvers/design/goal_certificate.h"

namespace contactcert::queries {
namespace {

using exact::InputError;
using exact::Q;
using solvers::DesignProblem;
using solvers::PlacementStatus;

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

/// Candidate points from `candidates` N, `candidates` FILE ({"candidates": [[x, y], ...]}) or `lattice` PITCH.
std::vector<solvers::Candidate> read_candidates(const DesignOptions& o, const geometry::Shape& shape,
                                                std::string* how) {
  if (o.candidates.empty() == o.lattice.empty())
    throw InputError("command line", "--candidates", "exactly one of --candidates N|FILE and --lattice PITCH");
  if (!o.lattice.empty()) {
    const Q pitch = parse_number_list(o.lattice, "--lattice", 1)(0);
    if (sgn(pitch) <= 0) throw InputError("command line", "--lattice", "a pitch > 0");
    *how = "lattice of pitch " + exact::to_string(pitch);
    const long count = solvers::lattice_candidate_count(shape, pitch);  // before any candidate is stored
    if (count > kMaxDesignCandidates)
      throw InputError("command line", "--lattice",
                       "a coarser pitch: " + exact::to_string(pitch) + " makes " + std::to_string(count) +
                           " candidates, more than the limit of " + std::to_string(kMaxDesignCandidates));
    return solvers::lattice_candidates(shape, pitch);
  }
  if (o.candidates.find_first_not_of("0123456789") == std::string::npos) {
    if (o.candidates.size() > 6 || std::stol(o.candidates) > kMaxDesignCandidates)
      throw InputError("command line", "--candidates",
                       "at most " + std::to_string(kMaxDesignCandidates) + " candidates");
    *how = "equally spaced in arc length";
    return solvers::arc_length_candidates(shape, std::stol(o.candidates));
  }
  *how = "from " + o.candidates;
  const exact::JsonInput root = exact::JsonInput::load(o.candidates);
  root.expect_keys({"candidates", "description"});
  const exact::JsonInput list = root.at("candidates");
  if (list.is_array() && list.size() > static_cast<std::size_t>(kMaxDesignCandidates))  // before any per-point work
    list.fail("at most " + std::to_string(kMaxDesignCandidates) + " candidates (found " + std::to_string(list.size()) +
              ")");
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

DesignProblem build_problem(const DesignOptions& o, const geometry::PlanarScene& scene, std::string* how) {
  refuse_float(o.common.arith, "design is decided exactly (use exact or verified)");
  DesignProblem p;
  p.workpiece = scene.workpiece;
  p.mu_s = scene.fixels.front().mu_s;
  p.mu_k = scene.fixels.front().mu_k;
  p.fixels = o.fixels;
  p.goal_push = o.goal_push;
  p.insertable = o.insertable || !o.goal_wrench.empty() || o.goal_push;
  if (!o.goal_wrench.empty()) p.goal_wrench = parse_number_list(o.goal_wrench, "--goal-wrench", 3);
  if (o.stable_under) p.wrenches = parse_wrench_set(*o.stable_under);
  if (!o.stable_under && !p.insertable)
    throw InputError("command line", "--stable-under", "a requirement: --stable-under W and/or --insertable");
  p.rank = o.rank.value_or(o.stable_under ? solvers::Rank::kMargin : solvers::Rank::kGoalFraction);
  if (p.rank == solvers::Rank::kMargin && !o.stable_under)
    throw InputError("command line", "--rank", "--rank margin needs --stable-under W");
  if (p.rank == solvers::Rank::kGoalFraction && !p.insertable)
    throw InputError("command line", "--rank", "--rank goal-fraction needs --insertable");
  p.candidates = read_candidates(o, p.workpiece.shape, how);
  if (static_cast<long>(p.candidates.size()) > kMaxDesignCandidates)
    throw InputError(o.candidates.empty() ? "command line" : o.candidates,
                     o.candidates.empty() ? "--lattice" : "$.candidates",
                     "at most " + std::to_string(kMaxDesignCandidates) + " candidates");
  if (p.candidates.size() < 2 || static_cast<int>(p.candidates.size()) < p.fixels)
    throw InputError(o.candidates.find_first_not_of("0123456789") == std::string::npos ? "command line" : o.candidates,
                     o.candidates.empty() ? "--lattice" : "--candidates",
                     "at least " + std::to_string(std::max(2, p.fixels)) + " candidate points (got " +
                         std::to_string(p.candidates.size()) + ")");
  if (p.insertable) p.pushes = solvers::arc_length_candidates(p.workpiece.shape, o.push_points);
  return p;
}

/// SHA-256 of the problem's description: the identity a checkpoint must match.
std::string problem_key(const std::string& scene_text, const DesignOptions& o, const DesignProblem& p) {
  std::string d = scene_text + "|" + std::to_string(p.fixels) + "|" + o.stable_under.value_or("") + "|" +
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

/// One reported placement: re-decided with its evidence, its scene and certificates written under `stem`.
PlacementReport report_placement(const DesignProblem& problem, const solvers::CandidateSymmetry& symmetry,
                                 const std::string& scene_name, const std::string& out, std::size_t position,
                                 const solvers::Ranked& r) {
  PlacementReport rep{position, r, {}, out + "/placement_" + std::to_string(position)};
  const solvers::Evaluation again = solvers::evaluate_placement(problem, symmetry, r.placement, &rep.evidence);
  if (again.status != PlacementStatus::kAccepted || again.figure != r.figure)
    throw std::logic_error("design: a ranked placement re-decides differently");
  const solvers::PlacementEvidence& ev = rep.evidence;
  const std::string scene_text = solvers::placement_scene_text(
      problem, r.placement, "design placement " + std::to_string(position) + " of " + scene_name);
  const geometry::PlanarScene placement = solvers::placement_scene(problem, r.placement);
  write_text_file(rep.stem + ".json", scene_text);
  for (std::size_t w = 0; w < ev.stability.size(); ++w) {
    const exact::Vec<Q> g = problem.wrenches.rows.row(static_cast<Eigen::Index>(w)).transpose();
    write_text_file(rep.stem + "_wrench_" + std::to_string(w + 1) + ".cert.json",
                    stability_certificate_file(scene_text, placement, g, ev.stability[w]));
  }
  if (problem.insertable) {
    std::optional<geometry::Point2> push;
    if (ev.goal_push_point >= 0) push = problem.pushes[static_cast<std::size_t>(ev.goal_push_point)].point;
    write_text_file(rep.stem + "_goal.cert.json",
                    solvers::goal_certificate(scene_text, placement, ev.goal_witness, push));
    if (problem.goal_wrench.size() > 0)
      write_text_file(rep.stem + "_goal_wrench.cert.json",
                      solvers::goal_certificate(scene_text, placement, problem.goal_wrench, {}));
  }
  return rep;
}

/// The root's bookkeeping while chunks finish: merged result, checkpoint, progress, budgets.
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

/// What the search covers: the problem with its symmetry, its size and identity.
struct DesignPlan {
  DesignProblem problem;
  std::string how;
  long total = 0;
  solvers::CandidateSymmetry symmetry;
  std::string key;
};

/// The checkpoint to resume from (root), decided on the root and shared: the run is refused on every rank if the
/// root refuses it (the root's message names the file and field); the others learn of it through the broadcast
/// instead of waiting for work that never comes.
std::optional<DesignRun> resume(const DesignOptions& o, const DesignPlan& plan, solvers::Distributor& dist,
                                std::optional<solvers::DesignCheckpoint>* resumed) {
  std::exception_ptr failure;
  DesignRun refused{DesignStatus::kRefused, "", std::nullopt};
  int code = 0;
  if (dist.is_root() && !o.checkpoint.empty()) {
    try {
      *resumed = solvers::read_checkpoint(o.checkpoint, plan.key, plan.problem, plan.symmetry, o.chunk_size, plan.total,
                                          static_cast<std::size_t>(o.top));
    } catch (const InputError& e) {
      refused.refusal = e.what();
      code = 2;
    } catch (...) {
      failure = std::current_exception();
      code = 1;
    }
  }
  code = std::stoi(dist.from_root(std::to_string(code)));
  if (failure) std::rethrow_exception(failure);
  if (code != 0) return refused;
  return std::nullopt;
}

/// The distributed search and, on the root, the report.
Limited<DesignRun> search(const SceneInput& in, const DesignOptions& o, const DesignPlan& plan,
                          solvers::Distributor& dist, std::optional<solvers::DesignCheckpoint> resumed,
                          const DesignProgress& progress) {
  const std::size_t K = static_cast<std::size_t>(o.top);
  const long total = plan.total;
  const long chunks = solvers::chunk_count(total, o.chunk_size);
  RootState st;
  st.total = total;
  st.deadline = o.common.deadline();
  st.max_placements = o.max_placements;
  st.checkpoint = resumed ? std::move(*resumed)
                          : solvers::DesignCheckpoint{plan.key, o.chunk_size, chunks, {}, {solvers::TopK(K), {}}};
  for (const auto& [first, last] : st.checkpoint.done.ranges()) st.chunks_before += last - first + 1;
  st.placements_before = solvers::placements_in(st.checkpoint.done, o.chunk_size, total);
  long cursor = 0;  // chunks are handed out in increasing order, skipping those done before
  auto next = [&]() -> std::optional<long> {
    cursor = st.checkpoint.done.next_missing(cursor);
    if (cursor >= chunks) return std::nullopt;
    return cursor++;
  };
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
    if (progress && t > 0) {
      const double rate = static_cast<double>(st.placements_now) / t;
      const long left = total - st.placements_done();
      progress(std::to_string(st.placements_done()) + " of " + std::to_string(total) + " placements, " +
               std::to_string(static_cast<long>(rate)) + "/s on " + std::to_string(dist.size()) + " ranks" +
               (rate > 0 ? ", about " + duration_text(static_cast<double>(left) / rate) + " left" : ""));
    }
    if (st.deadline.expired() || st.placements_now >= st.max_placements) st.budget_hit = true;
    return !st.budget_hit;
  };
  solvers::InsertionCones<exact::Q> cones;  // insertion cones shared across this run's placements
  auto work = [&](long chunk, const std::function<bool()>& between) -> std::optional<std::string> {
    bool complete = false;
    const solvers::ChunkResult r =
        solvers::run_chunk(plan.problem, plan.symmetry, chunk, o.chunk_size, total, K, between, &complete, &cones);
    if (!complete) return std::nullopt;
    return solvers::chunk_result_text(r);
  };
  const bool ran_out = dist.run(next, work, record, keep_going);
  if (!dist.is_root())
    return DesignRun{ran_out ? DesignStatus::kWorkerFinished : DesignStatus::kLimit, "", std::nullopt};
  const bool finished = ran_out || st.checkpoint.done.next_missing(0) >= chunks;  // a budget met by the last chunk
  save();
  const solvers::ChunkResult& result = st.checkpoint.result;
  if (!finished)
    return Limit{"design " + in.name + ": " +
                     (st.deadline.expired() ? st.deadline.reached_text() : "placement budget --max-placements reached"),
                 std::to_string(st.placements_done()) + " of " + std::to_string(total) + " placements in " +
                     std::to_string(st.chunks_before + st.chunks_now) + " of " + std::to_string(chunks) + " chunks; " +
                     statistics_text(result.statistics) +
                     (o.checkpoint.empty() ? "" : "; resume with --checkpoint " + o.checkpoint),
                 Limit::Kind::kStopped};
  DesignReport rep{in.name,
                   o.stable_under,
                   plan.problem,
                   plan.how,
                   total,
                   plan.symmetry.permutations.size(),
                   result.statistics,
                   {},
                   o.out + "/design.svg"};
  std::vector<std::string> captions;
  for (std::size_t i = 0; i < result.top.items().size(); ++i) {
    rep.top.push_back(report_placement(plan.problem, plan.symmetry, in.name, o.out, i + 1, result.top.items()[i]));
    captions.push_back(placement_caption(plan.problem, result.top.items()[i]));
  }
  write_text_file(rep.svg,
                  design_svg(plan.problem, result.top.items(), captions,
                             "contactcert design " + in.name + ": best " + std::to_string(result.top.items().size()) +
                                 " placements by " + solvers::rank_name(plan.problem.rank)));
  return DesignRun{DesignStatus::kFinished, "", std::move(rep)};
}

json placement_json(const DesignReport& report, const PlacementReport& p) {
  const DesignProblem& problem = report.problem;
  const solvers::PlacementEvidence& ev = p.evidence;
  json j;
  j["rank"] = p.position;
  j["candidates"] = p.ranked.placement;
  json points = json::array(), normals = json::array();
  for (int i : p.ranked.placement) {
    const auto& c = problem.candidates[static_cast<std::size_t>(i)];
    points.push_back(point_json(c.point));
    normals.push_back(point_json(c.normal));
  }
  j["points"] = points;
  j["normals"] = normals;
  j["figure"] = exact_json(p.ranked.figure);
  j["figure_approx"] = exact::nearest_double(p.ranked.figure);
  j["scene_file"] = p.stem + ".json";
  if (problem.rank == solvers::Rank::kMargin && !ev.margins.empty())
    j["nearest"] = ev.margins[worst_margin(ev)].nearest;
  json verdicts = json::array();
  for (std::size_t w = 0; w < ev.stability.size(); ++w) {
    const exact::Vec<Q> g = problem.wrenches.rows.row(static_cast<Eigen::Index>(w)).transpose();
    json v = {{"wrench", exact_json(g)},
              {"verdict", solvers::verdict_name(ev.stability[w].verdict)},
              {"certificate", p.stem + "_wrench_" + std::to_string(w + 1) + ".cert.json"}};
    if (w < ev.margins.size()) v["squared_margin"] = exact_json(ev.margins[w].squared_radius);
    verdicts.push_back(v);
  }
  j["verdicts"] = verdicts;
  if (problem.insertable) {
    j["goal_witness"] = primitive_json(ev.goal_witness);
    if (ev.goal_push_point >= 0)
      j["goal_push_point"] = point_json(problem.pushes[static_cast<std::size_t>(ev.goal_push_point)].point);
    j["goal_pushes"] = ev.goal_pushes;
    j["goal_fraction"] = exact_json(goal_fraction(problem, ev));
    j["goal_certificate"] = p.stem + "_goal.cert.json";
    if (problem.goal_wrench.size() > 0) j["goal_wrench_certificate"] = p.stem + "_goal_wrench.cert.json";
  }
  return j;
}

}  // namespace

solvers::Rank parse_rank(const std::string& text, const std::string& field) {
  for (const solvers::Rank r : {solvers::Rank::kMargin, solvers::Rank::kGoalFraction})
    if (text == solvers::rank_name(r)) return r;
  throw InputError("command line", field, "margin or goal-fraction, found " + exact::quoted_excerpt(text));
}

std::size_t worst_margin(const solvers::PlacementEvidence& ev) {
  std::size_t worst = 0;
  for (std::size_t m = 1; m < ev.margins.size(); ++m)
    if (ev.margins[m].squared_radius < ev.margins[worst].squared_radius) worst = m;
  return worst;
}

exact::Q goal_fraction(const solvers::DesignProblem& problem, const solvers::PlacementEvidence& ev) {
  Q frac(ev.goal_pushes, static_cast<long>(problem.pushes.size()));
  frac.canonicalize();
  return frac;
}

namespace {

/// run_design's work: a budget thrown inside ends every rank (abort_all) before with_limits reports it.
Limited<DesignRun> design_run(const SceneInput& in, const DesignOptions& o, solvers::Distributor& dist,
                              const DesignProgress& progress) {
  DesignPlan plan;
  plan.problem = build_problem(o, in.scene, &plan.how);
  plan.total = solvers::placement_count(static_cast<long>(plan.problem.candidates.size()), plan.problem.fixels);
  if (plan.total < 0) throw InputError("command line", "--candidates", "fewer candidates (C(N, k) exceeds 2^62)");
  plan.symmetry = solvers::candidate_symmetry(plan.problem);
  plan.key = problem_key(in.text, o, plan.problem);
  if (!o.out.empty()) create_output_dir(o.out);

  dist.agree(plan.key);
  std::optional<solvers::DesignCheckpoint> resumed;
  if (std::optional<DesignRun> refused = resume(o, plan, dist, &resumed)) return *refused;
  try {
    return search(in, o, plan, dist, std::move(resumed), progress);
  } catch (const exact::InputError& e) {
    dist.abort_all(e.what(), 2);
    throw;
  } catch (const exact::BudgetExceeded& e) {
    dist.abort_all(std::string("budget exceeded: ") + e.what() + " (covered: " + e.covered + ")", 3);
    throw;
  } catch (const std::exception& e) {
    dist.abort_all(std::string("internal error: ") + e.what(), 1);
    throw;
  }
}

}  // namespace

Limited<DesignRun> run_design(const SceneInput& in, const DesignOptions& o, solvers::Distributor& dist,
                              const DesignProgress& progress) {
  return with_limits(o.common.arith, [&] { return design_run(in, o, dist, progress); });
}

json to_json(const DesignReport& r) {
  json j;
  j["scene"] = r.scene_name;
  j["fixels"] = r.problem.fixels;
  json cands = json::array();
  for (const auto& c : r.problem.candidates) cands.push_back(point_json(c.point));
  j["candidates"] = {
      {"source", r.candidate_source}, {"count", static_cast<long>(r.problem.candidates.size())}, {"points", cands}};
  j["requirements"] = {
      {"stable_under", r.stable_under ? json(*r.stable_under) : json(nullptr)},
      {"insertable", r.problem.insertable},
      {"goal_wrench", r.problem.goal_wrench.size() ? exact_json(r.problem.goal_wrench) : json(nullptr)},
      {"goal_push", r.problem.goal_push}};
  j["rank"] = solvers::rank_name(r.problem.rank);
  j["placements"] = r.placements;
  j["symmetries"] = r.symmetries;
  j["statistics"] = statistics_json(r.statistics);
  json top = json::array();
  for (const PlacementReport& p : r.top) top.push_back(placement_json(r, p));
  j["top"] = top;
  j["svg"] = r.svg;
  return j;
}

std::string requirement_text(const DesignReport& r) {
  const DesignProblem& problem = r.problem;
  const bool stable = problem.wrenches.kind != solvers::WrenchSet::Kind::kNone;
  return (stable ? "strongly stable under " + r.stable_under.value_or("") : std::string()) +
         (problem.insertable
              ? std::string(stable ? ", " : "") + "insertable (G_goal non-empty" +
                    (problem.goal_wrench.size() ? ", containing " + tuple_text(problem.goal_wrench) : "") +
                    (problem.goal_push
                         ? ", containing a push at one of " + std::to_string(problem.pushes.size()) + " push points"
                         : "") +
                    ")"
              : "");
}

std::string statistics_text(const solvers::DesignStatistics& s) {
  std::string t = "evaluated " + std::to_string(s.evaluated());
  for (int i = 0; i < solvers::kPlacementStatusCount; ++i)
    t += ", " + std::string(solvers::placement_status_name(static_cast<PlacementStatus>(i))) + " " +
         std::to_string(s.by_status[static_cast<std::size_t>(i)]);
  return t + ", LPs " + std::to_string(s.lps);
}

std::string placement_caption(const solvers::DesignProblem& problem, const solvers::Ranked& r) {
  char approx[32];
  std::snprintf(approx, sizeof approx, "%.4g", r.figure.get_d());
  return "candidates " + candidate_list_text(r.placement) + ": " +
         (problem.rank == solvers::Rank::kMargin ? "margin^2 " : "goal ") + approx;
}

std::string candidate_list_text(const solvers::Placement& placement) {
  std::string cand;
  for (int i : placement) cand += (cand.empty() ? "" : ", ") + std::to_string(i);
  return cand;
}

}  // namespace contactcert::queries
