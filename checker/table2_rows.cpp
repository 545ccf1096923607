#include "checker/table2_rows.h"

#include <algorithm>
#include <optional>
#include <sstream>

namespace contactcert::checker::table2_check {
namespace {

using W = std::array<Q, 3>;

// What Table 2 says of one acceleration.
enum class Acc : char { kFree, kZero, kNonNegative, kPositive, kNegative };
// What it says of the contact force.
enum class Force : char { kNone, kLeftEdge, kRightEdge, kStaticCone };

struct Letter {
  Acc a_n, a_t;
  Force c;
};

// Table 2's row of letter L at a fixel that touches or not; nullopt if L is no letter or does not fit the fixel.
std::optional<Letter> table2_letter(char L, bool touching, bool printed_separation) {
  const bool strict_s = touching && !printed_separation;
  switch (L) {
    case 's':
      return Letter{strict_s ? Acc::kPositive : Acc::kNonNegative, Acc::kFree, Force::kNone};
    case 'S':
      return Letter{Acc::kNonNegative, Acc::kFree, Force::kNone};
    case 'a':
      if (touching) return std::nullopt;
      return Letter{Acc::kNegative, Acc::kFree, Force::kNone};
    case 'u':
      if (touching) return std::nullopt;
      return Letter{Acc::kFree, Acc::kFree, Force::kNone};
    case 'l':
      if (!touching) return std::nullopt;
      return Letter{Acc::kZero, Acc::kPositive, Force::kLeftEdge};
    case 'r':
      if (!touching) return std::nullopt;
      return Letter{Acc::kZero, Acc::kNegative, Force::kRightEdge};
    case 'n':
      if (!touching) return std::nullopt;
      return Letter{Acc::kZero, Acc::kZero, Force::kStaticCone};
    case 'm':
      if (!touching) return std::nullopt;
      return Letter{Acc::kZero, Acc::kFree, Force::kStaticCone};
    default:
      return std::nullopt;
  }
}

bool signed_row(Acc a) { return a == Acc::kNonNegative || a == Acc::kPositive || a == Acc::kNegative; }

bool meets(Acc a, int sign) {
  switch (a) {
    case Acc::kFree:
      return true;
    case Acc::kZero:
      return sign == 0;
    case Acc::kNonNegative:
      return sign >= 0;
    case Acc::kPositive:
      return sign > 0;
    case Acc::kNegative:
      return sign < 0;
  }
  return false;
}

Q dot(const W& w, const Vec<Q>& v) { return w[0] * v(0) + w[1] * v(1) + w[2] * v(2); }

// x times the wrench w, added to the three entries of acc.
void add_scaled(W& acc, const Q& x, const W& w) {
  for (std::size_t d = 0; d < 3; ++d) acc[d] += x * w[d];
}

std::size_t add_column(Rows& r, Rows::Sign s) {
  r.columns.push_back(s);
  return r.columns.size() - 1;
}

// A row w . vdot (vdot in columns 0-2) plus `slack` times the column sigma (if slack != 0).
void add_acceleration_row(Rows& r, const W& w, int slack, std::size_t sigma) {
  std::vector<Rows::Entry> row;
  for (std::size_t d = 0; d < 3; ++d) row.push_back({d, w[d]});
  if (slack != 0) row.push_back({sigma, Q(slack)});
  r.rows.push_back(std::move(row));
}

// Fixel f's kinematic rows under its letter: a_n's, then a_t's; a signed row gets a slack column of its own,
// a_x - sigma = 0 for a_x >= 0 or > 0, a_x + sigma = 0 for a_x < 0 (> 0 or < 0: sigma strict). At most one of a
// fixel's two rows is signed.
void add_kinematic(Rows& r, const CheckedFixel& f, const Letter& L) {
  std::size_t sigma = 0;
  for (Acc a : {L.a_n, L.a_t})
    if (signed_row(a)) sigma = add_column(r, a == Acc::kNonNegative ? Rows::Sign::kNonNegative : Rows::Sign::kPositive);
  auto row = [&](Acc a, const W& w) {
    if (a == Acc::kFree) return;
    add_acceleration_row(r, w, !signed_row(a) ? 0 : a == Acc::kNegative ? 1 : -1, sigma);
  };
  row(L.a_n, f.w_n);
  row(L.a_t, f.w_t);
}

Rows vdot_columns() {
  Rows r;
  r.columns.assign(3, Rows::Sign::kFree);
  return r;
}

// The two rows of |c_t| <= mu_s c_n: mu_s c_n - c_t - rho+ = 0, mu_s c_n + c_t - rho- = 0.
void add_friction(Rows& r, const Q& mu_s, std::size_t cn, std::size_t ct, std::size_t rho) {
  r.rows.push_back({{cn, mu_s}, {ct, Q(-1)}, {rho, Q(-1)}});
  r.rows.push_back({{cn, mu_s}, {ct, Q(1)}, {rho + 1, Q(-1)}});
}

// Adds `x` times the column `col` to the three dynamics rows from `first` on.
void add_dynamics(Rows& r, std::size_t first, std::size_t col, const W& x) {
  for (std::size_t d = 0; d < 3; ++d) r.rows[first + d].push_back({col, x[d]});
}

W negated(const W& w) { return {-w[0], -w[1], -w[2]}; }

W combined(const W& n, const Q& t_per_n, const W& t) {
  W w = n;
  add_scaled(w, t_per_n, t);
  return w;
}

Vec<Q> right_hand_side(std::size_t rows, const Vec<Q>& g) {
  Vec<Q> b = Vec<Q>::Zero(static_cast<Eigen::Index>(rows));
  b.tail(3) = g;
  return b;
}

// The force of a fixel whose letter is l or r: c_t per c_n (Table 2: friction opposes the sliding).
Q sliding_t_per_n(const CheckedFixel& f, Force c) { return c == Force::kLeftEdge ? Q(-f.mu_k) : f.mu_k; }

// The name of a component of z, e.g. "-a1n" or "c0[n-mu t]" (fixels numbered from 0, docs/formats.md).
std::string component_name(const char* head, std::size_t fixel, const char* tail) {
  std::ostringstream s;
  s << head << fixel << tail;
  return s.str();
}

}  // namespace

CheckedScene checked_scene(const geometry::PlanarScene& scene, bool touching_only) {
  CheckedScene out{{}, scene.workpiece.inertia_per_mass};
  const geometry::Point2& com = scene.workpiece.com;
  for (const geometry::Fixel& fixel : scene.fixels) {
    const geometry::ContactFrame& frame = fixel.frame;
    if (touching_only && !frame.touching()) continue;
    const Q rx = frame.point.x - com.x, ry = frame.point.y - com.y;
    const Q nx = frame.normal.x, ny = frame.normal.y, tx = -ny, ty = nx;  // t = n turned by +90 degrees
    std::array<Q, 6> w{nx, ny, rx * ny - ry * nx, tx, ty, rx * ty - ry * tx};
    // The primitive integer vector on the ray of w: times the lcm of the denominators, over the gcd.
    exact::Z lcm = 1, gcd = 0;
    for (const Q& x : w) mpz_lcm(lcm.get_mpz_t(), lcm.get_mpz_t(), x.get_den_mpz_t());
    for (Q& x : w) {
      x *= lcm;
      mpz_gcd(gcd.get_mpz_t(), gcd.get_mpz_t(), x.get_num_mpz_t());
    }
    for (Q& x : w) x /= gcd;
    out.fixels.push_back({{w[0], w[1], w[2]}, {w[3], w[4], w[5]}, fixel.mu_s, fixel.mu_k, frame.touching()});
  }
  return out;
}

bool motzkin_holds(const Rows& r, const Vec<Q>& y) {
  if (y.size() != static_cast<Eigen::Index>(r.rows.size())) return false;
  std::vector<Q> yA(r.columns.size());
  for (std::size_t i = 0; i < r.rows.size(); ++i)
    for (const Rows::Entry& e : r.rows[i]) yA[e.col] += y(static_cast<Eigen::Index>(i)) * e.value;
  bool strict_positive = false;
  for (std::size_t j = 0; j < yA.size(); ++j) {
    const int s = sgn(yA[j]);
    if (r.columns[j] == Rows::Sign::kFree ? s != 0 : s < 0) return false;
    strict_positive = strict_positive || (s > 0 && r.columns[j] == Rows::Sign::kPositive);
  }
  Q yb = 0;
  if (r.b.size()) yb = y.dot(r.b);
  return sgn(yb) < 0 || (sgn(yb) == 0 && strict_positive);
}

bool kinematic_rows(const CheckedScene& scene, const std::string& letters, bool printed_separation, Rows& out) {
  if (letters.size() > scene.fixels.size()) return false;
  Rows r = vdot_columns();
  for (std::size_t i = 0; i < letters.size(); ++i) {
    const CheckedFixel& f = scene.fixels[i];
    const auto L = table2_letter(letters[i], f.touching, printed_separation);
    if (!L) return false;
    add_kinematic(r, f, *L);
  }
  out = std::move(r);
  return true;
}

bool motion_rows(const CheckedScene& scene, const std::string& mode, const Vec<Q>& g, Rows& out) {
  const std::size_t k = scene.fixels.size();
  if (mode.size() != k || g.size() != 3) return false;
  // The kinematic rows with each fixel's columns in place: sigma, c_n, c_t, rho+, rho-.
  Rows r = vdot_columns();
  std::vector<Letter> letters;
  std::vector<std::size_t> cn(k), ct(k), rho(k);
  for (std::size_t i = 0; i < k; ++i) {
    const CheckedFixel& f = scene.fixels[i];
    const auto L = table2_letter(mode[i], f.touching, false);
    if (!L || !f.touching || mode[i] == 'm' || mode[i] == 'S') return false;
    letters.push_back(*L);
    add_kinematic(r, f, *L);
    if (L->c == Force::kNone) continue;
    cn[i] = add_column(r, Rows::Sign::kNonNegative);
    if (L->c != Force::kStaticCone) continue;
    ct[i] = add_column(r, Rows::Sign::kFree);
    rho[i] = add_column(r, Rows::Sign::kNonNegative);
    add_column(r, Rows::Sign::kNonNegative);
  }
  for (std::size_t i = 0; i < k; ++i)
    if (letters[i].c == Force::kStaticCone) add_friction(r, scene.fixels[i].mu_s, cn[i], ct[i], rho[i]);
  // M vdot - sum of the contact wrenches = g.
  const std::size_t dyn = r.rows.size();
  r.rows.resize(dyn + 3);
  add_dynamics(r, dyn, 0, {Q(1), Q(0), Q(0)});
  add_dynamics(r, dyn, 1, {Q(0), Q(1), Q(0)});
  add_dynamics(r, dyn, 2, {Q(0), Q(0), scene.inertia_per_mass});
  for (std::size_t i = 0; i < k; ++i) {
    const CheckedFixel& f = scene.fixels[i];
    switch (letters[i].c) {
      case Force::kNone:
        break;
      case Force::kLeftEdge:
      case Force::kRightEdge:
        add_dynamics(r, dyn, cn[i], negated(combined(f.w_n, sliding_t_per_n(f, letters[i].c), f.w_t)));
        break;
      case Force::kStaticCone:
        add_dynamics(r, dyn, cn[i], negated(f.w_n));
        add_dynamics(r, dyn, ct[i], negated(f.w_t));
        break;
    }
  }
  r.b = right_hand_side(r.rows.size(), g);
  out = std::move(r);
  return true;
}

Rows resting_rows(const CheckedScene& scene, const Vec<Q>& g) {
  Rows r;
  const std::size_t k = scene.fixels.size();
  for (std::size_t i = 0; i < 4 * k; ++i)
    r.columns.push_back(i % 4 == 1 ? Rows::Sign::kFree : Rows::Sign::kNonNegative);  // c_n, c_t, rho+, rho-
  for (std::size_t i = 0; i < k; ++i) add_friction(r, scene.fixels[i].mu_s, 4 * i, 4 * i + 1, 4 * i + 2);
  const std::size_t dyn = r.rows.size();
  r.rows.resize(dyn + 3);
  for (std::size_t i = 0; i < k; ++i) {
    add_dynamics(r, dyn, 4 * i, negated(scene.fixels[i].w_n));
    add_dynamics(r, dyn, 4 * i + 1, negated(scene.fixels[i].w_t));
  }
  r.b = right_hand_side(r.rows.size(), g);
  return r;
}

bool realises(const CheckedScene& scene, const std::string& letters, bool printed_separation, const Vec<Q>& vdot) {
  if (vdot.size() != 3 || letters.size() > scene.fixels.size()) return false;
  for (std::size_t i = 0; i < letters.size(); ++i) {
    const CheckedFixel& f = scene.fixels[i];
    const auto L = table2_letter(letters[i], f.touching, printed_separation);
    if (!L || !meets(L->a_n, sgn(dot(f.w_n, vdot))) || !meets(L->a_t, sgn(dot(f.w_t, vdot)))) return false;
  }
  return true;
}

std::string motion_violation(const CheckedScene& scene, const std::string& mode, const Vec<Q>& g, const Vec<Q>& vdot,
                             const Vec<Q>& c) {
  const std::size_t k = scene.fixels.size();
  if (mode.size() != k || g.size() != 3 || vdot.size() != 3 || c.size() != static_cast<Eigen::Index>(2 * k))
    return "the witness has the wrong sizes";
  W wrench{g(0), g(1), g(2)};  // g + J c
  for (std::size_t i = 0; i < k; ++i) {
    const CheckedFixel& f = scene.fixels[i];
    const auto L = table2_letter(mode[i], f.touching, false);
    if (!L || mode[i] == 'm' || mode[i] == 'S') return "the witness mode: only the letters s l r n";
    const std::string at = " at fixel " + std::to_string(i) + " (Table 2, '" + mode[i] + "')";
    if (!meets(L->a_n, sgn(dot(f.w_n, vdot))) || !meets(L->a_t, sgn(dot(f.w_t, vdot))))
      return "the acceleration violates its mode" + at;
    const Q &c_n = c(static_cast<Eigen::Index>(i)), &c_t = c(static_cast<Eigen::Index>(k + i));
    switch (L->c) {
      case Force::kNone:
        if (sgn(c_n) != 0 || sgn(c_t) != 0) return "a separating contact carries force" + at;
        break;
      case Force::kLeftEdge:
      case Force::kRightEdge:
        if (sgn(c_n) < 0 || c_t != sliding_t_per_n(f, L->c) * c_n)
          return "a sliding force is not on the edge of its friction cone" + at;
        break;
      case Force::kStaticCone:
        if (sgn(c_n) < 0 || abs(c_t) > f.mu_s * c_n) return "a rolling force is outside its friction cone" + at;
        break;
    }
    add_scaled(wrench, c_n, f.w_n);
    add_scaled(wrench, c_t, f.w_t);
  }
  if (vdot(0) != wrench[0] || vdot(1) != wrench[1] || scene.inertia_per_mass * vdot(2) != wrench[2])
    return "M vdot != g + J c (eq. 4)";
  return "";
}

std::string resting_violation(const CheckedScene& scene, const Vec<Q>& g, const Vec<Q>& c) {
  const std::size_t k = scene.fixels.size();
  if (g.size() != 3 || c.size() != static_cast<Eigen::Index>(2 * k)) return "the resting forces have the wrong size";
  W wrench{g(0), g(1), g(2)};
  for (std::size_t i = 0; i < k; ++i) {
    const CheckedFixel& f = scene.fixels[i];
    const Q &c_n = c(static_cast<Eigen::Index>(i)), &c_t = c(static_cast<Eigen::Index>(k + i));
    if (sgn(c_n) < 0 || abs(c_t) > f.mu_s * c_n)
      return "the resting force at fixel " + std::to_string(i) + " is outside its static friction cone";
    add_scaled(wrench, c_n, f.w_n);
    add_scaled(wrench, c_t, f.w_t);
  }
  for (const Q& x : wrench)
    if (sgn(x) != 0) return "the resting forces do not balance the wrench (J c + g != 0)";
  return "";
}

bool cone_columns(const CheckedScene& scene, const std::string& mode, ConeColumns& out) {
  const std::size_t k = scene.fixels.size();
  if (mode.size() != k) return false;
  std::vector<Letter> letters;
  for (std::size_t i = 0; i < k; ++i) {
    const auto L = table2_letter(mode[i], scene.fixels[i].touching, false);
    if (!L) return false;
    letters.push_back(*L);
  }
  ConeColumns c;
  // The rows and the signed accelerations: every a_n, then every a_t.
  for (int tangent = 0; tangent < 2; ++tangent)
    for (std::size_t i = 0; i < k; ++i) {
      const Acc a = tangent ? letters[i].a_t : letters[i].a_n;
      if (a == Acc::kFree) continue;
      c.row_wrenches.push_back(tangent ? scene.fixels[i].w_t : scene.fixels[i].w_n);
      if (a == Acc::kZero) continue;
      ConeColumns::Z z;
      z.acceleration = true;
      z.fixel = i;
      z.row = c.row_wrenches.size() - 1;
      z.sign = a == Acc::kNegative ? -1 : 1;
      z.strict = a == Acc::kPositive || a == Acc::kNegative;
      z.name = component_name(z.sign < 0 ? "-a" : "a", i, tangent ? "t" : "n");
      c.z.push_back(std::move(z));
    }
  // The force multipliers: each fixel's first edge (or its sliding edge), then each static cone's second edge.
  auto force = [&](std::size_t i, int side, const Q& mu) {  // c = z (w_n + side mu w_t)
    ConeColumns::Z z;
    z.fixel = i;
    z.t_per_n = side * mu;
    z.name = component_name("c", i, side < 0 ? "[n-mu t]" : "[n+mu t]");
    c.z.push_back(std::move(z));
  };
  for (std::size_t i = 0; i < k; ++i) {
    const CheckedFixel& f = scene.fixels[i];
    if (letters[i].c == Force::kStaticCone || letters[i].c == Force::kLeftEdge)
      force(i, -1, letters[i].c == Force::kStaticCone ? f.mu_s : f.mu_k);
    if (letters[i].c == Force::kRightEdge) force(i, 1, f.mu_k);
  }
  for (std::size_t i = 0; i < k; ++i)
    if (letters[i].c == Force::kStaticCone) force(i, 1, scene.fixels[i].mu_s);
  out = std::move(c);
  return true;
}

std::string cone_empty_violation(const ConeColumns& cols, const Vec<Q>& y) {
  if (y.size() != static_cast<Eigen::Index>(cols.row_wrenches.size())) return "y has the wrong length";
  W sum{Q(0), Q(0), Q(0)};
  for (std::size_t r = 0; r < cols.row_wrenches.size(); ++r)
    add_scaled(sum, y(static_cast<Eigen::Index>(r)), cols.row_wrenches[r]);
  for (const Q& x : sum)
    if (sgn(x) != 0) return "y^T P is not zero (sum_r y_r w_r != 0)";
  // Then every force column of y^T K is -(sum_r y_r w_r)^T M^-1 (w_n + mu w_t) = 0.
  bool positive = false;
  for (std::size_t j = 0; j < cols.z.size(); ++j) {
    const ConeColumns::Z& z = cols.z[j];
    if (!z.acceleration) continue;
    const int s = z.sign * sgn(y(static_cast<Eigen::Index>(z.row)));
    if (s < 0) return "(y^T K)_" + std::to_string(j) + " < 0 (" + z.name + ")";
    positive = positive || (s > 0 && z.strict);
  }
  if (!positive) return "y^T K is zero on every strict component";
  return "";
}

namespace {

// M^-1 w at the certificates' scale: diag(p, p, q) w for I/m = p/q in lowest terms.
Vec<Q> scaled_m_inverse(const CheckedScene& scene, const W& w) {
  const Q& inertia = scene.inertia_per_mass;
  Vec<Q> v(3);
  v << w[0] * inertia.get_num(), w[1] * inertia.get_num(), w[2] * inertia.get_den();
  return v;
}

}  // namespace

std::string wrench_outside_violation(const CheckedScene& scene, const ConeColumns& cols, const Vec<Q>& y,
                                     const Vec<Q>& g) {
  if (y.size() != static_cast<Eigen::Index>(cols.row_wrenches.size()) || g.size() != 3)
    return "y or g has the wrong length";
  W sum{Q(0), Q(0), Q(0)};
  for (std::size_t r = 0; r < cols.row_wrenches.size(); ++r)
    add_scaled(sum, y(static_cast<Eigen::Index>(r)), cols.row_wrenches[r]);
  const Vec<Q> v = scaled_m_inverse(scene, sum);  // y^T P = v^T, M^-1 symmetric
  const int b = sgn(Q(v.dot(g)));
  if (b > 0) return "y^T P g > 0";
  bool positive = b < 0;
  for (std::size_t j = 0; j < cols.z.size(); ++j) {
    const ConeColumns::Z& z = cols.z[j];
    int s = 0;
    if (z.acceleration) {
      s = z.sign * sgn(y(static_cast<Eigen::Index>(z.row)));
    } else {
      const CheckedFixel& f = scene.fixels[z.fixel];
      s = -sgn(Q(dot(combined(f.w_n, z.t_per_n, f.w_t), v)));
    }
    if (s < 0) return "(y^T K)_" + std::to_string(j) + " < 0 (" + z.name + ")";
    positive = positive || (s > 0 && z.strict);
  }
  if (!positive) return "y^T P g = 0 and y^T K is zero on every strict component";
  return "";
}

Vec<Q> cone_contact_forces(const ConeColumns& cols, const std::vector<std::size_t>& touching, const Vec<Q>& z) {
  const auto k = static_cast<Eigen::Index>(touching.size());
  Vec<Q> c = Vec<Q>::Zero(2 * k);
  for (std::size_t j = 0; j < cols.z.size(); ++j) {
    const ConeColumns::Z& f = cols.z[j];
    const auto at = std::find(touching.begin(), touching.end(), f.fixel);
    if (f.acceleration || at == touching.end()) continue;
    const auto i = static_cast<Eigen::Index>(at - touching.begin());
    c(i) += z(static_cast<Eigen::Index>(j));
    c(k + i) += f.t_per_n * z(static_cast<Eigen::Index>(j));
  }
  return c;
}

std::string cone_witness_violation(const CheckedScene& scene, const ConeColumns& cols, const Vec<Q>& z,
                                   const Vec<Q>& g) {
  if (z.size() != static_cast<Eigen::Index>(cols.z.size()) || g.size() != 3) return "z or g has the wrong length";
  W force{g(0), g(1), g(2)};  // J c + g
  std::vector<Q> a(cols.row_wrenches.size());
  for (std::size_t j = 0; j < cols.z.size(); ++j) {
    const ConeColumns::Z& c = cols.z[j];
    const Q& x = z(static_cast<Eigen::Index>(j));
    if (sgn(x) < 0 || (c.strict && sgn(x) == 0))
      return "z_" + std::to_string(j) + " (" + c.name + ") violates its sign";
    if (c.acceleration) {
      a[c.row] = c.sign * x;
      continue;
    }
    const CheckedFixel& f = scene.fixels[c.fixel];
    add_scaled(force, x, combined(f.w_n, c.t_per_n, f.w_t));
  }
  const Vec<Q> vdot = scaled_m_inverse(scene, force);  // M^-1 (J c + g)
  for (std::size_t r = 0; r < a.size(); ++r)
    if (a[r] != dot(cols.row_wrenches[r], vdot)) return "K z != P g (row " + std::to_string(r) + ")";
  return "";
}

}  // namespace contactcert::checker::table2_check
