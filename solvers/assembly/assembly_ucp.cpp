#include "solvers/assembly/assembly_ucp.h"

namespace contactcert::solvers::assembly {

using Eigen::Index;
using exact::Mat;
using exact::Q;
using exact::Vec;
using geometry::Point2;

ucp::QuasistaticProblem assembly_quasistatic(const geometry::Assembly& a, const std::string& file) {
  ucp::QuasistaticProblem p;
  p.nc = static_cast<int>(a.contacts.size());
  p.nq = 3 * static_cast<int>(a.bodies.size());
  p.ntheta = 2 * static_cast<int>(a.fingers.size());
  // The contact of each finger.
  std::vector<long> contact_of(a.fingers.size(), -1);
  for (std::size_t i = 0; i < a.contacts.size(); ++i) {
    const geometry::AssemblyContact& c = a.contacts[i];
    if (c.to.kind == geometry::Party::Kind::kFinger)
      throw exact::InputError(file, "$.contacts[" + std::to_string(i) + "].to",
                              "a finger as the `from` party (the normal points from the finger into the body)");
    if (c.from.kind != geometry::Party::Kind::kFinger) continue;
    if (contact_of[c.from.index] >= 0)
      throw exact::InputError(file, "$.contacts[" + std::to_string(i) + "].from", "a finger in one contact only");
    contact_of[c.from.index] = static_cast<long>(i);
  }
  for (std::size_t f = 0; f < contact_of.size(); ++f)
    if (contact_of[f] < 0)
      throw exact::InputError(file, "$.fingers[" + std::to_string(f) + "]", "a finger in a contact");

  Mat<Q> Wt = Mat<Q>::Zero(2 * p.nc, p.nq);  // W^T: normal rows, then tangent rows (eq. 1)
  for (int i = 0; i < p.nc; ++i) {
    const geometry::AssemblyContact& c = a.contacts[static_cast<std::size_t>(i)];
    const Point2 t = geometry::perp(c.normal);
    for (const auto& [party, sign] : {std::pair{c.from, -1}, std::pair{c.to, 1}}) {
      if (!party.movable()) continue;
      const auto b = static_cast<Index>(3 * party.index);
      Wt.row(i).segment(b, 3) << sign * c.normal.x, sign * c.normal.y, sign * geometry::cross(c.point, c.normal);
      Wt.row(p.nc + i).segment(b, 3) << sign * t.x, sign * t.y, sign * geometry::cross(c.point, t);
    }
  }
  p.Jn = Mat<Q>::Zero(p.nc, p.ntheta);
  p.Jt = Mat<Q>::Zero(p.nc, p.ntheta);
  p.theta_dot = Vec<Q>::Zero(p.ntheta);
  Vec<Q> tau = Vec<Q>::Zero(p.ntheta);
  for (std::size_t f = 0; f < a.fingers.size(); ++f) {
    const geometry::Finger& finger = a.fingers[f];
    const auto i = static_cast<Index>(contact_of[f]);
    const auto joint = static_cast<Index>(2 * f);
    const Point2& n = a.contacts[static_cast<std::size_t>(i)].normal;
    const Point2 t = geometry::perp(n);
    if (finger.world_axes) {  // joints along x and y: rows n^T and t^T
      p.Jn.row(i).segment(joint, 2) << n.x, n.y;
      p.Jt.row(i).segment(joint, 2) << t.x, t.y;
    } else {  // joints along n and t: selection rows
      p.Jn(i, joint) = 1;
      p.Jt(i, joint + 1) = 1;
    }
    for (Index k = 0; k < 2; ++k) {
      const Q& v = k == 0 ? finger.given.x : finger.given.y;
      (finger.force_controlled ? p.abar : p.alpha).push_back(static_cast<int>(joint + k));
      (finger.force_controlled ? tau : p.theta_dot)(joint + k) = v;
    }
  }
  // P = [W^T  J_abar]; d = [0 (nc); g_obj; (g_man - tau)_abar] with g_man = 0.
  const auto m = static_cast<Index>(p.nq + static_cast<int>(p.abar.size()));
  p.P = Mat<Q>::Zero(2 * p.nc, m);
  p.P.leftCols(p.nq) = Wt;
  p.d = Vec<Q>::Zero(p.nc + m);
  for (std::size_t b = 0; b < a.bodies.size(); ++b) {
    const geometry::Body& body = a.bodies[b];
    const Point2 f{body.load_fx, body.load_fy};
    p.d.segment(p.nc + static_cast<Index>(3 * b), 3) << f.x, f.y, body.load_torque + geometry::cross(body.com, f);
  }
  for (std::size_t k = 0; k < p.abar.size(); ++k) {
    const int j = p.abar[k];
    p.P.col(p.nq + static_cast<Index>(k)) << p.Jn.col(j), p.Jt.col(j);
    p.d(p.nc + p.nq + static_cast<Index>(k)) = -tau(j);
  }
  p.mu = Vec<Q>(p.nc);
  for (int i = 0; i < p.nc; ++i) p.mu(i) = a.contacts[static_cast<std::size_t>(i)].mu_s;
  ucp::validate(p, file);
  return p;
}

}  // namespace contactcert::solvers::assembly
