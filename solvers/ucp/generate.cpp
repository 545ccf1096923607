#include "solvers/ucp/generate.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "exact/rational_text.h"

namespace contactcert::solvers::ucp {

namespace {
using Index = Eigen::Index;

Q uniform_q(std::mt19937_64& rng, long lo, long hi, long den) {
  std::uniform_int_distribution<long> d(lo, hi);
  Q q(d(rng), den);
  q.canonicalize();
  return q;
}

/// A rational unit vector ((a^2 - b^2), 2ab) / (a^2 + b^2), rotated into a random quadrant.
std::pair<Q, Q> pythagorean_direction(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> d(1, 6);
  int a = d(rng), b = d(rng);
  while (a == b) b = d(rng);
  Q s(a * a + b * b);
  Q c = Q(a * a - b * b) / s, t = Q(2 * a * b) / s;
  switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
    case 0:
      return {c, t};
    case 1:
      return {-t, c};
    case 2:
      return {-c, -t};
    default:
      return {t, -c};
  }
}

Q cross(const Q& a1, const Q& a2, const Q& b1, const Q& b2) { return a1 * b2 - a2 * b1; }
}  // namespace

UcpProblem generate_random_problem(const RandomProblemOptions& o, std::mt19937_64& rng) {
  if (o.nc < 1 || o.abar_size < 0 || o.abar_size > 2 * o.nc || sgn(o.mu_max) <= 0)
    throw std::invalid_argument("random problem: need nc >= 1, 0 <= |abar| <= 2nc, mu_max > 0");
  const int nc = o.nc, nq = 3, nt = 2 * nc;
  QuasistaticProblem p;
  p.nc = nc;
  p.nq = nq;
  p.ntheta = nt;
  Mat<Q> Wn(nq, nc), Wt(nq, nc);
  for (int i = 0; i < nc; ++i) {
    // Contact point r_i on the workpiece; inward normal n_i (toward the centre of gravity at the origin).
    Q rx = uniform_q(rng, -10, 10, 10), ry = uniform_q(rng, -10, 10, 10);
    auto [nx, ny] = pythagorean_direction(rng);
    if (sgn(Q(nx * rx + ny * ry)) > 0) nx = -nx, ny = -ny;
    const Q tx = -ny, ty = nx;                                       // n x t points out of the plane
    Wn(0, i) = nx, Wn(1, i) = ny, Wn(2, i) = cross(rx, ry, nx, ny);  // eq. (1)
    Wt(0, i) = tx, Wt(1, i) = ty, Wt(2, i) = cross(rx, ry, tx, ty);
  }
  // Point fingers: joint 2i moves finger i along n_i, joint 2i+1 along t_i.
  p.Jn = Mat<Q>::Zero(nc, nt);
  p.Jt = Mat<Q>::Zero(nc, nt);
  for (int i = 0; i < nc; ++i) p.Jn(i, 2 * i) = 1, p.Jt(i, 2 * i + 1) = 1;
  p.mu = Vec<Q>(nc);
  Q mu_max = o.mu_max;
  mu_max.canonicalize();
  for (int i = 0; i < nc; ++i) p.mu(i) = mu_max * uniform_q(rng, 1, 19, 20);
  // Friction-consistent forces: |c_t| <= mu c_n (7); then (2), (3) give g_obj and tau - g_man.
  Vec<Q> cn(nc), ct(nc);
  for (int i = 0; i < nc; ++i) {
    cn(i) = uniform_q(rng, 0, 10, 5);
    ct(i) = p.mu(i) * cn(i) * uniform_q(rng, -10, 10, 10);
  }
  const Vec<Q> g_obj = -(Wn * cn + Wt * ct);
  const Vec<Q> tau_minus_gman = p.Jn.transpose() * cn + p.Jt.transpose() * ct;
  // Non-negative v_n and a random q_dot; theta_dot from (4), (5).
  Vec<Q> q_dot(nq), vn(nc), vt(nc);
  for (int k = 0; k < nq; ++k) q_dot(k) = uniform_q(rng, -10, 10, 10);
  for (int i = 0; i < nc; ++i) vn(i) = uniform_q(rng, 0, 5, 5), vt(i) = uniform_q(rng, -5, 5, 5);
  const Vec<Q> wn = Wn.transpose() * q_dot, wt = Wt.transpose() * q_dot;
  Vec<Q> theta(nt);
  for (int i = 0; i < nc; ++i) theta(2 * i) = wn(i) - vn(i), theta(2 * i + 1) = wt(i) - vt(i);
  // abar: a random set of effort-controlled joints.
  std::vector<int> joints(static_cast<std::size_t>(nt));
  std::iota(joints.begin(), joints.end(), 0);
  std::shuffle(joints.begin(), joints.end(), rng);
  p.abar.assign(joints.begin(), joints.begin() + o.abar_size);
  std::sort(p.abar.begin(), p.abar.end());
  for (int j = 0; j < nt; ++j)
    if (!std::binary_search(p.abar.begin(), p.abar.end(), j)) p.alpha.push_back(j);
  p.theta_dot = Vec<Q>::Zero(nt);
  for (int j : p.alpha) p.theta_dot(j) = theta(j);
  const Index na = o.abar_size;
  p.P = Mat<Q>(2 * nc, nq + na);
  p.P.block(0, 0, nc, nq) = Wn.transpose();
  p.P.block(nc, 0, nc, nq) = Wt.transpose();
  for (Index k = 0; k < na; ++k) {
    const int j = p.abar[static_cast<std::size_t>(k)];
    p.P.block(0, nq + k, nc, 1) = p.Jn.col(j);
    p.P.block(nc, nq + k, nc, 1) = p.Jt.col(j);
  }
  p.d = Vec<Q>::Zero(nc + nq + na);
  p.d.segment(nc, nq) = g_obj;
  for (Index k = 0; k < na; ++k) p.d(nc + nq + k) = -tau_minus_gman(p.abar[static_cast<std::size_t>(k)]);
  validate(p, "generated");
  UcpProblem u;
  u.quasistatic = p;
  u.set(build_ucp(p));
  u.source = "random problem (Pang, Trinkle, Lo section 5): nc=" + std::to_string(nc) + " mu in (0," +
             exact::to_string(mu_max) + ") |abar|=" + std::to_string(na);
  return u;
}

UcpProblem reduction_problem(const ZeroOneProblem& zo) {
  const Index m = zo.A.rows(), n = zo.A.cols();
  const Mat<Q> I = Mat<Q>::Identity(n, n);
  UcpInstance<Q> ucp;
  ucp.X.A = Mat<Q>::Zero(m + n, 2 * n);
  ucp.X.A.block(0, 0, m, n) = zo.A;  // A z = b
  ucp.X.A.block(m, 0, n, n) = I;     // z + w = e
  ucp.X.A.block(m, n, n, n) = I;
  ucp.Y.A = Mat<Q>::Zero(m + n, 2 * n);
  ucp.Y.A.block(0, n, m, n) = zo.A;  // A v = b
  ucp.Y.A.block(m, 0, n, n) = I;     // u + v = e
  ucp.Y.A.block(m, n, n, n) = I;
  Vec<Q> rhs(m + n);
  rhs << zo.b, Vec<Q>::Ones(n);
  ucp.X.b = rhs;
  ucp.Y.b = rhs;
  UcpProblem u;
  u.set(std::move(ucp));
  u.source = "Proposition 2 reduction of a 0-1 problem with " + std::to_string(m) + " rows and " + std::to_string(n) +
             " columns";
  return u;
}

ZeroOneProblem random_zero_one(int m, int n, bool planted, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> a(-3, 3), bit(0, 1);
  ZeroOneProblem zo{Mat<Q>(m, n), Vec<Q>(m)};
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) zo.A(i, j) = a(rng);
  if (planted) {
    Vec<Q> z(n);
    for (int j = 0; j < n; ++j) z(j) = bit(rng);
    zo.b = zo.A * z;
  } else {
    std::uniform_int_distribution<int> bd(-n, n);
    for (int i = 0; i < m; ++i) zo.b(i) = bd(rng);
  }
  return zo;
}

bool zero_one_feasible(const ZeroOneProblem& zo) {
  const Index n = zo.A.cols();
  if (n > 20) throw std::invalid_argument("zero_one_feasible: brute force needs n <= 20");
  for (unsigned long mask = 0; mask < (1ul << n); ++mask) {
    Vec<Q> z(n);
    for (Index j = 0; j < n; ++j) z(j) = (mask >> j) & 1ul;
    if (zo.A * z == zo.b) return true;
  }
  return false;
}

}  // namespace contactcert::solvers::ucp
