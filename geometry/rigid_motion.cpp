#include "geometry/rigid_motion.h"

#include <algorithm>
#include <cmath>

#include "exact/fraction_free.h"

namespace contactcert::geometry {

template <>
std::vector<Vec2<exact::Q>> apply_all(const Pose<exact::Q>& pose, const std::vector<Vec2<exact::Q>>& points) {
  using exact::Z;
  const exact::Q* const q[4] = {&pose.c, &pose.s, &pose.t.x, &pose.t.y};
  Z n[4], p[2], x, y, den;
  // A pose reached by Cayley steps has one denominator (1 + U^2 up to a factor): then L is it, without an lcm.
  const mpz_srcptr d = mpq_denref(pose.c.get_mpq_t());
  const bool shared =
      std::all_of(q + 1, q + 4, [d](const exact::Q* v) { return mpz_cmp(mpq_denref(v->get_mpq_t()), d) == 0; });
  Z L;
  if (shared) {
    L = pose.c.get_den();
    for (int i = 0; i < 4; ++i) n[i] = q[i]->get_num();
  } else {
    L = exact::ring::to_common_denominator<Z>(
        4, [&](Eigen::Index i) -> const exact::Q& { return *q[i]; }, n);
  }
  std::vector<Vec2<exact::Q>> out(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const exact::Q* const v[2] = {&points[i].x, &points[i].y};
    const Z M = exact::ring::to_common_denominator<Z>(
        2, [&](Eigen::Index j) -> const exact::Q& { return *v[j]; }, p);
    mpz_mul(x.get_mpz_t(), n[0].get_mpz_t(), p[0].get_mpz_t());
    mpz_submul(x.get_mpz_t(), n[1].get_mpz_t(), p[1].get_mpz_t());
    mpz_addmul(x.get_mpz_t(), n[2].get_mpz_t(), M.get_mpz_t());
    mpz_mul(y.get_mpz_t(), n[1].get_mpz_t(), p[0].get_mpz_t());
    mpz_addmul(y.get_mpz_t(), n[0].get_mpz_t(), p[1].get_mpz_t());
    mpz_addmul(y.get_mpz_t(), n[3].get_mpz_t(), M.get_mpz_t());
    mpz_mul(den.get_mpz_t(), L.get_mpz_t(), M.get_mpz_t());
    exact::ring::to_rational(x, den, out[i].x);
    exact::ring::to_rational(y, den, out[i].y);
  }
  return out;
}

double turned_angle(const Pose<double>& p) { return std::atan2(p.s, p.c); }

Pose<double> to_double(const Pose<exact::Q>& p) { return {p.c.get_d(), p.s.get_d(), {p.t.x.get_d(), p.t.y.get_d()}}; }

}  // namespace contactcert::geometry
