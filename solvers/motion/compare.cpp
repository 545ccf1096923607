#include "solvers/motion/compare.h"

#include <cmath>
#include <map>

namespace contactcert::solvers::motion {
namespace {

/// The float poses' own numbers as rationals (each double is a rational), to check them exactly.
Poses<Q> as_rational(const Poses<double>& poses) {
  Poses<Q> out;
  for (const Pose<double>& p : poses) out.push_back({Q(p.c), Q(p.s), {Q(p.t.x), Q(p.t.y)}});
  return out;
}

std::map<std::string, char> modes(const std::vector<ContactRecord<Q>>& c) {
  std::map<std::string, char> m;
  for (const auto& x : c) m[x.name] = x.mode;
  return m;
}
std::map<std::string, char> modes(const std::vector<ContactRecord<double>>& c) {
  std::map<std::string, char> m;
  for (const auto& x : c) m[x.name] = x.mode;
  return m;
}

/// The first difference of one step's contacts, or empty.
std::string contact_difference(const StepRecord<Q>& e, const StepRecord<double>& f) {
  const auto me = modes(e.contacts), mf = modes(f.contacts);
  for (const auto& [name, mode] : me) {
    const auto it = mf.find(name);
    if (it == mf.end()) return "missed contact: " + name;
    if (it->second != mode) return "mode of " + name + ": " + mode + " (exact) vs " + it->second + " (float)";
  }
  for (const auto& [name, mode] : mf)
    if (!me.count(name)) return "phantom contact: " + name;
  return "";
}

}  // namespace

double pose_distance(const MotionScene& scene, const Poses<Q>& a, const Poses<double>& b) {
  double d = 0;
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const Pose<double> ad = geometry::to_double(a[k]);
    for (const Point2& p : std::get<geometry::PolygonShape>(scene.bodies[k].workpiece.shape).vertices) {
      const Vec2<double> q{p.x.get_d(), p.y.get_d()};
      const Vec2<double> delta = ad.apply(q) - b[k].apply(q);
      d = std::max(d, std::hypot(delta.x, delta.y));
    }
  }
  return d;
}

std::vector<Divergence> compare_runs(const MotionScene& scene, const Trajectory<Q>& ex, const Trajectory<double>& fl) {
  const SceneGeometry<Q> g = scene_geometry<Q>(scene);
  const std::size_t n = std::min(ex.steps.size(), fl.steps.size());
  std::vector<Divergence> out;
  const auto note = [&](const std::string& kind, std::size_t k, const std::string& what, const Poses<Q>& pe,
                        const Poses<double>& pf, double te, double tf) {
    for (const Divergence& d : out)
      if (d.kind == kind) return;
    out.push_back({static_cast<long>(k), kind, what, pose_distance(scene, pe, pf), te, tf});
  };
  for (std::size_t k = 0; k < n; ++k) {
    const StepRecord<Q>& e = ex.steps[k];
    const StepRecord<double>& f = fl.steps[k];
    const double te = e.time.get_d();
    if (e.verdict != f.verdict)
      note("verdict", k,
           std::string(ucp::status_name(e.verdict)) + " (exact) vs " + ucp::status_name(f.verdict) + " (float)",
           e.poses_after, f.poses_after, te, f.time);
    if (const std::string c = contact_difference(e, f); !c.empty())
      note(c.rfind("mode", 0) == 0 ? "mode" : "contacts", k, c, e.poses_after, f.poses_after, te, f.time);
    std::vector<Vec2<Q>> tips;
    for (const Vec2<double>& t : f.tips_after) tips.push_back({Q(t.x), Q(t.y)});
    if (const std::string o = overlap(g, as_rational(f.poses_after), tips); !o.empty())
      note("penetration", k, o, e.poses_after, f.poses_after, te, f.time);
  }
  if (ex.steps.size() != fl.steps.size() || ex.status != fl.status)
    note("run_end", n,
         std::string(run_status_name(ex.status)) + " after " + std::to_string(ex.steps.size()) + " steps (exact) vs " +
             run_status_name(fl.status) + " after " + std::to_string(fl.steps.size()) + " (float)",
         ex.final_poses, fl.final_poses, ex.final_time.get_d(), fl.final_time);
  return out;
}

}  // namespace contactcert::solvers::motion
