#include "solvers/motion/simulate.h"

#include <Eigen/QR>
#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>

#include "exact/enclose.h"
#include "exact/input_error.h"
#include "solvers/motion/bounded.h"
#include "solvers/motion/first_root.h"
#include "solvers/motion/keep_contacts.h"
#include "solvers/motion/step_problem.h"
#include "solvers/motion/uniqueness_certificate.h"
#include "solvers/motion/unreduced_point.h"

namespace contactcert::solvers::motion {
namespace {

using Index = Eigen::Index;
using exact::reduced;
using exact::sign;

/// The solution's physics in T: per contact the signs of v_n and v_t and c_n, c_t; per body its q_dot; on the float
/// path every joint velocity; on the exact paths the solution itself (its v_t read unreduced, and the joint velocities
/// read only for the separating fingers: finger_velocity).
template <class T>
struct StepPhysics {
  std::vector<int> vn, vt;
  std::vector<T> cn, ct, theta;
  std::vector<Twist<T>> twists;
  const ucp::PhysicalSolution* solution = nullptr;
};

StepPhysics<Q> physics(const ucp::UcpProblem&, const ucp::UcpReport& r, const Q*) {
  const ucp::PhysicalSolution& s = *r.physical;
  StepPhysics<Q> out;
  out.solution = &s;
  out.cn.resize(static_cast<std::size_t>(s.c_n.size()));  // in place: a growing vector would copy the rationals
  out.ct.resize(out.cn.size());
  for (Index i = 0; i < s.v_n.size(); ++i) {
    out.vn.push_back(s.v_n.sign(i));
    out.vt.push_back(s.v_t.sign(i));
    out.cn[static_cast<std::size_t>(i)] = s.c_n(i);
    out.ct[static_cast<std::size_t>(i)] = s.c_t(i);
  }
  out.twists.resize(static_cast<std::size_t>(s.q_dot.size() / 3));
  for (Index b = 0; b + 2 < s.q_dot.size(); b += 3)
    out.twists[static_cast<std::size_t>(b / 3)] = {{s.q_dot(b), s.q_dot(b + 1)}, s.q_dot(b + 2)};
  return out;
}

/// The float path's physics from its pair: u = [q_dot; -theta_abar] solves P u = v + J_alpha theta_alpha (least
/// squares in doubles), c_t = s_t^+ - mu c_n.
StepPhysics<double> physics(const ucp::UcpProblem& problem, const ucp::UcpReport& r, const double*) {
  const ucp::QuasistaticProblem& p = *problem.quasistatic;
  const Index nc = p.nc;
  StepPhysics<double> out;
  exact::Vec<double> rhs = exact::to_double(p.J_alpha_theta_alpha());
  for (Index i = 0; i < nc; ++i) {
    const double vn = r.x_approx(i), vt = r.x_approx(nc + i) - r.x_approx(2 * nc + i);
    out.vn.push_back(sign(vn));
    out.vt.push_back(sign(vt));
    out.cn.push_back(r.y_approx(i));
    out.ct.push_back(r.y_approx(nc + i) - p.mu(i).get_d() * r.y_approx(i));
    rhs(i) += vn;
    rhs(nc + i) += vt;
  }
  const exact::Vec<double> u = exact::to_double(p.P).colPivHouseholderQr().solve(rhs);
  out.theta.assign(static_cast<std::size_t>(p.ntheta), 0.0);
  for (int j : p.alpha) out.theta[static_cast<std::size_t>(j)] = p.theta_dot(j).get_d();
  for (std::size_t k = 0; k < p.abar.size(); ++k) out.theta[static_cast<std::size_t>(p.abar[k])] = -u(p.nq + Index(k));
  for (Index b = 0; b + 2 < p.nq; b += 3) out.twists.push_back({{u(b), u(b + 1)}, u(b + 2)});
  return out;
}

/// The velocity of the finger whose joints are j and j + 1.
Vec2<Q> finger_velocity(const StepPhysics<Q>& ph, std::size_t j) {
  return {ph.solution->theta_dot(Index(j)), ph.solution->theta_dot(Index(j + 1))};
}
Vec2<double> finger_velocity(const StepPhysics<double>& ph, std::size_t j) { return {ph.theta[j], ph.theta[j + 1]}; }

/// The mode letter of a contact from the signs of v_n and v_t.
char mode_letter(int vn, int vt) {
  if (vn > 0) return 's';
  return vt == 0 ? 'r' : (vt > 0 ? '+' : '-');
}

/// The names of a not in b (a step's few contacts: a linear search).
std::vector<std::string> minus(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  std::vector<std::string> out;
  for (const std::string& x : a)
    if (std::find(b.begin(), b.end(), x) == b.end()) out.push_back(x);
  return out;
}

/// True if the enclosures prove that a point p moving with velocity v along the edge a -> b reaches neither end before
/// time h (the time to the end ahead, (e . e - s0) / (v . e) or -s0 / (v . e) with e = b - a, s0 = (p - a) . e, is
/// then > h).
bool proven_not_before(const Vec2<exact::Interval>& a, const Vec2<exact::Interval>& b, const Vec2<exact::Interval>& p,
                       const Vec2<exact::Interval>& v, const exact::Interval& h) {
  const Vec2<exact::Interval> e = b - a;
  const exact::Interval s0 = dot2(p - a, e), rate = dot2(v, e);
  if (rate.inf() > 0) return (dot2(e, e) - s0 - h * rate).inf() > 0;
  if (rate.sup() < 0) return (s0 + h * rate).inf() > 0;
  return false;
}

/// A finger carried along body edge c.body with relative velocity `slip` (along the edge): the time before h at which
/// it reaches the edge's end and which body vertex that is, if it does (linear in the body's frame). The exact paths
/// first let the enclosures prove that it does not (the common case: a slow slide), else compare the time unreduced
/// and reduce it only when it cuts the step.
template <class T>
std::optional<std::pair<T, int>> slide_to_vertex(const WorldBodies<T>& world, const Contact<T>& c, const Vec2<T>& slip,
                                                 const T& h) {
  const auto which = static_cast<std::size_t>(c.which);
  const std::vector<Vec2<T>>& body = world.vertices[which];
  const auto nb = static_cast<int>(body.size());
  const int next = (c.body + 1) % nb;
  if constexpr (std::is_same_v<T, Q>) {
    const std::vector<Vec2<exact::Interval>>& in = world.enclosed[which];
    if (proven_not_before(in[static_cast<std::size_t>(c.body)], in[static_cast<std::size_t>(next)], enclose(c.point),
                          enclose(slip), exact::enclose(h)))
      return std::nullopt;
  }
  const auto a = unreduced(body[static_cast<std::size_t>(c.body)]);
  const auto e = unreduced(body[static_cast<std::size_t>(next)]) - a;
  const auto s0 = dot2(unreduced(c.point) - a, e), rate = dot2(unreduced(slip), e);
  if (sign(rate) == 0) return std::nullopt;
  const auto t = sign(rate) > 0 ? (dot2(e, e) - s0) / rate : -s0 / rate;
  if (!(t < unreduced(h))) return std::nullopt;
  return std::pair<T, int>{reduced(t), sign(rate) > 0 ? next : c.body};
}

/// The fingers' commands at time t and the step's length: H, or up to the next schedule change (then `cut_by`).
template <class T>
struct StepSchedule {
  std::vector<FingerCommand<T>> commands;
  T H;
  std::string cut_by;
};

template <class T>
StepSchedule<T> step_schedule(const MotionScene& scene, const SceneGeometry<T>& g, const T& t, const T& H) {
  StepSchedule<T> out{std::vector<FingerCommand<T>>(scene.fingers.size()), H, ""};
  Q tq;
  if constexpr (std::is_same_v<T, Q>)
    tq = t;
  else
    tq = Q(t);
  for (std::size_t f = 0; f < scene.fingers.size(); ++f) {
    const ScheduleAt at = schedule_at(scene.fingers[f], tq);
    out.commands[f] = {at.segment->force, {from_q<T>(at.segment->value.x), from_q<T>(at.segment->value.y)}};
    if (at.ends && from_q<T>(*at.ends - tq) < out.H) {
      out.H = from_q<T>(*at.ends - tq);
      out.cut_by = "schedule change of " + g.finger_names[f];
    }
  }
  return out;
}

/// A carried finger's tip p after the step on the exact paths: step(p + mu e), e = R e_b its edge in the world (e_b
/// in the frame of the body carrying it, R the body's rotation), is after(q + mu e_b) with q = before^-1(p) the tip in
/// the body's frame and after = step o before the body's new pose: the pose applied to a point of the body's size
/// rather than the step to one of the world's. in_body keeps (body, q) from step to step while the finger stays on
/// that body (the float path moves its tip as it did).
Vec2<Q> carried_tip(std::optional<std::pair<int, Vec2<Q>>>& in_body, const Vec2<Q>& p, int body, const Vec2<Q>& e_b,
                    const Q& mu, const Pose<Q>& before, const Pose<Q>& after) {
  if (!in_body || in_body->first != body) in_body = std::pair<int, Vec2<Q>>{body, before.unrotate(p - before.t)};
  Vec2<Q>& q = in_body->second;
  q = q + mu * e_b;
  return after.apply(q);
}

/// What an overlap owes to the translation correction: ": the translation correction cannot keep C, ... closed
/// (...)" naming the maintained contacts it leaves dipping, else empty.
std::string unkept_dips(const std::vector<std::string>& dipping) {
  std::string names;
  for (const std::string& name : dipping) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? ""
                       : ": the translation correction cannot keep " + names +
                             " closed (more independent contact constraints than translation freedoms)";
}

/// How each finger moves over the step: carried along its edge with a slide (in contact, v_n = 0), or by a
/// velocity (free, or separating), or not at all (a free force-controlled finger).
template <class T>
struct FingerMotion {
  std::vector<std::optional<Vec2<T>>> free_velocity, carried_slip;
  std::vector<T> rate;  ///< a carried finger's slip is rate e, e = J^T n its body edge in the world
};

/// slip . e for the finger carried at contact i (joints j, j + 1), with slip its velocity vf relative to the body point
/// under it and e = (n_y, -n_x) its edge: slip . e = slip x n. That is the contact's v_t = t . (body - finger velocity)
/// with t = J n = -e, which the exact paths read from the solution (unreduced: its numerator over the vector's
/// denominator); the float path's v_t is not its twist's (least squares), so it takes the twist's.
exact::Unreduced slip_along(const StepPhysics<Q>& ph, std::size_t i, std::size_t, const Twist<Q>&, const Contact<Q>&) {
  exact::Unreduced out;
  ph.solution->v_t.entry(static_cast<Index>(i), out.n, out.d);
  return out;
}
double slip_along(const StepPhysics<double>& ph, std::size_t, std::size_t j, const Twist<double>& tw,
                  const Contact<double>& c) {
  return cross2(finger_velocity(ph, j) - (tw.v + tw.omega * perp2(c.point)), c.normal);
}

/// Records each contact's mode and force components in r, and says how each finger moves. A carried finger's slide
/// along its edge e = J^T n over the step is a multiple of e (bounded), so the tip stays exactly on the edge.
template <class T>
FingerMotion<T> record_contacts(const ContactSet<T>& cs, const StepPhysics<T>& ph, const StepSchedule<T>& sched,
                                StepRecord<T>& r) {
  const std::size_t nf = sched.commands.size();
  FingerMotion<T> m{std::vector<std::optional<Vec2<T>>>(nf), std::vector<std::optional<Vec2<T>>>(nf),
                    std::vector<T>(nf)};
  std::vector<bool> touching(nf, false);
  std::size_t joint = 0;
  r.contacts.reserve(cs.contacts.size());  // no copies of the records' rationals as the vector grows
  for (std::size_t i = 0; i < cs.contacts.size(); ++i) {
    const Contact<T>& c = cs.contacts[i];
    r.contacts.push_back({c.name, mode_letter(ph.vn[i], ph.vt[i]), c.point, c.normal, ph.cn[i], ph.ct[i]});
    if (c.kind != ContactKind::kFinger) continue;
    const auto f = static_cast<std::size_t>(c.other);
    touching[f] = true;
    const std::size_t j = joint;
    joint += 2;
    if (ph.vn[i] != 0) {
      m.free_velocity[f] = finger_velocity(ph, j);
      continue;
    }
    const Twist<T>& tw = ph.twists[static_cast<std::size_t>(c.which)];
    // H (slip . e) / (e . e), unreduced on the exact paths: one reduction.
    const auto n = unreduced(c.normal);
    const T along = reduced(unreduced(sched.H) * slip_along(ph, i, j, tw, c) / dot2(n, n));
    m.rate[f] = bounded(along) / sched.H;
    m.carried_slip[f] = m.rate[f] * Vec2<T>{c.normal.y, -c.normal.x};
  }
  for (std::size_t f = 0; f < nf; ++f)
    if (!touching[f] && !sched.commands[f].force) m.free_velocity[f] = sched.commands[f].value;
  return m;
}

/// The twist applied to body b (StepRecord::applied): turning, about a rolling obstacle contact's point (exactly the
/// instantaneous centre: the body's velocity is zero there) or else the instantaneous centre (bounded), by the
/// rotation that brings the pose's tan(theta / 2) after a full step, (U + u) / (1 - U u) with u = omega H / 2, to a
/// bounded value (exact paths; in unreduced fractions, reduced twice: U_new and omega).
template <class T>
Twist<T> applied_twist(const ContactSet<T>& cs, const StepRecord<T>& r, std::size_t b, const Twist<T>& tw,
                       const Pose<T>& pose, const T& H) {
  Twist<T> out = tw;
  if (sign(tw.omega) == 0) return out;
  const Vec2<T>* pivot = nullptr;
  for (std::size_t i = 0; i < cs.contacts.size() && !pivot; ++i)
    if (fixed_party(cs.contacts[i], b) && r.contacts[i].mode == 'r') pivot = &cs.contacts[i].point;
  const Vec2<T> centre = pivot ? *pivot : Vec2<T>{bounded(T(-tw.v.y / tw.omega)), bounded(T(tw.v.x / tw.omega))};
  if constexpr (std::is_same_v<T, Q>) {
    using exact::Unreduced;
    const Unreduced one{1, 1}, two{2, 1}, c1 = one + unreduced(pose.c);
    if (sign(c1) != 0) {
      // U_old = tan(theta / 2) is small (on the grid): reduced first, it keeps the rest small.
      const Unreduced U_old = unreduced(reduced(unreduced(pose.s) / c1)), u = unreduced(tw.omega) * unreduced(H) / two;
      if (const Unreduced den = one - U_old * u; sign(den) != 0) {
        const Unreduced U_new = unreduced(bounded(reduced((U_old + u) / den)));
        out.omega = reduced(two * ((U_new - U_old) / (one + U_old * U_new)) / unreduced(H));
      }
    }
  }
  out.v = out.omega * Vec2<T>{centre.y, -centre.x};  // omega J (0 - centre)
  return out;
}

/// Cuts the step (r.h, cut_by, cut_exact) at the first contact that closes, or where a carried finger reaches the
/// end of its edge, if before H.
template <class T>
void cut_step(const SceneGeometry<T>& g, const WorldBodies<T>& world, const std::vector<Vec2<T>>& tips,
              const ContactSet<T>& cs, const FingerMotion<T>& m, const T& H, StepRecord<T>& r) {
  r.h = H;
  if (const auto closing = first_closing(g, world, tips, r.applied, m.free_velocity, H)) {
    r.h = closing->tau;
    r.cut_by = closing->name;
    r.cut_exact = closing->exact;
  }
  for (const Contact<T>& c : cs.contacts) {
    const auto f = static_cast<std::size_t>(c.other);
    if (c.kind != ContactKind::kFinger || !m.carried_slip[f]) continue;
    if (const auto end = slide_to_vertex(world, c, *m.carried_slip[f], r.h)) {
      r.h = end->first;
      r.cut_by = g.finger_names[f] + " reaches body vertex " + std::to_string(end->second);
      r.cut_exact = true;
    }
  }
}

}  // namespace

const char* run_status_name(RunStatus s) {
  switch (s) {
    case RunStatus::kCompleted:
      return "completed";
    case RunStatus::kJammed:
      return "jammed";
    case RunStatus::kNoContact:
      return "no_contact";
    case RunStatus::kUnsupportedContact:
      return "unsupported_contact";
    case RunStatus::kOverlap:
      return "overlap";
    case RunStatus::kIrrationalContactTime:
      return "irrational_contact_time";
    case RunStatus::kUnknown:
      return "unknown";
  }
  return "unknown";
}

/// The step records a run reserves room for before its first step.
constexpr long kReservedSteps = 1024;

template <class T>
Stepper<T>::Stepper(MotionScene scene, const SimulateOptions& opts)
    : scene_(std::move(scene)),
      opts_(opts),
      g_(scene_geometry<T>(scene_)),
      H_(from_q<T>(opts.dt.value_or(scene_.dt))),
      N_(opts.steps.value_or(scene_.steps)),
      uopts_(opts.ucp),
      start_(std::chrono::steady_clock::now()) {
  constexpr bool exact_path = std::is_same_v<T, Q>;
  uopts_.arith =
      exact_path ? (opts.arith == exact::Arith::kFloat ? exact::Arith::kVerified : opts.arith) : exact::Arith::kFloat;
  // Room for the records up front (up to kReservedSteps): gmpxx does not declare its rationals' moves noexcept (they
  // allocate), so a growing std::vector copies every exact record, all its rationals, each time it doubles.
  out_.steps.reserve(static_cast<std::size_t>(std::clamp(N_, 0L, kReservedSteps)));
  for (const Finger& f : scene_.fingers) out_.final_tips.push_back({from_q<T>(f.tip.x), from_q<T>(f.tip.y)});
  out_.final_poses.assign(g_.bodies.size(), Pose<T>{});
  world_ = world_bodies(g_, out_.final_poses);
  if (const std::string o = overlap(g_, world_, out_.final_tips); !o.empty())
    finish(RunStatus::kOverlap, o + " at time 0");
}

template <class T>
void Stepper<T>::finish(RunStatus s, std::string why) {
  out_.status = s;
  out_.reason = std::move(why);
}

template <class T>
bool Stepper<T>::step() {
  constexpr bool exact_path = std::is_same_v<T, Q>;
  using clock = std::chrono::steady_clock;
  const auto k = static_cast<long>(out_.steps.size());
  if (out_.status != RunStatus::kCompleted || k >= N_) return false;
  const auto step_start = clock::now();
  const auto done = [&](bool made) {
    out_.seconds = std::chrono::duration<double>(clock::now() - start_).count();
    return made;
  };
  if (opts_.time_limit > 0) {
    uopts_.time_limit = opts_.time_limit - std::chrono::duration<double>(step_start - start_).count();
    if (uopts_.time_limit <= 0) {
      finish(RunStatus::kUnknown, "time limit after " + std::to_string(k) + " steps");
      return done(false);
    }
  }
  Poses<T>& poses = out_.final_poses;
  T& t = out_.final_time;
  std::vector<Vec2<T>>& tips = out_.final_tips;
  StepRecord<T> r;
  r.index = k;
  r.time = t;
  r.poses = poses;
  const ContactSet<T> cs = find_contacts(g_, world_, tips);
  std::vector<bool> held(poses.size(), false);  // every body needs a contact (else it would fall: no solution)
  for (const Contact<T>& c : cs.contacts) {
    held[static_cast<std::size_t>(c.which)] = true;
    if (c.kind == ContactKind::kBodyBody) held[static_cast<std::size_t>(c.other)] = true;
  }
  const auto free_body = std::find(held.begin(), held.end(), false);
  if (!cs.unsupported.empty() || free_body != held.end()) {
    const bool none = cs.unsupported.empty();
    finish(none ? RunStatus::kNoContact : RunStatus::kUnsupportedContact,
           none ? "no contact holds the " + g_.body_names[static_cast<std::size_t>(free_body - held.begin())] +
                      " (a quasistatic body needs one)"
                : cs.unsupported);
    return done(false);
  }
  std::vector<std::string> names;
  for (const Contact<T>& c : cs.contacts) names.push_back(c.name);
  r.made = minus(names, previous_);
  r.broken = minus(previous_, names);
  previous_ = names;
  const StepSchedule<T> sched = step_schedule(scene_, g_, t, H_);
  r.cut_by = sched.cut_by;

  ucp::UcpProblem problem;
  std::optional<geometry::Assembly> assembly;  // several bodies
  try {
    if (g_.bodies.size() == 1) {
      problem = step_problem(g_, poses[0], cs.contacts, sched.commands, "step " + std::to_string(k));
    } else {
      assembly = step_assembly(g_, poses, cs.contacts, sched.commands);
      problem = assembly_step_problem(*assembly);
    }
  } catch (const exact::InputError& e) {
    finish(RunStatus::kUnsupportedContact, std::string("the step's problem was refused: ") + e.what());
    return done(false);
  }
  const ucp::UcpReport rep = ucp::solve_ucp(problem, uopts_);
  r.verdict = rep.status;
  r.reason = rep.reason;
  const std::string assembly_text =
      exact_path && opts_.certificates && assembly ? exact::json_text(assembly_scene_json(*assembly)) : "";
  if (exact_path && opts_.certificates) r.certificate = ucp::certificate_text(problem, rep, assembly_text);
  if (rep.status != ucp::UcpStatus::kSolvable) {
    for (const Contact<T>& c : cs.contacts) r.contacts.push_back({c.name, '?', c.point, c.normal});
    r.poses_after = poses;  // no motion
    r.tips_after = tips;
    r.seconds = std::chrono::duration<double>(clock::now() - step_start).count();
    out_.steps.push_back(r);
    const bool jammed = rep.status == ucp::UcpStatus::kJammed;
    finish(jammed ? RunStatus::kJammed : RunStatus::kUnknown,
           (jammed ? "jammed at step " : "step ") + std::to_string(k) + ": " + rep.reason);
    return done(true);
  }
  const StepPhysics<T> ph = physics(problem, rep, static_cast<const T*>(nullptr));
  r.twists = ph.twists;
  if (exact_path && opts_.uniqueness) {
    r.uniqueness = motion_uniqueness(problem, uopts_.arith, opts_.max_uniqueness_modes, opts_.certificates);
    r.uniqueness_certificate = uniqueness_certificate(problem, *r.uniqueness, assembly_text);
    r.uniqueness->evidence.reset();  // written down; a long run keeps only the verdicts
  }
  const FingerMotion<T> fm = record_contacts(cs, ph, sched, r);
  for (std::size_t b = 0; b < poses.size(); ++b)
    r.applied.push_back(applied_twist(cs, r, b, ph.twists[b], poses[b], sched.H));
  cut_step(g_, world_, tips, cs, fm, sched.H, r);

  Poses<T> twist_steps;
  std::vector<char> modes;
  for (std::size_t b = 0; b < poses.size(); ++b)
    twist_steps.push_back(geometry::twist_step(r.applied[b].v, r.applied[b].omega, r.h));
  for (const ContactRecord<T>& c : r.contacts) modes.push_back(c.mode);
  const Poses<T> steps = keep_contacts(poses, std::move(twist_steps), cs.contacts, modes, r.applied);
  for (std::size_t b = 0; b < poses.size(); ++b) poses[b] = compose(steps[b], poses[b]);
  std::vector<int> carrier(tips.size(), 0), edge(tips.size(), 0);  // the body and edge a carried finger touches
  for (const Contact<T>& c : cs.contacts)
    if (c.kind == ContactKind::kFinger) {
      carrier[static_cast<std::size_t>(c.other)] = c.which;
      edge[static_cast<std::size_t>(c.other)] = c.body;
    }
  tips_in_body_.resize(tips.size());
  for (std::size_t f = 0; f < tips.size(); ++f) {
    const auto b = static_cast<std::size_t>(carrier[f]);
    if (!fm.carried_slip[f]) tips_in_body_[f].reset();
    if (fm.carried_slip[f]) {
      if constexpr (exact_path) {
        const std::vector<Vec2<T>>& body = g_.bodies[b];
        const auto i = static_cast<std::size_t>(edge[f]);
        tips[f] = carried_tip(tips_in_body_[f], tips[f], carrier[f], body[(i + 1) % body.size()] - body[i],
                              r.h * fm.rate[f], r.poses[b], poses[b]);
      } else {
        const Pose<T>& step = steps[b];
        tips[f] = step.apply(tips[f]) + step.rotate(r.h * *fm.carried_slip[f]);  // step(p + h slip)
      }
    } else if (fm.free_velocity[f])
      tips[f] = tips[f] + r.h * *fm.free_velocity[f];
  }
  t = t + r.h;
  world_ = world_bodies(g_, poses);
  r.poses_after = poses;
  r.tips_after = tips;
  r.seconds = std::chrono::duration<double>(clock::now() - step_start).count();
  out_.steps.push_back(std::move(r));
  const StepRecord<T>& last = out_.steps.back();
  if (const std::string o = overlap(g_, world_, tips); !o.empty())
    finish(RunStatus::kOverlap,
           o + " after step " + std::to_string(k) + unkept_dips(dipping_contacts(cs.contacts, modes, steps)));
  else if (!last.cut_exact)
    finish(RunStatus::kIrrationalContactTime,
           last.cut_by + " closes at an irrational time: the run stops just before it, the gap > 0 (step " +
               std::to_string(k) + ")");
  return done(true);
}

template <class T>
Trajectory<T> simulate(const MotionScene& scene, const SimulateOptions& opts) {
  Stepper<T> s(scene, opts);
  while (s.step()) {
  }
  return s.take();
}

template class Stepper<Q>;
template class Stepper<double>;
template Trajectory<Q> simulate<Q>(const MotionScene&, const SimulateOptions&);
template Trajectory<double> simulate<double>(const MotionScene&, const SimulateOptions&);

}  // namespace contactcert::solvers::motion
