#include "geometry/rigid_motion.h"

#include <algorithm>
#include <cmath>

#include "exact/fraction_free.h"

namespace contactcert::geometry {

namespace {

using exact::Z;

/// The pose's (c, s, t_x, t_y) = n / L over their least common denominator L.
struct PoseNumerators {
  Z n[4], L;
  explicit PoseNumerators(const Pose<exact::Q>& pose) {
    const exact::Q* const q[4] = {&pose.c, &pose.s, &pose.t.x, &pose.t.y};
    // A pose reached by Cayley steps has one denominator (1 + U^2 up to a factor): then L is it, without an lcm.
    const mpz_srcptr d = mpq_denref(pose.c.get_mpq_t());
    if (std::all_of(q + 1, q + 4, [d](const exact::Q* v) { return mpz_cmp(mpq_denref(v->get_mpq_t()), d) == 0; })) {
      L = pose.c.get_den();
      for (int i = 0; i < 4; ++i) n[i] = q[i]->get_num();
    } else {
      L = exact::ring::to_common_denominator<Z>(
          4, [&](Eigen::Index i) -> const exact::Q& { return *q[i]; }, n);
    }
  }

  /// R p + t = (C P_x - S P_y + T_x M, S P_x + C P_y + T_y M) / (L M) with p = P / M.
  Vec2<exact::Q> apply(const Vec2<exact::Q>& point) const {
    const exact::Q* const v[2] = {&point.x, &point.y};
    Z p[2], x, y, den;
    const Z M = exact::ring::to_common_denominator<Z>(
        2, [&](Eigen::Index j) -> const exact::Q& { return *v[j]; }, p);
    mpz_mul(x.get_mpz_t(), n[0].get_mpz_t(), p[0].get_mpz_t());
    mpz_submul(x.get_mpz_t(), n[1].get_mpz_t(), p[1].get_mpz_t());
    mpz_addmul(x.get_mpz_t(), n[2].get_mpz_t(), M.get_mpz_t());
    mpz_mul(y.get_mpz_t(), n[1].get_mpz_t(), p[0].get_mpz_t());
    mpz_addmul(y.get_mpz_t(), n[0].get_mpz_t(), p[1].get_mpz_t());
    mpz_addmul(y.get_mpz_t(), n[3].get_mpz_t(), M.get_mpz_t());
    mpz_mul(den.get_mpz_t(), L.get_mpz_t(), M.get_mpz_t());
    Vec2<exact::Q> out;
    exact::ring::to_rational(x, den, out.x);
    exact::ring::to_rational(y, den, out.y);
    return out;
  }
};

}  // namespace

template <>
std::vector<Vec2<exact::Q>> apply_all(const Pose<exact::Q>& pose, const std::vector<Vec2<exact::Q>>& points) {
  const PoseNumerators numerators(pose);
  std::vector<Vec2<exact::Q>> out;
  out.reserve(points.size());
  for (const Vec2<exact::Q>& p : points) out.push_back(numerators.apply(p));
  return out;
}

template <>
Vec2<exact::Q> Pose<exact::Q>::apply(const Vec2<exact::Q>& p) const {
  return PoseNumerators(*this).apply(p);
}

double turned_angle(const Pose<double>& p) { return std::atan2(p.s, p.c); }

Pose<double> to_double(const Pose<exact::Q>& p) { return {p.c.get_d(), p.s.get_d(), {p.t.x.get_d(), p.t.y.get_d()}}; }

}  // namespace contactcert::geometry
