#include "queries/simulate_query.h"

#include <chrono>
#include <cmath>

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/nearest_double.h"
#include "exact/rational_text.h"
#include "queries/trajectory_svg.h"
#include "queries/ucp_uniqueness.h"

namespace contactcert::queries {
namespace {

namespace motion = solvers::motion;
using exact::Q;
using geometry::Pose;
using geometry::Vec2;

// Exact strings (ex) and float views (ap) of the trajectory's numbers.
json ex(const Q& x) { return exact::to_string(x); }
double ap(const Q& x) { return exact::nearest_double(x); }
double ap(double x) { return x; }
template <class T>
json ex(const Vec2<T>& p) {
  return json::array({ex(p.x), ex(p.y)});
}
template <class T>
json ap(const Vec2<T>& p) {
  return json::array({ap(p.x), ap(p.y)});
}
template <class V>
json ex(const std::vector<V>& v) {
  json out = json::array();
  for (const V& x : v) out.push_back(ex(x));
  return out;
}
template <class V>
json ap(const std::vector<V>& v) {
  json out = json::array();
  for (const V& x : v) out.push_back(ap(x));
  return out;
}

/// j[key]: the exact value (exact paths only), j[key_approx]: its float view.
template <class T, class V>
void put(json& j, const std::string& key, const V& value) {
  if constexpr (std::is_same_v<T, Q>) j[key] = ex(value);
  j[key + "_approx"] = ap(value);
}

/// world = R body + t, R = [[c, -s], [s, c]], and the angle it turns (a float view).
template <class T>
json pose_json(const Pose<T>& p) {
  json j;
  put<T>(j, "R", std::vector<Vec2<T>>{{p.c, T(-p.s)}, {p.s, p.c}});
  put<T>(j, "t", p.t);
  j["angle_approx"] = std::atan2(ap(p.s), ap(p.c));
  return j;
}

/// Body b's twist as (v_x, v_y, omega); zero when the step has none (no solution).
template <class T>
std::vector<T> twist_of(const std::vector<motion::Twist<T>>& twists, std::size_t b) {
  const motion::Twist<T> t = b < twists.size() ? twists[b] : motion::Twist<T>{};
  return {t.v.x, t.v.y, t.omega};
}

/// One body of a step with several: its name, pose, q_dot, applied q_dot and pose after the step.
template <class T>
json body_step_json(const motion::StepRecord<T>& s, std::size_t b, const std::string& name) {
  json j;
  j["name"] = name;
  j["pose"] = pose_json(s.poses[b]);
  put<T>(j, "q_dot", twist_of(s.twists, b));
  put<T>(j, "applied_q_dot", twist_of(s.applied, b));
  j["pose_after"] = pose_json(s.poses_after[b]);
  return j;
}

/// A step: with one body its pose, q_dot, applied_q_dot and pose_after at the top; with several, `bodies`.
template <class T>
json step_json(const motion::StepRecord<T>& s, const std::string& certificate,
               const std::string& uniqueness_certificate, const std::vector<std::string>& names) {
  const bool one = names.size() == 1;
  json j;
  j["index"] = s.index;
  put<T>(j, "time", s.time);
  put<T>(j, "h", s.h);
  j["cut_by"] = s.cut_by.empty() ? json(nullptr) : json(s.cut_by);
  j["cut_exact"] = s.cut_exact;
  if (one) j["pose"] = pose_json(s.poses[0]);
  j["verdict"] = solvers::ucp::status_name(s.verdict);
  j["reason"] = s.reason;
  if (one) {
    put<T>(j, "q_dot", twist_of(s.twists, 0));
    put<T>(j, "applied_q_dot", twist_of(s.applied, 0));
  } else {
    json bodies = json::array();
    for (std::size_t b = 0; b < names.size(); ++b) bodies.push_back(body_step_json(s, b, names[b]));
    j["bodies"] = bodies;
  }
  json contacts = json::array();
  for (const motion::ContactRecord<T>& c : s.contacts) {
    json cj{{"name", c.name}, {"mode", std::string(1, c.mode)}};
    put<T>(cj, "point", c.point);
    put<T>(cj, "normal", c.normal);
    put<T>(cj, "force", c.force());
    contacts.push_back(cj);
  }
  j["contacts"] = contacts;
  j["events"] = {{"made", s.made}, {"broken", s.broken}};
  if (s.uniqueness) j["uniqueness"] = uniqueness_json(*s.uniqueness);
  if (one) j["pose_after"] = pose_json(s.poses_after[0]);
  put<T>(j, "fingers_after", s.tips_after);
  if (!certificate.empty()) j["certificate"] = certificate;
  if (!uniqueness_certificate.empty()) j["uniqueness_certificate"] = uniqueness_certificate;
  j["seconds"] = s.seconds;
  return j;
}

/// The final state: the pose (one body) or each body's name and pose (`bodies`), and the finger tips.
template <class T>
json final_json(const motion::Trajectory<T>& r, const std::vector<std::string>& names) {
  json j;
  put<T>(j, "time", r.final_time);
  if (names.size() == 1) {
    j["pose"] = pose_json(r.final_poses[0]);
  } else {
    json bodies = json::array();
    for (std::size_t b = 0; b < names.size(); ++b)
      bodies.push_back({{"name", names[b]}, {"pose", pose_json(r.final_poses[b])}});
    j["bodies"] = bodies;
  }
  put<T>(j, "fingers", r.final_tips);
  return j;
}

std::vector<std::string> body_names(const motion::MotionScene& scene) {
  std::vector<std::string> out;
  for (const motion::MovingBody& b : scene.bodies) out.push_back(b.name);
  return out;
}

template <class T>
void put_run(json& j, const motion::Trajectory<T>& r, const std::vector<std::string>& certificates,
             const std::vector<std::string>& uniqueness_certificates, const std::vector<std::string>& names) {
  const auto at = [](const std::vector<std::string>& files, std::size_t k) { return k < files.size() ? files[k] : ""; };
  json steps = json::array();
  for (std::size_t k = 0; k < r.steps.size(); ++k)
    steps.push_back(step_json(r.steps[k], at(certificates, k), at(uniqueness_certificates, k), names));
  j["steps"] = steps;
  j["final"] = final_json(r, names);
}

json divergence_json(const motion::Divergence& d) {
  return {{"kind", d.kind},
          {"step", d.step},
          {"what", d.what},
          {"pose_distance", d.pose_distance},
          {"time_exact", d.time_exact},
          {"time_float", d.time_float}};
}

/// The solver's options from the query's (checked here: the front ends parse, the query refuses).
motion::SimulateOptions solver_options(const SimulateOptions& o, exact::Arith arith) {
  if (o.steps && (*o.steps < 1 || *o.steps > 1000000))
    throw exact::InputError("command line", "--steps", "a step count from 1 to 1000000");
  if (o.dt && sgn(*o.dt) <= 0) throw exact::InputError("command line", "--dt", "a step size > 0");
  if (o.max_modes < 1) throw exact::InputError("command line", "--max-modes", "a budget >= 1");
  if (o.max_nodes < 1) throw exact::InputError("command line", "--max-nodes", "a budget >= 1");
  if (!(o.common.time_limit >= 0 && o.common.time_limit <= kMaxTimeLimit))
    throw exact::InputError("command line", "--time-limit", "a number of seconds from 0 to 1e7");
  if (arith == exact::Arith::kFloat && !o.certificates.empty())
    throw exact::InputError("command line", "--certificates", "a certificate needs --arith exact or verified");
  if (arith == exact::Arith::kFloat && o.compare)
    throw exact::InputError("command line", "--compare",
                            "the float run beside an exact one: --arith exact or verified");
  motion::SimulateOptions so;
  so.arith = arith;
  so.steps = o.steps;
  so.dt = o.dt;
  so.uniqueness = o.uniqueness;
  so.max_uniqueness_modes = o.max_modes;
  so.certificates = !o.certificates.empty();
  so.time_limit = o.common.time_limit;
  so.ucp.max_nodes = o.max_nodes;
  return so;
}

}  // namespace

MotionInput parse_motion(const std::string& text, const std::string& name) {
  const exact::JsonInput root = exact::JsonInput::parse(text, name);
  if (!motion::is_motion_scene(root))
    throw exact::InputError(name, "$.motion",
                            "a motion scene (\"kind\": \"quasistatic_scene\" with \"motion\": {\"dt\", \"steps\"}, "
                            "docs/formats.md section 2)");
  return {name, text, motion::read_motion_scene(root)};
}

MotionInput load_motion(const std::string& path) { return parse_motion(exact::JsonInput::read_text(path), path); }

Q parse_dt(const std::string& text, const std::string& field) {
  Q h;
  if (!exact::parse_rational_into(text, h) || sgn(h) <= 0)
    throw exact::InputError("command line", field,
                            "a step size > 0 written exactly (\"1/10\", \"0.1\"), got " + exact::quoted_excerpt(text));
  return h;
}

SimulateRun::SimulateRun(const MotionInput& input, const SimulateOptions& o)
    : options_(o), start_(std::chrono::steady_clock::now()) {
  answer_.file = input.name;
  answer_.scene = input.scene;
  answer_.arith = scene_arith(o.common.arith);
  solver_ = solver_options(o, answer_.arith);
  answer_.dt = o.dt.value_or(input.scene.dt);
  answer_.steps = o.steps.value_or(input.scene.steps);
  if (!o.certificates.empty()) create_output_dir(o.certificates, "--certificates");
  if (!o.svg.empty()) write_text_file(o.svg, "");  // an unwritable path fails before the run, not after it
  if (answer_.arith == exact::Arith::kFloat)
    float_.emplace(input.scene, solver_);
  else
    exact_.emplace(input.scene, solver_);
}

bool SimulateRun::advance() {
  if (finished_) return false;
  if (!exact_) return float_->step();
  if (!exact_->step()) return false;
  const motion::StepRecord<Q>& s = exact_->trajectory().steps.back();
  // A step's certificate (and its uniqueness's) to DIR/step-K{suffix}.json, if it has one.
  const auto write = [&](std::vector<std::string>& files, const std::string& text, const std::string& suffix) {
    if (options_.certificates.empty() || text.empty()) {
      files.emplace_back();
      return;
    }
    files.push_back(options_.certificates + "/step-" + std::to_string(s.index) + suffix + ".json");
    write_certificate_file("simulate", files.back(), text, std::to_string(s.index + 1) + " steps made");
  };
  write(answer_.certificates, s.certificate, "");
  write(answer_.uniqueness_certificates, s.uniqueness_certificate, "-uniqueness");
  return true;
}

std::optional<json> SimulateRun::next() {
  if (!advance()) return std::nullopt;
  const std::vector<std::string> names = body_names(answer_.scene);
  if (exact_)
    return step_json(exact_->trajectory().steps.back(), answer_.certificates.back(),
                     answer_.uniqueness_certificates.back(), names);
  return step_json(float_->trajectory().steps.back(), "", "", names);
}

SimulateAnswer SimulateRun::finish() {
  if (finished_) return answer_;
  while (advance()) {
  }
  finished_ = true;
  SimulateAnswer& a = answer_;
  if (float_) a.float_run = float_->take();
  if (exact_) a.exact_run = exact_->take();
  if (exact_ && options_.compare) {
    // The float run gets what is left of the time limit (at least a moment: then it ends `unknown` at once).
    if (solver_.time_limit > 0) solver_.time_limit = std::max(1e-9, solver_.time_limit - seconds_since(start_));
    a.float_run = motion::simulate<double>(a.scene, solver_);
    a.divergences = motion::compare_runs(a.scene, *a.exact_run, *a.float_run);
    a.compared = true;
  }
  if (!options_.svg.empty()) {
    write_text_file(options_.svg, trajectory_svg(a));
    a.svg = options_.svg;
  }
  a.seconds = seconds_since(start_);
  return a;
}

Limited<SimulateAnswer> run_simulate(const MotionInput& input, const SimulateOptions& options) {
  return with_limits(options.common.arith, [&] { return SimulateRun(input, options).finish(); });
}

motion::RunStatus run_status(const SimulateAnswer& a) {
  return a.exact_run ? a.exact_run->status : a.float_run->status;
}
const std::string& run_reason(const SimulateAnswer& a) {
  return a.exact_run ? a.exact_run->reason : a.float_run->reason;
}
std::size_t steps_done(const SimulateAnswer& a) {
  return a.exact_run ? a.exact_run->steps.size() : a.float_run->steps.size();
}
bool stopped_by_budget(const SimulateAnswer& a) { return run_status(a) == motion::RunStatus::kUnknown; }

json to_json(const SimulateAnswer& a) {
  json j;
  j["file"] = a.file;
  j["status"] = motion::run_status_name(run_status(a));
  j["reason"] = run_reason(a);
  j["arith"] = exact::arith_name(a.arith);
  put<Q>(j, "dt", a.dt);
  j["steps_asked"] = a.steps;
  j["steps_done"] = steps_done(a);
  const std::vector<std::string> names = body_names(a.scene);
  if (a.exact_run)
    put_run(j, *a.exact_run, a.certificates, a.uniqueness_certificates, names);
  else
    put_run(j, *a.float_run, {}, {}, names);
  if (a.compared) {
    const motion::Trajectory<double>& f = *a.float_run;
    j["float"] = {{"status", motion::run_status_name(f.status)},
                  {"reason", f.reason},
                  {"steps_done", f.steps.size()},
                  {"final", final_json(f, names)}};
    json d = json::array();
    for (const motion::Divergence& x : a.divergences) d.push_back(divergence_json(x));
    j["divergences"] = d;
  }
  if (!a.svg.empty()) j["svg"] = a.svg;
  j["seconds"] = a.seconds;
  return j;
}

}  // namespace contactcert::queries
