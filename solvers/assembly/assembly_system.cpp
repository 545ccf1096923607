#include "solvers/assembly/assembly_system.h"

#include <stdexcept>

namespace contactcert::solvers::assembly {
namespace {

using Eigen::Index;
using geometry::Point2;

std::array<Q, 3> wrench(const Point2& f, const Point2& r, int sign) {
  return {sign * f.x, sign * f.y, sign * geometry::cross(r, f)};
}

}  // namespace

AssemblyModel assembly_model(const geometry::Assembly& a) {
  AssemblyModel m;
  for (const geometry::Body& b : a.bodies) {
    m.M.push_back({b.mass, b.mass, b.inertia});
    m.g.push_back({b.load_fx, b.load_fy, b.load_torque});
  }
  for (const geometry::AssemblyContact& c : a.contacts) {
    ContactJacobian J;
    const Point2 t = geometry::perp(c.normal);
    const geometry::Party* parties[] = {&c.from, &c.to};
    for (int s = 0; s < 2; ++s) {
      if (!parties[s]->movable()) continue;
      const long body = static_cast<long>(parties[s]->index);
      const Point2 r = c.point - a.bodies[static_cast<std::size_t>(body)].com;
      J.sides[static_cast<std::size_t>(s)] = {body, wrench(c.normal, r, s == 0 ? -1 : 1),
                                              wrench(t, r, s == 0 ? -1 : 1)};
    }
    J.mu_s = c.mu_s;
    J.mu_k = c.mu_k;
    m.contacts.push_back(J);
  }
  return m;
}

std::array<Q, 2> contact_acceleration(const AssemblyModel& model, std::size_t i, const Vec<Q>& vdot) {
  std::array<Q, 2> a{Q(0), Q(0)};
  for (const ContactJacobian::Side& s : model.contacts[i].sides) {
    if (s.body < 0) continue;
    for (Index d = 0; d < 3; ++d) {
      const Q& v = vdot(3 * s.body + d);
      a[0] += s.w_n[static_cast<std::size_t>(d)] * v;
      a[1] += s.w_t[static_cast<std::size_t>(d)] * v;
    }
  }
  return a;
}

AssemblySystem assembly_system(const AssemblyModel& model, const std::string& letters, bool resting) {
  AssemblySystem out;
  assembly_system(model, letters, out, resting);
  return out;
}

void assembly_system(const AssemblyModel& model, const std::string& letters, AssemblySystem& out, bool resting) {
  const std::size_t k = model.contacts.size();
  const auto N = static_cast<Index>(model.bodies());
  if (letters.size() != k) throw std::invalid_argument("assembly_system: one letter per contact");
  out.resting = resting;
  out.vdot_size = resting ? 0 : 3 * N;
  out.row_label.clear();
  auto& S = out.system;
  S.rows = S.cols = 0;
  S.is_free.clear();
  S.strict.clear();
  // At most 3N + 1 entries in the energy row and 3N on the diagonal of M; per contact 2 x 7 kinematic, 2 x 3
  // friction and 2 x 6 Newton-Euler entries (no reallocation: it would copy every fraction).
  S.entries.reserve(static_cast<std::size_t>(6 * N + 1) + 32 * k);
  std::size_t used = 0;  // entries written; those of out's last system are overwritten (their limbs reused)
  const auto column = [&S](bool free, bool strict) {
    S.is_free.push_back(free);
    S.strict.push_back(strict);
    return S.cols++;
  };
  // a_{row, col} = v, or -v if `negate`.
  const auto add = [&S, &used](Index row, Index col, const Q& v, bool negate = false) {
    if (sgn(v) == 0) return;
    if (used == S.entries.size()) S.entries.push_back({row, col, Q()});
    exact::Entry<Q>& e = S.entries[used++];
    e.row = row;
    e.col = col;
    if (negate)
      e.value = -v;
    else
      e.value = v;
  };
  const Q one(1), minus_one(-1);
  if (!resting) {
    for (Index j = 0; j < 3 * N; ++j) column(true, false);
    // The energy row g^T vdot - e = 0, e > 0 (header comment).
    const Index e = column(false, true);
    for (Index b = 0; b < N; ++b)
      for (Index d = 0; d < 3; ++d)
        add(0, 3 * b + d, model.g[static_cast<std::size_t>(b)][static_cast<std::size_t>(d)]);
    add(0, e, minus_one);
    ++S.rows;
    out.row_label.push_back(0);
  }
  // a row sum_b w^b . vdot_b (+ slack sign * sigma)
  const auto kinematic = [&](std::size_t i, bool normal, Index sigma, int slack_sign) {
    for (const ContactJacobian::Side& s : model.contacts[i].sides) {
      if (s.body < 0) continue;
      for (Index d = 0; d < 3; ++d) add(S.rows, 3 * s.body + d, (normal ? s.w_n : s.w_t)[static_cast<std::size_t>(d)]);
    }
    if (sigma >= 0) add(S.rows, sigma, one, slack_sign < 0);
    ++S.rows;
    out.row_label.push_back(1 + 4 * static_cast<Index>(i) + (normal ? 0 : 1));
  };
  const auto friction = [&](std::size_t i, const Q& mu, Index c_n, Index c_t) {
    for (int sign : {-1, 1}) {
      const Index rho = column(false, false);
      add(S.rows, c_n, mu);
      add(S.rows, c_t, one, sign < 0);
      add(S.rows, rho, minus_one);
      ++S.rows;
      out.row_label.push_back(1 + 4 * static_cast<Index>(i) + (sign < 0 ? 2 : 3));
    }
  };
  out.c_n_column.assign(k, -1);
  out.c_t_column.assign(k, -1);
  out.c_t_per_c_n.assign(k, Q(0));
  for (std::size_t i = 0; i < k; ++i) {
    const ContactJacobian& c = model.contacts[i];
    const char L = resting ? 'n' : letters[i];
    if (L == 's' || L == 'l' || L == 'r' || L == '*') {
      const Index sigma = column(false, L != '*');
      if (L == 's' || L == '*') {
        kinematic(i, true, sigma, -1);  // a_n - sigma = 0
      } else {
        kinematic(i, true, -1, 0);                      // a_n = 0
        kinematic(i, false, sigma, L == 'l' ? -1 : 1);  // a_t -+ sigma = 0
        out.c_t_per_c_n[i] = L == 'l' ? Q(-c.mu_k) : c.mu_k;
      }
      if (L == 's') continue;
      out.c_n_column[i] = column(false, false);
      if (L != '*') continue;
    } else if (L == 'n') {
      if (!resting) {
        kinematic(i, true, -1, 0);
        kinematic(i, false, -1, 0);
      }
      out.c_n_column[i] = column(false, false);
    } else {
      throw std::invalid_argument("assembly_system: letters are s l r n *");
    }
    out.c_t_column[i] = column(true, false);
    friction(i, L == '*' ? std::max(c.mu_s, c.mu_k) : c.mu_s, out.c_n_column[i], out.c_t_column[i]);
  }
  // Newton-Euler rows: M_b vdot_b - sum_i (c_in w^b_in + c_it w^b_it) = g_b.
  const Index first = S.rows;
  if (out.b.size() == first + 3 * N)
    out.b.setZero();
  else
    out.b = Vec<Q>::Zero(first + 3 * N);
  for (Index b = 0; b < N; ++b)
    for (Index d = 0; d < 3; ++d) {
      if (!resting)
        add(first + 3 * b + d, 3 * b + d, model.M[static_cast<std::size_t>(b)][static_cast<std::size_t>(d)]);
      out.b(first + 3 * b + d) = model.g[static_cast<std::size_t>(b)][static_cast<std::size_t>(d)];
    }
  for (std::size_t i = 0; i < k; ++i) {
    if (out.c_n_column[i] < 0) continue;
    for (const ContactJacobian::Side& s : model.contacts[i].sides) {
      if (s.body < 0) continue;
      for (Index d = 0; d < 3; ++d) {
        const Index row = first + 3 * s.body + d;
        const Q& wn = s.w_n[static_cast<std::size_t>(d)];
        const Q& wt = s.w_t[static_cast<std::size_t>(d)];
        if (out.c_t_column[i] >= 0) {
          add(row, out.c_n_column[i], wn, true);
          add(row, out.c_t_column[i], wt, true);
        } else {
          add(row, out.c_n_column[i], wn + out.c_t_per_c_n[i] * wt, true);
        }
      }
    }
  }
  S.rows += 3 * N;
  S.entries.erase(S.entries.begin() + static_cast<std::ptrdiff_t>(used), S.entries.end());
  for (Index r = 0; r < 3 * N; ++r) out.row_label.push_back(1 + 4 * static_cast<Index>(k) + r);
}

Vec<Q> AssemblySystem::acceleration(const Vec<Q>& x) const { return x.head(vdot_size); }

Vec<Q> AssemblySystem::forces(const Vec<Q>& x) const {
  const auto k = static_cast<Index>(c_n_column.size());
  Vec<Q> c = Vec<Q>::Zero(2 * k);
  for (Index i = 0; i < k; ++i) {
    const auto u = static_cast<std::size_t>(i);
    if (c_n_column[u] < 0) continue;
    c(i) = x(c_n_column[u]);
    c(k + i) = c_t_column[u] >= 0 ? x(c_t_column[u]) : Q(c_t_per_c_n[u] * c(i));
  }
  return c;
}

}  // namespace contactcert::solvers::assembly
