#include "checker/assembly_check.h"

#include <set>

#include "checker/sparse_motzkin_reader.h"
#include "checker/table2_rows.h"
#include "geometry/contact_frame.h"

namespace contactcert::checker {

using namespace solvers::assembly;  // the verdict and evidence types the certificate is read into
namespace {

/// Rows of the system of `letters` (s l r n *) over N bodies, or of the resting system (docs/formats.md section
/// 3a): the energy row, then per contact s: 1, l r: 2, n: 4, *: 3 (resting: its 2 friction rows), then 3N. Only
/// sizes the vectors read; the checker builds the rows themselves and refuses a vector of another length.
std::size_t system_rows(std::size_t N, const std::string& letters, std::size_t k, bool resting) {
  if (resting) return 2 * k + 3 * N;
  std::size_t rows = 1 + 3 * N;
  for (const char L : letters) rows += L == 's' ? 1 : L == 'n' ? 4 : L == '*' ? 3 : 2;
  return rows;
}

/// A prefix (`whole`: a mode) of k letters over s l r n, or InputError naming the field.
std::string read_letters(const exact::JsonInput& j, std::size_t k, bool whole) {
  const std::string text = j.string();
  if (text.find_first_not_of("slrn") != std::string::npos || text.size() > k || (whole && text.size() != k))
    j.fail(whole ? "a mode: one letter s l r n per contact (" + std::to_string(k) + ")"
                 : "a prefix: at most " + std::to_string(k) + " letters s l r n");
  return text;
}

using geometry::Point2;
using table2_check::Rows;
using Sign = Rows::Sign;

/// Where contact point p lies relative to body b: r = p - com_b, and the sign of the body's side (+1 `to`).
struct Touch {
  std::size_t body;
  Point2 r;
  int sign;
};

struct CheckedContact {
  Point2 n, t;
  std::vector<Touch> touches;
  Q mu_s, mu_k;
};

/// Re-verifies the frame (point on both boundaries, normal into `to` and out of `from`); "" if right.
std::string frame_violation(const geometry::Assembly& a, const geometry::AssemblyContact& c) {
  const geometry::Party* sides[] = {&c.from, &c.to};
  for (const geometry::Party* p : sides) {
    const Point2 n = p == &c.to ? c.normal : Q(-1) * c.normal;
    const geometry::Shape* shape = p->kind == geometry::Party::Kind::kBody       ? &a.bodies.at(p->index).shape
                                   : p->kind == geometry::Party::Kind::kObstacle ? &a.obstacles.at(p->index)
                                                                                 : nullptr;
    if (!shape) {
      const Point2 at =
          p->kind == geometry::Party::Kind::kFixel ? a.fixels.at(p->index) : a.fingers.at(p->index).position;
      if (!(at == c.point)) return "the contact point is not its point party's position";
      continue;
    }
    if (geometry::frame_from_contact(*shape, c.point, n, Q(0)).status != geometry::FrameStatus::kOk)
      return "the contact's point is not on both boundaries, or its normal is not a common normal from `from` into "
             "`to`";
  }
  return {};
}

std::vector<CheckedContact> checked_contacts(const geometry::Assembly& a) {
  std::vector<CheckedContact> out;
  for (const geometry::AssemblyContact& c : a.contacts) {
    CheckedContact cc{c.normal, {-c.normal.y, c.normal.x}, {}, c.mu_s, c.mu_k};
    if (c.from.movable()) cc.touches.push_back({c.from.index, c.point - a.bodies[c.from.index].com, -1});
    if (c.to.movable()) cc.touches.push_back({c.to.index, c.point - a.bodies[c.to.index].com, 1});
    out.push_back(cc);
  }
  return out;
}

/// The coefficients of d . (acc_to(p) - acc_from(p)) on (a_x, a_y, alpha) of each touching body.
void relative_row(const CheckedContact& c, const Point2& d, std::vector<Rows::Entry>& row) {
  for (const Touch& t : c.touches) {
    // d . (a_x - alpha r_y, a_y + alpha r_x)
    row.push_back({3 * t.body, t.sign * d.x});
    row.push_back({3 * t.body + 1, t.sign * d.y});
    row.push_back({3 * t.body + 2, t.sign * (d.y * t.r.x - d.x * t.r.y)});
  }
}

/// The rows of assembly_system.h's layout for `letters` (s l r n *), or the resting rows.
Rows checked_rows(const geometry::Assembly& a, const std::vector<CheckedContact>& cs, const std::string& letters,
                  bool resting) {
  const std::size_t N = a.bodies.size();
  Rows R;
  if (!resting) {
    // vdot, then e > 0 of the energy row g . vdot - e = 0 (every moving solution has g . vdot >= vdot^T M vdot > 0).
    R.columns.assign(3 * N, Sign::kFree);
    R.columns.push_back(Sign::kPositive);
    R.rows.emplace_back();
    for (std::size_t b = 0; b < N; ++b) {
      const geometry::Body& body = a.bodies[b];
      R.rows.back().push_back({3 * b, body.load_fx});
      R.rows.back().push_back({3 * b + 1, body.load_fy});
      R.rows.back().push_back({3 * b + 2, body.load_torque});
    }
    R.rows.back().push_back({3 * N, Q(-1)});
  }
  const auto col = [&R](Sign s) {
    R.columns.push_back(s);
    return R.columns.size() - 1;
  };
  // Per contact: c_n's column, c_t's column (or none) and c_t per c_n.
  std::vector<std::optional<std::size_t>> cn(cs.size()), ct(cs.size());
  std::vector<Q> slope(cs.size(), Q(0));
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const CheckedContact& c = cs[i];
    const char L = resting ? 'n' : letters[i];
    std::optional<std::size_t> sigma;
    if (L != 'n') sigma = col(L == '*' ? Sign::kNonNegative : Sign::kPositive);
    if (L == 's' || L == '*') {
      R.rows.emplace_back();
      relative_row(c, c.n, R.rows.back());
      R.rows.back().push_back({*sigma, Q(-1)});
    } else if (!resting) {
      R.rows.emplace_back();
      relative_row(c, c.n, R.rows.back());
      R.rows.emplace_back();
      relative_row(c, c.t, R.rows.back());
      if (L == 'l') R.rows.back().push_back({*sigma, Q(-1)});
      if (L == 'r') R.rows.back().push_back({*sigma, Q(1)});
    }
    if (L == 's') continue;
    cn[i] = col(Sign::kNonNegative);
    if (L == 'l' || L == 'r') {
      slope[i] = L == 'l' ? Q(-c.mu_k) : c.mu_k;
      continue;
    }
    ct[i] = col(Sign::kFree);
    const Q mu = L == '*' ? (c.mu_s < c.mu_k ? c.mu_k : c.mu_s) : c.mu_s;
    for (int s : {-1, 1}) {
      const std::size_t rho = col(Sign::kNonNegative);
      R.rows.push_back({{*cn[i], mu}, {*ct[i], Q(s)}, {rho, Q(-1)}});
    }
  }
  const std::size_t first = R.rows.size();
  R.rows.resize(first + 3 * N);
  R.b = Vec<Q>::Zero(static_cast<Eigen::Index>(first + 3 * N));
  for (std::size_t b = 0; b < N; ++b) {
    const geometry::Body& body = a.bodies[b];
    const Q M[3] = {body.mass, body.mass, body.inertia};
    const Q g[3] = {body.load_fx, body.load_fy, body.load_torque};
    for (std::size_t d = 0; d < 3; ++d) {
      if (!resting) R.rows[first + 3 * b + d].push_back({3 * b + d, M[d]});
      R.b(static_cast<Eigen::Index>(first + 3 * b + d)) = g[d];
    }
  }
  // The force c_n n + c_t t acts on `to` (sign +1) and its opposite on `from`: minus it on the left-hand side.
  for (std::size_t i = 0; i < cs.size(); ++i) {
    if (!cn[i]) continue;
    for (const Touch& t : cs[i].touches) {
      const auto wrench = [&](const Point2& f) { return std::array<Q, 3>{f.x, f.y, geometry::cross(t.r, f)}; };
      const auto wn = wrench(cs[i].n), wt = wrench(cs[i].t);
      for (std::size_t d = 0; d < 3; ++d) {
        auto& row = R.rows[first + 3 * t.body + d];
        if (ct[i]) {
          row.push_back({*cn[i], -t.sign * wn[d]});
          row.push_back({*ct[i], -t.sign * wt[d]});
        } else {
          row.push_back({*cn[i], -t.sign * (wn[d] + slope[i] * wt[d])});
        }
      }
    }
  }
  return R;
}

/// Body b's acceleration (a_x, a_y, alpha) within vdot.
Vec<Q> body_acceleration(const Vec<Q>& vdot, std::size_t b) {
  return vdot.segment(static_cast<Eigen::Index>(3 * b), 3);
}

/// Why c (c_1n..c_kn, c_1t..c_kt) and vdot fail the Newton-Euler rows, or "".
std::string newton_euler_violation(const geometry::Assembly& a, const std::vector<CheckedContact>& cs,
                                   const Vec<Q>& vdot, const Vec<Q>& c) {
  const auto k = static_cast<Eigen::Index>(cs.size());
  for (std::size_t b = 0; b < a.bodies.size(); ++b) {
    const geometry::Body& body = a.bodies[b];
    Q f[3] = {body.load_fx, body.load_fy, body.load_torque};
    for (Eigen::Index i = 0; i < k; ++i) {
      const CheckedContact& cc = cs[static_cast<std::size_t>(i)];
      const Point2 F = c(i) * cc.n + c(k + i) * cc.t;
      for (const Touch& t : cc.touches) {
        if (t.body != b) continue;
        f[0] += t.sign * F.x;
        f[1] += t.sign * F.y;
        f[2] += t.sign * geometry::cross(t.r, F);
      }
    }
    const Vec<Q> v = body_acceleration(vdot, b);
    if (!(body.mass * v(0) == f[0] && body.mass * v(1) == f[1] && body.inertia * v(2) == f[2]))
      return "body " + std::to_string(b) + ": M vdot != load + contact forces";
  }
  return {};
}

std::string resting_violation(const geometry::Assembly& a, const std::vector<CheckedContact>& cs, const Vec<Q>& c) {
  const auto k = static_cast<Eigen::Index>(cs.size());
  if (c.size() != 2 * k) return "resting forces of the wrong length";
  for (Eigen::Index i = 0; i < k; ++i)
    if (sgn(c(i)) < 0 || abs(c(k + i)) > cs[static_cast<std::size_t>(i)].mu_s * c(i))
      return "resting force of contact " + std::to_string(i) + " outside its static friction cone";
  return newton_euler_violation(a, cs, Vec<Q>::Zero(static_cast<Eigen::Index>(3 * a.bodies.size())), c);
}

/// Every mode over s l r n of k contacts extends a dead prefix: walks only prefixes of listed strings.
std::string coverage_violation(std::size_t k, const std::vector<AssemblyDeadPrefix>& dead) {
  std::set<std::string> is_dead, is_prefix;
  for (const AssemblyDeadPrefix& d : dead) {
    if (d.prefix.size() > k || d.prefix.find_first_not_of("slrn") != std::string::npos)
      return "dead prefix \"" + d.prefix + "\" is not a prefix of a mode";
    is_dead.insert(d.prefix);
    for (std::size_t j = 0; j <= d.prefix.size(); ++j) is_prefix.insert(d.prefix.substr(0, j));
  }
  std::vector<std::string> stack{""};
  while (!stack.empty()) {
    const std::string p = std::move(stack.back());
    stack.pop_back();
    if (is_dead.count(p)) continue;
    if (p.size() == k || !is_prefix.count(p)) return "no dead prefix covers the modes that start \"" + p + "\"";
    for (const char L : {'s', 'l', 'r', 'n'}) stack.push_back(p + L);
  }
  return {};
}

/// The order of a claim's dead prefixes' letters: `order` if it lists each of the k contacts once, the file's order
/// if it is empty; else empty.
std::vector<std::size_t> walk_positions(const std::vector<std::size_t>& order, std::size_t k) {
  std::vector<std::size_t> out(order);
  if (out.empty())
    for (std::size_t i = 0; i < k; ++i) out.push_back(i);
  std::vector<bool> seen(k, false);
  for (const std::size_t i : out) {
    if (out.size() != k || i >= k || seen[i]) return {};
    seen[i] = true;
  }
  return out;
}

/// The file-order letters of a prefix in the walk's order: contact order[j] takes letter j, the later ones `*`.
std::string placed_letters(const std::vector<std::size_t>& order, const std::string& prefix) {
  std::string letters(order.size(), '*');
  for (std::size_t j = 0; j < prefix.size(); ++j) letters[order[j]] = prefix[j];
  return letters;
}

}  // namespace

std::string assembly_motion_violation(const geometry::Assembly& a, const AssemblyMotion& m) {
  const std::vector<CheckedContact> cs = checked_contacts(a);
  const auto k = static_cast<Eigen::Index>(cs.size());
  const auto N = static_cast<Eigen::Index>(a.bodies.size());
  if (m.mode.size() != cs.size() || m.acceleration.size() != 3 * N || m.forces.size() != 2 * k)
    return "a moving solution of the wrong size";
  if (m.acceleration.isZero()) return "the moving solution has every body at rest";
  for (Eigen::Index i = 0; i < k; ++i) {
    const CheckedContact& c = cs[static_cast<std::size_t>(i)];
    std::vector<Rows::Entry> rn, rt;
    relative_row(c, c.n, rn);
    relative_row(c, c.t, rt);
    Q a_n = 0, a_t = 0;
    for (const auto& e : rn) a_n += e.value * m.acceleration(static_cast<Eigen::Index>(e.col));
    for (const auto& e : rt) a_t += e.value * m.acceleration(static_cast<Eigen::Index>(e.col));
    const Q &c_n = m.forces(i), &c_t = m.forces(k + i);
    bool ok = false;
    switch (m.mode[static_cast<std::size_t>(i)]) {
      case 's':
        ok = sgn(a_n) > 0 && sgn(c_n) == 0 && sgn(c_t) == 0;
        break;
      case 'l':
        ok = sgn(a_n) == 0 && sgn(a_t) > 0 && sgn(c_n) >= 0 && c_t == -c.mu_k * c_n;
        break;
      case 'r':
        ok = sgn(a_n) == 0 && sgn(a_t) < 0 && sgn(c_n) >= 0 && c_t == c.mu_k * c_n;
        break;
      case 'n':
        ok = sgn(a_n) == 0 && sgn(a_t) == 0 && sgn(c_n) >= 0 && abs(c_t) <= c.mu_s * c_n;
        break;
      default:
        break;
    }
    if (!ok)
      return "contact " + std::to_string(i) + " does not follow Table 2's letter " +
             m.mode.substr(static_cast<std::size_t>(i), 1);
  }
  return newton_euler_violation(a, cs, m.acceleration, m.forces);
}

CheckedAccelerations checked_accelerations(const geometry::Assembly& a) {
  CheckedAccelerations out;
  if (out.violation = assembly_frames_violation(a); !out.violation.empty()) return out;
  for (const CheckedContact& c : checked_contacts(a)) {
    out.rows.emplace_back();
    relative_row(c, c.n, out.rows.back()[0]);
    relative_row(c, c.t, out.rows.back()[1]);
  }
  return out;
}

std::string assembly_frames_violation(const geometry::Assembly& a) {
  for (std::size_t i = 0; i < a.contacts.size(); ++i)
    if (const std::string why = frame_violation(a, a.contacts[i]); !why.empty())
      return "contact " + std::to_string(i) + ": " + why;
  return "";
}

std::string check_assembly_stability(const geometry::Assembly& a, const AssemblyStabilityResult& claim) {
  if (claim.status != AssemblyStatus::kDecided) return "the verdict is not decided";
  if (const std::string why = assembly_frames_violation(a); !why.empty()) return why;
  const std::vector<CheckedContact> cs = checked_contacts(a);
  if (claim.has_moving)
    if (const std::string why = assembly_motion_violation(a, claim.moving); !why.empty()) return "moving: " + why;
  if (claim.verdict == AssemblyVerdict::kUnstable) {
    const Rows rest = checked_rows(a, cs, "", true);
    if (claim.resting_farkas.size() != static_cast<Eigen::Index>(rest.rows.size()) ||
        !table2_check::motzkin_holds(rest, claim.resting_farkas))
      return "unstable: the resting certificate does not prove the resting system infeasible";
    return {};
  }
  if (!claim.has_resting) return "a stable verdict without a resting solution";
  if (const std::string why = resting_violation(a, cs, claim.resting_forces); !why.empty()) return "resting: " + why;
  if (claim.verdict == AssemblyVerdict::kWeaklyStable)
    return claim.has_moving ? std::string() : "weakly stable without a moving solution";
  if (claim.has_moving) return "strongly stable with a moving solution";
  if (const std::string why = coverage_violation(cs.size(), claim.dead); !why.empty()) return why;
  const std::vector<std::size_t> order = walk_positions(claim.contact_order, cs.size());
  if (order.empty() && !cs.empty()) return "contact_order is not an order of the contacts (each index once)";
  for (const AssemblyDeadPrefix& d : claim.dead) {
    const Rows R = checked_rows(a, cs, placed_letters(order, d.prefix), false);
    if (d.motzkin.size() != static_cast<Eigen::Index>(R.rows.size()) || !table2_check::motzkin_holds(R, d.motzkin))
      return "dead prefix \"" + d.prefix + "\": its certificate does not prove the prefix's system infeasible";
  }
  return {};
}

AssemblyCertificateCheck check_assembly_certificate(const exact::JsonInput& c) {
  c.expect_keys({"kind", "verdict", "scene", "problem_sha256", "resting", "moving", "contact_order", "dead"});
  const exact::JsonInput embedded = exact::JsonInput::parse(c.at("scene").string(), c.file() + " (embedded scene)");
  const geometry::Assembly a = geometry::read_assembly(embedded);
  const std::size_t N = a.bodies.size(), k = a.contacts.size();
  AssemblyCertificateCheck out{false, "", N, k, 0};
  if (c.at("problem_sha256").string() != embedded.canonical_sha256()) {
    out.reason = "problem_sha256 is not the digest of the embedded scene";
    return out;
  }
  AssemblyStabilityResult claim;
  const std::string verdict = c.at("verdict").string();
  if (verdict == "strongly_stable")
    claim.verdict = AssemblyVerdict::kStronglyStable;
  else if (verdict == "weakly_stable")
    claim.verdict = AssemblyVerdict::kWeaklyStable;
  else if (verdict == "unstable")
    claim.verdict = AssemblyVerdict::kUnstable;
  else
    c.at("verdict").fail("expected strongly_stable, weakly_stable or unstable");
  const exact::JsonInput resting = c.at("resting");
  if (const auto f = resting.find("forces")) {
    resting.expect_keys({"forces"});
    claim.has_resting = true;
    claim.resting_forces = f->rational_vector(2 * k);
  } else {
    resting.expect_keys({"motzkin"});
    claim.resting_farkas = read_sparse_motzkin(resting.at("motzkin"), system_rows(N, "", k, true));
  }
  if (const auto m = c.find("moving")) {
    m->expect_keys({"mode", "acceleration", "forces"});
    claim.has_moving = true;
    claim.moving = {read_letters(m->at("mode"), k, true), m->at("acceleration").rational_vector(3 * N),
                    m->at("forces").rational_vector(2 * k)};
  }
  if (const auto order = c.find("contact_order")) {
    for (const exact::JsonInput& i : order->elements())
      claim.contact_order.push_back(static_cast<std::size_t>(i.integer(0, static_cast<long>(k) - 1)));
    if (walk_positions(claim.contact_order, k).empty())
      order->fail("each of the " + std::to_string(k) + " contacts once");
  }
  std::set<std::string> listed;
  for (const exact::JsonInput& d : c.at("dead").elements()) {
    d.expect_keys({"prefix", "motzkin"});
    std::string prefix = read_letters(d.at("prefix"), k, false);
    if (!listed.insert(prefix).second) {
      out.reason = "dead prefix \"" + prefix + "\" is listed twice";
      return out;
    }
    const std::string letters = prefix + std::string(k - prefix.size(), '*');
    claim.dead.push_back({std::move(prefix), read_sparse_motzkin(d.at("motzkin"), system_rows(N, letters, k, false))});
  }
  out.dead = claim.dead.size();
  const std::string why = check_assembly_stability(a, claim);
  out.valid = why.empty();
  out.reason = why.empty() ? "every vector of the evidence verifies exactly: " + verdict : why;
  return out;
}

}  // namespace contactcert::checker
