#include "geometry/rigid_motion.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "exact/fraction_free.h"

namespace contactcert::geometry {

namespace {

using exact::Q;
using exact::Z;

/// The numbers q[0..k) = n / L over their least common denominator L: a pose's (c, s, t_x, t_y) (k = 4), its rotation
/// (c, s) (k = 2) or a point's (x, y) (k = 2). n and L point into the rationals when they share one denominator (no
/// copy), else into own storage.
template <int k>
struct Numerators {
  mpz_srcptr n[k], L;
  Z own[k], own_L;
  explicit Numerators(const Q* const (&q)[k]) {
    // A pose reached by Cayley steps has one denominator (1 + U^2 up to a factor), and an exact rotation's c and s
    // share theirs (c^2 + s^2 = 1): then L is it, without an lcm.
    L = mpq_denref(q[0]->get_mpq_t());
    if (std::all_of(q + 1, q + k, [this](const Q* v) { return mpz_cmp(mpq_denref(v->get_mpq_t()), L) == 0; })) {
      for (int i = 0; i < k; ++i) n[i] = mpq_numref(q[i]->get_mpq_t());
    } else {
      own_L = exact::ring::to_common_denominator<Z>(
          k, [&](Eigen::Index i) -> const Q& { return *q[i]; }, own);
      L = own_L.get_mpz_t();
      for (int i = 0; i < k; ++i) n[i] = own[i].get_mpz_t();
    }
  }
  Numerators(const Numerators&) = delete;
  Numerators& operator=(const Numerators&) = delete;
};

struct PointNumerators : Numerators<2> {
  explicit PointNumerators(const Vec2<Q>& p) : Numerators<2>({&p.x, &p.y}) {}
};

/// R p (+ t with translate) = (x, y) / den for R's (c, s) = (n[0], n[1]) / L, t = (n[2], n[3]) / L, p = P / M:
/// (C P_x - S P_y + T_x M, S P_x + C P_y + T_y M) / (L M).
void turn(const mpz_srcptr* n, mpz_srcptr L, bool translate, const mpz_srcptr* P, mpz_srcptr M, Z& x, Z& y, Z& den) {
  mpz_mul(x.get_mpz_t(), n[0], P[0]);
  mpz_submul(x.get_mpz_t(), n[1], P[1]);
  mpz_mul(y.get_mpz_t(), n[1], P[0]);
  mpz_addmul(y.get_mpz_t(), n[0], P[1]);
  if (translate) {
    mpz_addmul(x.get_mpz_t(), n[2], M);
    mpz_addmul(y.get_mpz_t(), n[3], M);
  }
  mpz_mul(den.get_mpz_t(), L, M);
}

/// (x, y) / den reduced once per coordinate.
Vec2<Q> reduced(const Z& x, const Z& y, const Z& den) {
  Vec2<Q> out;
  exact::ring::to_rational(x, den, out.x);
  exact::ring::to_rational(y, den, out.y);
  return out;
}

/// The pose's (c, s, t_x, t_y) = n / L over their least common denominator L.
struct PoseNumerators : Numerators<4> {
  explicit PoseNumerators(const Pose<Q>& pose) : Numerators<4>({&pose.c, &pose.s, &pose.t.x, &pose.t.y}) {}

  /// R p + t, each coordinate reduced once.
  Vec2<Q> apply(const Vec2<Q>& point) const {
    const PointNumerators p(point);
    Z x, y, den;
    turn(n, L, true, p.n, p.L, x, y, den);
    return reduced(x, y, den);
  }
};

/// out.c = C / D, out.s = S / D in lowest terms for an exact rotation (c^2 + s^2 = 1, D > 0): c and s then have the
/// same reduced denominator, so g = gcd(C, D) also divides S and one gcd reduces both.
void set_rotation(Z& C, Z& S, Z& D, Pose<Q>& out) {
  Z g;
  mpz_gcd(g.get_mpz_t(), C.get_mpz_t(), D.get_mpz_t());
  assert(mpz_divisible_p(S.get_mpz_t(), g.get_mpz_t()));  // c^2 + s^2 = 1
  if (g != 1) {
    mpz_divexact(C.get_mpz_t(), C.get_mpz_t(), g.get_mpz_t());
    mpz_divexact(S.get_mpz_t(), S.get_mpz_t(), g.get_mpz_t());
    mpz_divexact(D.get_mpz_t(), D.get_mpz_t(), g.get_mpz_t());
  }
  mpz_set(mpq_numref(out.c.get_mpq_t()), C.get_mpz_t());
  mpz_set(mpq_denref(out.c.get_mpq_t()), D.get_mpz_t());
  mpz_set(mpq_numref(out.s.get_mpq_t()), S.get_mpz_t());
  mpz_set(mpq_denref(out.s.get_mpq_t()), D.get_mpz_t());
}

/// R(a / b) for coprime a and b > 0: c = (b^2 - a^2) / (a^2 + b^2), s = 2ab / (a^2 + b^2). An odd prime dividing a^2 +
/// b^2 and b^2 - a^2 or 2ab would divide a and b; 2 divides a^2 + b^2 (exactly once) only when a and b are both odd,
/// and then divides the numerators too: halving then is the whole reduction. Also returns a^2 + b^2 (unhalved).
Z cayley_of(mpz_srcptr a, mpz_srcptr b, Pose<Q>& out) {
  Z a2, b2, den, C, S;
  mpz_mul(a2.get_mpz_t(), a, a);
  mpz_mul(b2.get_mpz_t(), b, b);
  mpz_add(den.get_mpz_t(), a2.get_mpz_t(), b2.get_mpz_t());
  mpz_sub(C.get_mpz_t(), b2.get_mpz_t(), a2.get_mpz_t());
  mpz_mul(S.get_mpz_t(), a, b);
  const bool both_odd = mpz_odd_p(a) && mpz_odd_p(b);
  if (!both_odd) mpz_mul_2exp(S.get_mpz_t(), S.get_mpz_t(), 1);
  mpz_set(mpq_numref(out.s.get_mpq_t()), S.get_mpz_t());
  if (both_odd) {
    mpz_divexact_ui(C.get_mpz_t(), C.get_mpz_t(), 2);
    mpz_divexact_ui(mpq_denref(out.c.get_mpq_t()), den.get_mpz_t(), 2);
  } else {
    mpz_set(mpq_denref(out.c.get_mpq_t()), den.get_mpz_t());
  }
  mpz_set(mpq_numref(out.c.get_mpq_t()), C.get_mpz_t());
  mpz_set(mpq_denref(out.s.get_mpq_t()), mpq_denref(out.c.get_mpq_t()));
  return den;
}

}  // namespace

template <>
std::vector<Vec2<Q>> apply_all(const Pose<Q>& pose, const std::vector<Vec2<Q>>& points) {
  const PoseNumerators numerators(pose);
  std::vector<Vec2<Q>> out;
  out.reserve(points.size());
  for (const Vec2<Q>& p : points) out.push_back(numerators.apply(p));
  return out;
}

template <>
Vec2<Q> Pose<Q>::apply(const Vec2<Q>& p) const {
  return PoseNumerators(*this).apply(p);
}

template <>
Vec2<Q> Pose<Q>::rotate(const Vec2<Q>& p) const {
  const Numerators<2> r({&c, &s});
  const PointNumerators P(p);
  Z x, y, den;
  turn(r.n, r.L, false, P.n, P.L, x, y, den);
  return reduced(x, y, den);
}

template <>
Pose<Q> compose(const Pose<Q>& a, const Pose<Q>& b) {
  const PoseNumerators A(a), B(b);
  Pose<Q> out;
  Z C, S, D;
  turn(A.n, A.L, false, B.n, B.L, C, S, D);  // R_a (c_b, s_b) over L_a L_b
  set_rotation(C, S, D, out);
  Z x, y, den;
  turn(A.n, A.L, true, B.n + 2, B.L, x, y, den);  // a(t_b)
  out.t = reduced(x, y, den);
  return out;
}

template <>
Pose<Q> cayley_rotation(const Q& u) {
  Pose<Q> out;
  cayley_of(mpq_numref(u.get_mpq_t()), mpq_denref(u.get_mpq_t()), out);
  return out;
}

template <>
Pose<Q> twist_step(const Vec2<Q>& v, const Q& omega, const Q& h) {
  if (sgn(omega) == 0) return {Q(1), Q(0), h * v};
  Q u = omega * h;
  mpq_div_2exp(u.get_mpq_t(), u.get_mpq_t(), 1);
  const mpz_srcptr a = mpq_numref(u.get_mpq_t()), b = mpq_denref(u.get_mpq_t());
  Pose<Q> out;
  const Z den = cayley_of(a, b, out);
  // t = h b (b v + a J v) / (a^2 + b^2) with v = V / M, h = h_n / h_d: (b I + a J) v is a turn.
  const PointNumerators V(v);
  const mpz_srcptr b_plus_aJ[2] = {b, a};
  Z x, y, d, f;
  turn(b_plus_aJ, den.get_mpz_t(), false, V.n, V.L, x, y, d);
  mpz_mul(f.get_mpz_t(), b, mpq_numref(h.get_mpq_t()));
  x *= f;
  y *= f;
  mpz_mul(d.get_mpz_t(), d.get_mpz_t(), mpq_denref(h.get_mpq_t()));
  out.t = reduced(x, y, d);
  return out;
}

double turned_angle(const Pose<double>& p) { return std::atan2(p.s, p.c); }

Pose<double> to_double(const Pose<Q>& p) { return {p.c.get_d(), p.s.get_d(), {p.t.x.get_d(), p.t.y.get_d()}}; }

}  // namespace contactcert::geometry
