#include "checker/assembly_ucp_check.h"

#include <tuple>
#include <utility>

#include "checker/assembly_check.h"
#include "exact/rational_text.h"

namespace contactcert::checker {
namespace {

using exact::Mat;
using exact::Q;
using exact::Vec;
using geometry::Point2;
using Index = Eigen::Index;

/// The velocity of point p on a body whose q_dot is the unit vector e_k (k = 0: v_x, 1: v_y, 2: w).
Point2 unit_point_velocity(int k, const Point2& p) {
  if (k == 0) return {Q(1), Q(0)};
  if (k == 1) return {Q(0), Q(1)};
  return {-p.y, p.x};
}

/// "" if the matrices are equal, else where they first differ.
std::string differs(const std::string& name, const Mat<Q>& given, const Mat<Q>& derived) {
  if (given.rows() != derived.rows() || given.cols() != derived.cols())
    return name + " is " + std::to_string(given.rows()) + " x " + std::to_string(given.cols()) + ", the assembly's " +
           std::to_string(derived.rows()) + " x " + std::to_string(derived.cols());
  for (Index r = 0; r < given.rows(); ++r)
    for (Index c = 0; c < given.cols(); ++c)
      if (given(r, c) != derived(r, c))
        return name + "[" + std::to_string(r) + (given.cols() == 1 ? "" : "][" + std::to_string(c)) + "] is " +
               exact::to_string(given(r, c)) + ", the assembly's " + exact::to_string(derived(r, c));
  return "";
}

}  // namespace

std::string assembly_problem_violation(const geometry::Assembly& a, const solvers::ucp::QuasistaticProblem& p) {
  if (std::string why = assembly_frames_violation(a); !why.empty()) return why;
  const auto nc = static_cast<Index>(a.contacts.size()), nq = static_cast<Index>(3 * a.bodies.size());
  const auto ntheta = static_cast<Index>(2 * a.fingers.size());
  // The velocities and wrenches of eqs. (1) and (3), contact by contact.
  Mat<Q> Wt = Mat<Q>::Zero(2 * nc, nq), Jn = Mat<Q>::Zero(nc, ntheta), Jt = Mat<Q>::Zero(nc, ntheta);
  std::vector<Index> finger_contact(a.fingers.size(), -1);
  for (Index i = 0; i < nc; ++i) {
    const geometry::AssemblyContact& c = a.contacts[static_cast<std::size_t>(i)];
    const Point2 n = c.normal, t = geometry::perp(c.normal);
    for (const auto& [party, side] : {std::pair{c.from, -1}, std::pair{c.to, 1}}) {  // u_to(p) - u_from(p)
      if (party.movable())
        for (int k = 0; k < 3; ++k) {
          const Point2 u = unit_point_velocity(k, c.point);
          Wt(i, static_cast<Index>(3 * party.index) + k) = side * geometry::dot(n, u);
          Wt(nc + i, static_cast<Index>(3 * party.index) + k) = side * geometry::dot(t, u);
        }
    }
    if (c.to.kind == geometry::Party::Kind::kFinger) return "contact " + std::to_string(i) + " has a finger as `to`";
    if (c.from.kind != geometry::Party::Kind::kFinger) continue;
    if (finger_contact[c.from.index] >= 0) return "finger " + std::to_string(c.from.index) + " is in two contacts";
    finger_contact[c.from.index] = i;
    const geometry::Finger& f = a.fingers[c.from.index];
    const auto j = static_cast<Index>(2 * c.from.index);
    if (f.world_axes) {  // joint axes x and y
      Jn(i, j) = n.x, Jn(i, j + 1) = n.y, Jt(i, j) = t.x, Jt(i, j + 1) = t.y;
    } else {  // joint axes n and t of the contact
      Jn(i, j) = 1, Jt(i, j + 1) = 1;
    }
  }
  // The joints: velocity given (alpha) or force given (abar), and their values.
  std::vector<int> alpha, abar;
  Vec<Q> theta_dot = Vec<Q>::Zero(ntheta), tau = Vec<Q>::Zero(ntheta);
  for (std::size_t f = 0; f < a.fingers.size(); ++f) {
    if (finger_contact[f] < 0) return "finger " + std::to_string(f) + " is in no contact";
    const geometry::Finger& finger = a.fingers[f];
    for (int k = 0; k < 2; ++k) {
      const auto j = static_cast<int>(2 * f) + k;
      (finger.force_controlled ? abar : alpha).push_back(j);
      (finger.force_controlled ? tau : theta_dot)(j) = k == 0 ? finger.given.x : finger.given.y;
    }
  }
  const auto na = static_cast<Index>(abar.size());
  Mat<Q> P(2 * nc, nq + na);
  P.leftCols(nq) = Wt;
  Vec<Q> d = Vec<Q>::Zero(nc + nq + na);
  for (Index k = 0; k < na; ++k) {
    P.col(nq + k) << Jn.col(abar[static_cast<std::size_t>(k)]), Jt.col(abar[static_cast<std::size_t>(k)]);
    d(nc + nq + k) = -tau(abar[static_cast<std::size_t>(k)]);
  }
  for (std::size_t b = 0; b < a.bodies.size(); ++b) {  // each body's load about the world origin
    const geometry::Body& body = a.bodies[b];
    const auto r = nc + static_cast<Index>(3 * b);
    d(r) = body.load_fx, d(r + 1) = body.load_fy;
    d(r + 2) = body.load_torque + body.com.x * body.load_fy - body.com.y * body.load_fx;
  }
  Vec<Q> mu(nc);
  for (Index i = 0; i < nc; ++i) mu(i) = a.contacts[static_cast<std::size_t>(i)].mu_s;
  if (p.nc != nc || p.nq != nq || p.ntheta != ntheta)
    return "its sizes (nc, nq, ntheta) = (" + std::to_string(p.nc) + ", " + std::to_string(p.nq) + ", " +
           std::to_string(p.ntheta) + ") are not the assembly's (" + std::to_string(nc) + ", " + std::to_string(nq) +
           ", " + std::to_string(ntheta) + ")";
  if (p.alpha != alpha || p.abar != abar) return "its joints with given velocity or force are not the assembly's";
  for (const auto& [name, given, derived] :
       {std::tuple{"P", &p.P, &P}, std::tuple{"Jn", &p.Jn, &Jn}, std::tuple{"Jt", &p.Jt, &Jt}})
    if (std::string why = differs(name, *given, *derived); !why.empty()) return why;
  if (std::string why = differs("theta_dot", p.theta_dot, theta_dot); !why.empty()) return why;
  if (std::string why = differs("d", p.d, d); !why.empty()) return why;
  return differs("mu", p.mu, mu);
}

}  // namespace contactcert::checker
