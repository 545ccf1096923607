#include "checker/ucp_check.h"

#include "checker/frame_check.h"
#include "checker/ucp_sets.h"
#include "exact/rational_text.h"
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

using ucp_sets::CheckData;

Vec<Q> read_vector(const JsonInput& in) { return in.rational_vector(); }

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
    if (!ucp_sets::primitive_or_zero(u))
      why = "it is not a primitive integer vector (integers with gcd 1)";
    else if (side == "X")
      why = c.quasistatic ? ucp_sets::check_velocity_farkas(c, zx, u) : ucp_sets::check_farkas(c.AX, c.bX, zx, u);
    else
      why = ucp_sets::check_farkas(c.AY, c.bY, zy, u);
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
  if (!ucp_sets::satisfies_X(c, x)) {
    out.reason = "x is not in X";
    return out;
  }
  out.verdict = CertificateVerdict::kValid;
  out.reason = "x in X, y in Y, both non-negative, and x^T y = 0 exactly";
  return out;
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
    if (const std::string why = ucp_sets::embedding_violation(cert, problem); !why.empty()) {
      out.reason = why;
      return out;
    }
    const CheckData c = ucp_sets::derive(problem);
    if (kind == "ucp_jammed") return check_jammed(cert, c);
    return check_solvable(cert, c);
  } catch (const InputError& e) {
    out.reason = std::string("malformed certificate: ") + e.what();
  }
  return out;
}

}  // namespace contactcert::checker
