#include "solvers/ucp/scene_builder.h"

#include "geometry/scene_json.h"

namespace contactcert::solvers::ucp {
namespace {

using exact::JsonInput;
using geometry::Point2;
using geometry::read_point;

SceneContact read_contact(const geometry::Shape& shape, const JsonInput& c, geometry::FrameRule frames) {
  c.expect_keys({"name", "point", "normal", "position", "mu", "finger"});
  SceneContact out;
  geometry::FrameInput given;
  const auto pos = c.find("position");
  if (pos) {
    if (c.find("point") || c.find("normal")) c.fail("either \"position\" or \"point\" and \"normal\", not both");
    given.position = read_point(*pos);
  } else {
    given.point = read_point(c.at("point"));
    given.normal = read_point(c.at("normal"));
  }
  const geometry::FrameResult frame = frames(shape, given);
  if (pos) {
    if (frame.status == geometry::FrameStatus::kOk && !frame.frame.touching())
      pos->fail("a position on the workpiece boundary (a contact touches; this one is off the workpiece)");
    if (frame.status != geometry::FrameStatus::kOk) pos->fail(frame.message);
  } else {
    if (frame.status == geometry::FrameStatus::kClosestNotUnique) c.at("point").fail(frame.message);
    if (frame.status != geometry::FrameStatus::kOk) c.at("normal").fail(frame.message);
  }
  out.r = frame.frame.point;
  out.n = frame.frame.normal;
  out.mu = c.at("mu").rational();
  if (sgn(out.mu) < 0) c.at("mu").fail("a friction coefficient >= 0");
  if (const auto f = c.find("finger")) {
    f->expect_keys({"axes", "velocity", "force"});
    out.finger = true;
    if (const auto axes = f->find("axes")) {
      const std::string a = axes->string();
      if (a != "frame" && a != "world") axes->fail("\"frame\" (joints along n and t) or \"world\" (along x and y)");
      out.world_axes = a == "world";
    }
    const auto v = f->find("velocity"), force = f->find("force");
    if (bool(v) == bool(force))
      f->fail("exactly one of \"velocity\" (a velocity-controlled finger) or \"force\" (force-controlled)");
    out.force_controlled = bool(force);
    out.given = read_point(v ? *v : *force);
  }
  return out;
}

/// The contacts of the scene `root` on the workpiece `w`, at least one.
std::vector<SceneContact> read_contacts(const JsonInput& root, const geometry::Workpiece& w,
                                        geometry::FrameRule frames) {
  std::vector<SceneContact> contacts;
  const JsonInput list = root.at("contacts");
  for (const JsonInput& c : list.elements()) contacts.push_back(read_contact(w.shape, c, frames));
  if (contacts.empty()) list.fail("at least one contact");
  return contacts;
}

}  // namespace

std::vector<geometry::ContactFrame> quasistatic_scene_frames(const JsonInput& root) {
  std::vector<geometry::ContactFrame> out;
  for (const SceneContact& c : read_contacts(root, geometry::read_workpiece(root.at("workpiece")), geometry::frame_of))
    out.push_back({c.r, c.n, Q(0)});
  return out;
}

QuasistaticProblem build_quasistatic_scene(const JsonInput& root, geometry::FrameRule frames) {
  root.expect_keys({"kind", "name", "description", "source", "note", "workpiece", "gravity", "contacts"});
  const geometry::Workpiece w = geometry::read_workpiece(root.at("workpiece"));
  const Point2 gravity = root.find("gravity") ? read_point(root.at("gravity")) : Point2{Q(0), Q(0)};
  return quasistatic_of_contacts(w.com, gravity, read_contacts(root, w, frames), root.file());
}

QuasistaticProblem quasistatic_of_contacts(const Point2& com, const Point2& gravity,
                                           const std::vector<SceneContact>& contacts, const std::string& file) {
  QuasistaticProblem p;
  p.nc = static_cast<int>(contacts.size());
  p.nq = 3;
  for (const SceneContact& c : contacts) p.ntheta += c.finger ? 2 : 0;
  p.Jn = Mat<Q>::Zero(p.nc, p.ntheta);
  p.Jt = Mat<Q>::Zero(p.nc, p.ntheta);
  p.theta_dot = Vec<Q>::Zero(p.ntheta);
  Mat<Q> Wt(2 * p.nc, 3);  // W^T: normal rows, then tangent rows (eq. 1)
  Vec<Q> tau = Vec<Q>::Zero(p.ntheta);
  int joint = 0;
  for (int i = 0; i < p.nc; ++i) {
    const SceneContact& c = contacts[static_cast<std::size_t>(i)];
    const Point2 t = geometry::perp(c.n);
    Wt.row(i) << c.n.x, c.n.y, geometry::cross(c.r, c.n);
    Wt.row(p.nc + i) << t.x, t.y, geometry::cross(c.r, t);
    if (!c.finger) continue;
    // The finger's joints: along (n, t) of its contact, or along (x, y).
    if (c.world_axes) {
      p.Jn.row(i).segment(joint, 2) << c.n.x, c.n.y;
      p.Jt.row(i).segment(joint, 2) << t.x, t.y;
    } else {
      p.Jn(i, joint) = 1;
      p.Jt(i, joint + 1) = 1;
    }
    for (int k = 0; k < 2; ++k) {
      const Q& v = k == 0 ? c.given.x : c.given.y;
      (c.force_controlled ? p.abar : p.alpha).push_back(joint + k);
      (c.force_controlled ? tau : p.theta_dot)(joint + k) = v;
    }
    joint += 2;
  }
  // P = [W^T  J_abar]; d = [0 (nc); g_obj; (g_man - tau)_abar] with g_man = 0.
  const auto m = static_cast<Eigen::Index>(3 + p.abar.size());
  p.P = Mat<Q>::Zero(2 * p.nc, m);
  p.P.leftCols(3) = Wt;
  p.d = Vec<Q>::Zero(p.nc + m);
  p.d.segment(p.nc, 3) << gravity.x, gravity.y, geometry::cross(com, gravity);
  for (std::size_t k = 0; k < p.abar.size(); ++k) {
    const int j = p.abar[k];
    p.P.col(3 + static_cast<Eigen::Index>(k)) << p.Jn.col(j), p.Jt.col(j);
    p.d(p.nc + 3 + static_cast<Eigen::Index>(k)) = -tau(j);
  }
  p.mu = Vec<Q>(p.nc);
  for (int i = 0; i < p.nc; ++i) p.mu(i) = contacts[static_cast<std::size_t>(i)].mu;
  validate(p, file);
  return p;
}

}  // namespace contactcert::solvers::ucp
