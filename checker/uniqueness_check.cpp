#include "checker/uniqueness_check.h"

#include <algorithm>

#include "checker/frame_check.h"
#include "checker/mode_coverage.h"
#include "checker/ucp_sets.h"
#include "exact/rational_text.h"

namespace contactcert::checker {
namespace {

using Index = Eigen::Index;
using exact::JsonInput;
using exact::Q;
using exact::Vec;
using ucp_sets::CheckData;

/// The components of x = (v_n, v_t^+, v_t^-) and of y = (c_n, s_t^+, s_t^-) that a mode fixes to zero, contact i
/// owning components i, nc + i, 2nc + i of each: s (separate) y = 0; r (roll) x = 0; + (slide along +t, friction
/// c_t = -mu c_n) v_n = v_t^- = 0 and s_t^+ = 0; - (along -t) v_n = v_t^+ = 0 and s_t^- = 0; ? (undecided) none.
/// Each complementary pair (x_j, y_j) of a decided contact has a zero, so a mode's faces are complementary.
struct Zeros {
  std::vector<bool> x, y;
};

Zeros zeros_of(const std::string& mode) {
  const std::size_t nc = mode.size();
  Zeros z{std::vector<bool>(3 * nc, false), std::vector<bool>(3 * nc, false)};
  for (std::size_t i = 0; i < nc; ++i) {
    // Per letter, which of (v_n, v_t^+, v_t^-) and then of (c_n, s_t^+, s_t^-) are zero at contact i.
    const char l = mode[i];
    const char* zero = l == 's' ? "000111" : l == 'r' ? "111000" : l == '+' ? "101010" : l == '-' ? "110001" : "000000";
    for (std::size_t t = 0; t < 3; ++t) {
      z.x[t * nc + i] = zero[t] == '1';
      z.y[t * nc + i] = zero[3 + t] == '1';
    }
  }
  return z;
}

/// A mode (nc letters of s r + -) or, with `prefix`, a prefix of the tree (nc characters: '?' for the contacts
/// left undecided, then letters: the tree decides the last contact first); InputError naming `j` otherwise.
std::string read_mode(const JsonInput& j, std::size_t nc, bool prefix) {
  const std::string m = j.string();
  bool letters = false;
  for (const char ch : m) {
    const bool letter = ch == 's' || ch == 'r' || ch == '+' || ch == '-';
    if (!letter && !(prefix && ch == '?' && !letters))
      j.fail(prefix ? "a prefix: '?' for the undecided contacts, then one of s r + - per contact"
                    : "one letter s r + - per contact");
    letters = letters || letter;
  }
  if (m.size() != nc) j.fail(std::to_string(nc) + " characters, one per contact");
  return m;
}

/// The decided letters of a prefix in the order the tree decides them (the last contact first): the strings the
/// coverage walk takes (mode_coverage.h).
std::string tree_order(const std::string& mode) {
  std::string out;
  for (auto it = mode.rbegin(); it != mode.rend() && *it != '?'; ++it) out += *it;
  return out;
}

/// A string in the tree's order back as a pattern per contact ('?' for the contacts it leaves undecided).
std::string as_pattern(const std::string& tree, std::size_t nc) {
  return std::string(nc - std::min(nc, tree.size()), '?') + std::string(tree.rbegin(), tree.rend());
}

/// Why z is not in the non-negative orthant's face with the given zeros, or "".
std::string orthant_violation(const Vec<Q>& z, const std::vector<bool>& zero, const char* name) {
  for (Index j = 0; j < z.size(); ++j) {
    if (sgn(z(j)) < 0) return std::string(name) + "[" + std::to_string(j) + "] < 0";
    if (zero[static_cast<std::size_t>(j)] && sgn(z(j)) != 0)
      return std::string(name) + "[" + std::to_string(j) + "] is not 0 in this mode";
  }
  return "";
}

/// Why (x, y) is not a point of the mode's faces of X and Y, or "".
std::string point_violation(const CheckData& c, const Zeros& z, const Vec<Q>& x, const Vec<Q>& y) {
  if (std::string why = orthant_violation(x, z.x, "x"); !why.empty()) return why;
  if (std::string why = orthant_violation(y, z.y, "y"); !why.empty()) return why;
  if (!ucp_sets::satisfies_X(c, x)) return "x is not in X";
  if (c.AY * y != c.bY) return "y is not in Y";
  return "";
}

/// Why y does not prove dir * q_dot_k >= h^T y = bound over the mode's face of X, or "". For (u, x) with
/// P u = B x + h, x >= 0 and x_j = 0 where the mode fixes it: if P^T y = dir e_k and (B^T y)_j >= 0 on every free
/// j, then dir u_k = y^T P u = (B^T y)^T x + h^T y >= h^T y (weak LP duality).
std::string dual_violation(const CheckData& c, Index k, int dir, const std::vector<bool>& xzero, const Vec<Q>& y,
                           const Q& bound) {
  const Index nc = c.n / 3;
  if (y.size() != 2 * nc)
    return "it has " + std::to_string(y.size()) + " entries, expected 2nc = " + std::to_string(2 * nc);
  const Vec<Q> yP = c.P.transpose() * y;
  for (Index j = 0; j < yP.size(); ++j)
    if (yP(j) != (j == k ? Q(dir) : Q(0)))
      return "y^T P is not " + std::string(dir > 0 ? "" : "-") + "e_k in column " + std::to_string(j);
  for (Index j = 0; j < c.n; ++j)
    if (!xzero[static_cast<std::size_t>(j)] && sgn(j < 2 * nc ? y(j) : Q(-y(j - nc))) < 0)
      return "(B^T y)_" + std::to_string(j) + " < 0 on a component the mode leaves free";
  if (Q(c.h.dot(y)) != bound) return "h^T y = " + exact::to_string(Q(c.h.dot(y))) + ", not " + exact::to_string(bound);
  return "";
}

/// Whether every component a mode leaves free is free in `wide` too (the first face lies in the second).
bool inside(const std::vector<bool>& narrow_zero, const std::vector<bool>& wide_zero) {
  for (std::size_t j = 0; j < narrow_zero.size(); ++j)
    if (!narrow_zero[j] && wide_zero[j]) return false;
  return true;
}

UniquenessCertificateCheck check_unique(const JsonInput& cert, const CheckData& c, std::size_t nc, Index nq) {
  UniquenessCertificateCheck out;
  out.verdict = "unique";
  const Vec<Q> motion = cert.at("motion").rational_vector(static_cast<std::size_t>(nq));
  // Dead prefixes: each Farkas vector proves its face of X or Y empty (so are the faces of all its completions).
  std::vector<std::string> dead, leaves;
  for (const JsonInput& d : cert.at("dead").elements()) {
    d.expect_keys({"prefix", "empty", "farkas"});
    const std::string prefix = read_mode(d.at("prefix"), nc, true);
    const std::string side = d.at("empty").string();
    if (side != "X" && side != "Y") d.at("empty").fail("expected \"X\" or \"Y\"");
    const Vec<Q> f = d.at("farkas").rational_vector();
    const Zeros z = zeros_of(prefix);
    const std::string why = !ucp_sets::primitive_or_zero(f)
                                ? "it is not a primitive integer vector (integers with gcd 1)"
                            : side == "X" ? ucp_sets::check_velocity_farkas(c, z.x, f)
                                          : ucp_sets::check_farkas(c.AY, c.bY, z.y, f);
    if (!why.empty()) {
      out.reason = "dead prefix " + prefix + ": the Farkas vector for " + side + " fails: " + why;
      return out;
    }
    dead.push_back(tree_order(prefix));
  }
  // Solution modes: each with a point of its faces (so a solution exists).
  std::vector<std::vector<bool>> solution_zeros;
  for (const JsonInput& m : cert.at("solution_modes").elements()) {
    m.expect_keys({"mode", "x", "y"});
    const std::string mode = read_mode(m.at("mode"), nc, false);
    const Zeros z = zeros_of(mode);
    const std::string why = point_violation(c, z, m.at("x").rational_vector(3 * nc), m.at("y").rational_vector(3 * nc));
    if (!why.empty()) {
      out.reason = "solution mode " + mode + ": its point is not in its faces: " + why;
      return out;
    }
    leaves.push_back(tree_order(mode));
    solution_zeros.push_back(z.x);
  }
  out.dead = static_cast<long>(dead.size());
  out.solution_modes = static_cast<long>(leaves.size());
  if (leaves.empty()) {
    out.reason = "no solution mode is listed: a unique motion needs a solution";
    return out;
  }
  // The tree: every one of the 4^nc modes extends exactly one dead prefix or is exactly one solution mode.
  const auto letters = [](std::size_t) { return std::string("sr+-"); };
  if (auto gap = mode_coverage(nc, letters, dead, leaves)) {
    gap->prefix = as_pattern(gap->prefix, nc), gap->within = as_pattern(gap->within, nc);
    out.reason = "the prefix tree (one letter per contact, '?' for any): " + coverage_gap_text(*gap);
    return out;
  }
  // Bounds: each pins q_dot over its mode's face of X.
  const JsonInput bounds = cert.at("bounds");
  if (static_cast<double>(bounds.size()) * static_cast<double>(leaves.size()) > 1e7)
    bounds.fail("at most 10^7 (solution mode, bound) pairs to compare");
  std::vector<std::vector<bool>> bounded_zeros;
  for (const JsonInput& b : bounds.elements()) {
    b.expect_keys({"mode", "low", "high"});
    const std::string mode = read_mode(b.at("mode"), nc, false);
    const Zeros z = zeros_of(mode);
    const std::vector<JsonInput> low = b.at("low").elements(), high = b.at("high").elements();
    if (low.size() != static_cast<std::size_t>(nq))
      b.at("low").fail(std::to_string(nq) + " dual vectors, one per q_dot component");
    if (high.size() != static_cast<std::size_t>(nq))
      b.at("high").fail(std::to_string(nq) + " dual vectors, one per q_dot component");
    for (Index k = 0; k < nq; ++k)
      for (const int dir : {1, -1}) {
        const JsonInput& y = (dir > 0 ? low : high)[static_cast<std::size_t>(k)];
        const std::string why = dual_violation(c, k, dir, z.x, y.rational_vector(), Q(dir * motion(k)));
        if (!why.empty()) {
          out.reason =
              "bound of mode " + mode + ", q_dot[" + std::to_string(k) + "] " + (dir > 0 ? "low" : "high") + ": " + why;
          return out;
        }
      }
    bounded_zeros.push_back(z.x);
  }
  for (std::size_t i = 0; i < solution_zeros.size(); ++i) {
    bool covered = false;
    for (std::size_t b = 0; b < bounded_zeros.size() && !covered; ++b)
      covered = inside(solution_zeros[i], bounded_zeros[b]);
    if (!covered) {
      out.reason = "solution mode " + cert.at("solution_modes").at(i).at("mode").string() +
                   " lies in no bounded mode's face of X: its q_dot is not pinned";
      return out;
    }
  }
  out.valid = true;
  out.reason = "every solution has the same q_dot: " + std::to_string(out.dead) + " dead prefixes and " +
               std::to_string(out.solution_modes) + " solution modes cover the modes, and the duals of " +
               std::to_string(bounded_zeros.size()) + " bounded faces pin q_dot over every solution mode's face";
  return out;
}

UniquenessCertificateCheck check_not_unique(const JsonInput& cert, const CheckData& c, std::size_t nc, Index nq) {
  UniquenessCertificateCheck out;
  out.verdict = "not_unique";
  const JsonInput witnesses = cert.at("witnesses");
  if (witnesses.size() != 2) witnesses.fail("two solutions");
  std::vector<Vec<Q>> q;
  for (const JsonInput& w : witnesses.elements()) {
    w.expect_keys({"mode", "u", "x", "y"});
    const std::string mode = read_mode(w.at("mode"), nc, false);
    const Vec<Q> u = w.at("u").rational_vector(static_cast<std::size_t>(c.P.cols()));
    const Vec<Q> x = w.at("x").rational_vector(3 * nc), y = w.at("y").rational_vector(3 * nc);
    std::string why = point_violation(c, zeros_of(mode), x, y);
    if (why.empty() && c.P * u != Vec<Q>(ucp_sets::contact_velocity(c, x) + c.h)) why = "P u is not B x + h";
    if (!why.empty()) {
      out.reason = "witness " + std::to_string(q.size()) + " (mode " + mode + ") is not a solution: " + why;
      return out;
    }
    q.push_back(u.head(nq));
  }
  if (q[0] == q[1]) {
    out.reason = "the two witnesses have the same q_dot";
    return out;
  }
  out.valid = true;
  out.reason = "two solutions with different q_dot, each in its mode's faces of X and Y (complementary)";
  return out;
}

}  // namespace

UniquenessCertificateCheck check_uniqueness_certificate(const JsonInput& cert) {
  const std::string verdict = cert.at("verdict").string();
  if (verdict == "unique")
    cert.expect_keys({"kind", "format", "problem_sha256", "problem", "assembly", "verdict", "motion", "dead",
                      "solution_modes", "bounds"});
  else if (verdict == "not_unique")
    cert.expect_keys({"kind", "format", "problem_sha256", "problem", "assembly", "verdict", "witnesses"});
  else
    cert.at("verdict").fail("expected \"unique\" or \"not_unique\"");
  cert.at("format").integer(1, 1);
  // The frames of a quasistatic_scene are the checker's own (frame_check.h), never the solvers'.
  const solvers::ucp::UcpProblem problem =
      solvers::ucp::read_ucp_problem(cert.at("problem"), nullptr, frame_check::checked_frame);
  if (!problem.quasistatic) cert.at("problem").fail("a quasistatic problem (the certificate is about body velocities)");
  UniquenessCertificateCheck out;
  out.verdict = verdict;
  if (const std::string why = ucp_sets::embedding_violation(cert, problem); !why.empty()) {
    out.reason = why;
    return out;
  }
  const CheckData c = ucp_sets::derive(problem);
  const std::size_t nc = static_cast<std::size_t>(problem.quasistatic->nc);
  const Index nq = problem.quasistatic->nq;
  return verdict == "unique" ? check_unique(cert, c, nc, nq) : check_not_unique(cert, c, nc, nq);
}

}  // namespace contactcert::checker
