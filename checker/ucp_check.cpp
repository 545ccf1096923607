#include "checker/ucp_check.h"

#include "checker/assembly_ucp_check.h"
#include "checker/frame_check.h"
#include "exact/linalg.h"
#include "exact/rational_text.h"
#include "geometry/assembly.h"
#include "solvers/ucp/problem.h"

namespace contactcert::checker {

namespace {
using Index = Eigen::Index;
using exact::InputError;
using exact::JsonInput;
using exact::Mat;
using exact::Q;
using exact::Vec;
using solvers::ucp::QuasistaticProblem;
using solvers::ucp::UcpInstance;
using solvers::ucp::UcpProblem;

/// The data a checker needs, derived from the problem file by the checker itself (not by build_X / build_Y).
struct CheckData {
  bool quasistatic = false;
  Index n = 0;
  // Generic form, or Y of a quasistatic problem: {z >= 0 : A z = b}.
  Mat<Q> AX, AY;
  Vec<Q> bX, bY;
  // Quasistatic X: B x + h in the column space of P.
  Mat<Q> P;
  Vec<Q> h;
};

CheckData derive(const UcpProblem& u) {
  CheckData c;
  if (!u.quasistatic) {
    const UcpInstance<Q>& ucp = u.ucp();
    c.n = ucp.n();
    c.AX = ucp.X.A, c.bX = ucp.X.b, c.AY = ucp.Y.A, c.bY = ucp.Y.b;
    return c;
  }
  const QuasistaticProblem& p = *u.quasistatic;
  const Index nc = p.nc, nq = p.nq, na = static_cast<Index>(p.abar.size());
  c.quasistatic = true;
  c.n = 3 * nc;
  c.P = p.P;
  c.h = Vec<Q>::Zero(2 * nc);
  for (int j : p.alpha)
    for (Index i = 0; i < nc; ++i) {
      c.h(i) += p.Jn(i, j) * p.theta_dot(j);
      c.h(nc + i) += p.Jt(i, j) * p.theta_dot(j);
    }
  // Y = {(c_n, s+, s-) >= 0 : 2U c_n - s+ - s- = 0, (W_n - W_t U) c_n + W_t s+ = -g_obj,
  //      ((J_n^T)_abar - (J_t^T)_abar U) c_n + (J_t^T)_abar s+ = (tau - g_man)_abar}.
  c.AY = Mat<Q>::Zero(nc + nq + na, 3 * nc);
  for (Index i = 0; i < nc; ++i) {
    c.AY(i, i) = 2 * p.mu(i);
    c.AY(i, nc + i) = -1;
    c.AY(i, 2 * nc + i) = -1;
    for (Index k = 0; k < nq; ++k) {
      const Q wn = p.P(i, k), wt = p.P(nc + i, k);
      c.AY(nc + k, i) = wn - wt * p.mu(i);
      c.AY(nc + k, nc + i) = wt;
    }
    for (Index a = 0; a < na; ++a) {
      const int j = p.abar[static_cast<std::size_t>(a)];
      c.AY(nc + nq + a, i) = p.Jn(i, j) - p.Jt(i, j) * p.mu(i);
      c.AY(nc + nq + a, nc + i) = p.Jt(i, j);
    }
  }
  c.bY = -p.d;
  return c;
}

/// Checks that `u` proves {z >= 0 : A z = b, z_j = 0 for zero[j]} empty; returns "" or why not.
std::string check_farkas(const Mat<Q>& A, const Vec<Q>& b, const std::vector<bool>& zero, const Vec<Q>& u) {
  if (u.size() != A.rows())
    return "Farkas vector has " + std::to_string(u.size()) + " entries, expected " + std::to_string(A.rows());
  const Vec<Q> g = A.transpose() * u;
  for (Index j = 0; j < g.size(); ++j)
    if (!zero[static_cast<std::size_t>(j)] && sgn(g(j)) < 0)
      return "u^T A_" + std::to_string(j) + " < 0 on a column that is not fixed to zero";
  const Q ub = u.dot(b);
  if (sgn(ub) >= 0) return "u^T b >= 0";
  return "";
}

/// Quasistatic X side: w^T P = 0, (w_n, w_t, -w_t) >= 0 on free columns, w^T h > 0.
std::string check_velocity_farkas(const CheckData& c, const std::vector<bool>& zero, const Vec<Q>& w) {
  const Index nc = c.n / 3;
  if (w.size() != 2 * nc)
    return "Farkas vector has " + std::to_string(w.size()) + " entries, expected 2nc = " + std::to_string(2 * nc);
  const Vec<Q> wP = c.P.transpose() * w;
  for (Index k = 0; k < wP.size(); ++k)
    if (sgn(wP(k)) != 0) return "w^T P is not zero in column " + std::to_string(k);
  for (Index j = 0; j < c.n; ++j) {
    if (zero[static_cast<std::size_t>(j)]) continue;
    const Q g = j < 2 * nc ? w(j) : Q(-w(j - nc));
    if (sgn(g) < 0) return "w^T B_" + std::to_string(j) + " < 0 on a column that is not fixed to zero";
  }
  if (sgn(Q(w.dot(c.h))) <= 0) return "w^T J_alpha theta_dot_alpha <= 0";
  return "";
}

Vec<Q> read_vector(const JsonInput& in) { return in.rational_vector(); }

/// Whether u is written as documented: integers with gcd 1 (the zero vector fails the Farkas conditions itself).
bool primitive_or_zero(const Vec<Q>& u) {
  exact::Z g = 0;
  for (Index i = 0; i < u.size(); ++i) {
    if (u(i).get_den() != 1) return false;
    g = gcd(g, u(i).get_num());
  }
  return g == 0 || g == 1;
}

CertificateCheck check_jammed(const JsonInput& cert, const CheckData& c) {
  CertificateCheck out;
  out.kind = "ucp_jammed";
  const JsonInput nodes = cert.at("nodes");
  const std::size_t count = nodes.size();
  if (count == 0) {
    out.reason = "the tree has no nodes";
    return out;
  }
  // Depth-first with one set of fixings, set on the way down and cleared on the way up: memory O(n + depth),
  // bounded by the certificate's size whatever the tree (and depth <= n: a path splits each pair once).
  std::vector<bool> seen(count, false);
  std::vector<bool> zx(static_cast<std::size_t>(c.n), false), zy = zx;
  struct Frame {
    std::size_t id;
    int stage = 0;                        // 0: not entered; 1: x-child done; 2: y-child done
    std::size_t branch = 0, y_child = 0;  // branch is free on the path above (checked on entry)
  };
  std::vector<Frame> stack{{0}};
  while (!stack.empty()) {
    Frame& f = stack.back();
    if (f.stage == 1) {  // x_i = 0 explored; now y_i = 0
      zx[f.branch] = false;
      zy[f.branch] = true;
      f.stage = 2;
      stack.push_back({f.y_child});
      continue;
    }
    if (f.stage == 2) {
      zy[f.branch] = false;
      stack.pop_back();
      continue;
    }
    const std::string where = "node " + std::to_string(f.id) + ": ";
    if (seen[f.id]) {
      out.reason = where + "reached twice (the nodes must form a tree)";
      return out;
    }
    seen[f.id] = true;
    ++out.nodes;
    const JsonInput node = nodes.at(f.id);
    if (node.find("branch")) {
      node.expect_keys({"branch", "x_zero", "y_zero"});
      f.branch = static_cast<std::size_t>(node.at("branch").integer(0, static_cast<long>(c.n) - 1));
      // A pair already split on this path has x_i = 0 or y_i = 0: one child would repeat its parent's face.
      if (zx[f.branch] || zy[f.branch]) {
        out.reason = where + "branches on " + std::to_string(f.branch) +
                     ", which this path has fixed already (an extra node: one child repeats its parent)";
        return out;
      }
      const long limit = static_cast<long>(count) - 1;
      const auto a = static_cast<std::size_t>(node.at("x_zero").integer(0, limit));
      f.y_child = static_cast<std::size_t>(node.at("y_zero").integer(0, limit));
      zx[f.branch] = true;  // x_i = 0
      f.stage = 1;
      stack.push_back({a});  // invalidates f
      continue;
    }
    node.expect_keys({"empty", "farkas"});
    ++out.leaves;
    const std::string side = node.at("empty").string();
    const Vec<Q> u = read_vector(node.at("farkas"));
    if (side != "X" && side != "Y") node.at("empty").fail("expected \"X\" or \"Y\"");
    std::string why;
    if (!primitive_or_zero(u))
      why = "it is not a primitive integer vector (integers with gcd 1)";
    else if (side == "X")
      why = c.quasistatic ? check_velocity_farkas(c, zx, u) : check_farkas(c.AX, c.bX, zx, u);
    else
      why = check_farkas(c.AY, c.bY, zy, u);
    if (!why.empty()) {
      out.reason = where + "the Farkas vector for " + side + " fails: " + why;
      return out;
    }
    stack.pop_back();
  }
  for (std::size_t k = 0; k < count; ++k)
    if (!seen[k]) {
      out.reason = "node " + std::to_string(k) + " is not reachable from the root";
      return out;
    }
  out.verdict = CertificateVerdict::kValid;
  out.reason = "every one of the " + std::to_string(out.leaves) +
               " leaves proves its face of X or Y empty, and the branches cover every complementary pair";
  return out;
}

CertificateCheck check_solvable(const JsonInput& cert, const CheckData& c) {
  CertificateCheck out;
  out.kind = "ucp_solvable";
  const Vec<Q> x = cert.at("x").rational_vector(static_cast<std::size_t>(c.n));
  const Vec<Q> y = cert.at("y").rational_vector(static_cast<std::size_t>(c.n));
  for (Index j = 0; j < c.n; ++j)
    if (sgn(x(j)) < 0 || sgn(y(j)) < 0) {
      out.reason = "x or y has a negative entry at " + std::to_string(j);
      return out;
    }
  if (sgn(Q(x.dot(y))) != 0) {
    out.reason = "x^T y = " + exact::to_string(x.dot(y)) + " is not zero";
    return out;
  }
  if (c.AY * y != c.bY) {
    out.reason = "y is not in Y";
    return out;
  }
  bool x_in = false;
  if (c.quasistatic) {
    const Index nc = c.n / 3;
    Vec<Q> v(2 * nc);
    v << x.head(nc), Vec<Q>(x.segment(nc, nc) - x.tail(nc));
    x_in = exact::solve<Q>(c.P, Vec<Q>(v + c.h)).has_value();
  } else {
    x_in = c.AX * x == c.bX;
  }
  if (!x_in) {
    out.reason = "x is not in X";
    return out;
  }
  out.verdict = CertificateVerdict::kValid;
  out.reason = "x in X, y in Y, both non-negative, and x^T y = 0 exactly";
  return out;
}

/// With an embedded assembly (`assembly --ucp`): why the embedded problem is not the one the checker derives from
/// the assembly's geometry (assembly_ucp_check.h), or "".
std::string assembly_violation(const JsonInput& cert, const UcpProblem& problem) {
  const auto text = cert.find("assembly");
  if (!text) return "";
  const geometry::Assembly a =
      geometry::read_assembly(JsonInput::parse(text->string(), cert.file() + " (embedded assembly)"));
  const std::string why =
      problem.quasistatic ? assembly_problem_violation(a, *problem.quasistatic) : "it is not a quasistatic problem";
  return why.empty() ? "" : "the embedded problem is not the quasistatic problem of the embedded assembly: " + why;
}

}  // namespace

CertificateCheck check_ucp_certificate(const JsonInput& cert) {
  const std::string kind = cert.at("kind").string();
  CertificateCheck out;
  out.kind = kind;
  // An unreadable embedded problem is bad input (exit 2); errors in the evidence make the certificate invalid. The
  // frames of a quasistatic_scene are the checker's own (frame_check.h), never the solvers'.
  const UcpProblem problem = solvers::ucp::read_ucp_problem(cert.at("problem"), nullptr, frame_check::checked_frame);
  try {
    if (kind == "ucp_jammed")
      cert.expect_keys({"kind", "format", "problem_sha256", "problem", "assembly", "reason", "nodes"});
    else if (kind == "ucp_solvable")
      cert.expect_keys({"kind", "format", "problem_sha256", "problem", "assembly", "x", "y"});
    else
      cert.at("kind").fail("expected \"ucp_jammed\" or \"ucp_solvable\"");
    cert.at("format").integer(2, 2);
    if (cert.at("problem_sha256").string() != cert.at("problem").canonical_sha256()) {
      out.reason = "problem_sha256 is not the digest of the embedded problem";
      return out;
    }
    if (const std::string why = assembly_violation(cert, problem); !why.empty()) {
      out.reason = why;
      return out;
    }
    const CheckData c = derive(problem);
    if (kind == "ucp_jammed") return check_jammed(cert, c);
    return check_solvable(cert, c);
  } catch (const InputError& e) {
    out.reason = std::string("malformed certificate: ") + e.what();
  }
  return out;
}

}  // namespace contactcert::checker
