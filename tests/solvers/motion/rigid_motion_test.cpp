#include "geometry/rigid_motion.h"

#include <gtest/gtest.h>

namespace contactcert::geometry {
namespace {

using exact::Q;

TEST(RigidMotion, CayleyRotationIsExactlyOrthogonal) {
  for (const Q& u : {Q(1, 3), Q(-7, 5), Q(123456789, 1000)}) {
    const Pose<Q> r = cayley_rotation<Q>(u);
    EXPECT_EQ(r.c * r.c + r.s * r.s, Q(1));
    const Vec2<Q> p{Q(3), Q(-4, 7)};
    const Vec2<Q> q = r.apply(p);
    EXPECT_EQ(q.x * q.x + q.y * q.y, p.x * p.x + p.y * p.y);  // lengths kept exactly
    EXPECT_EQ(r.unrotate(q), p);
  }
  // u = tan(phi / 2): u = 1 is a quarter turn.
  const Pose<Q> quarter = cayley_rotation<Q>(Q(1));
  EXPECT_EQ(quarter.c, Q(0));
  EXPECT_EQ(quarter.s, Q(1));
}

TEST(RigidMotion, TwistStepKeepsThePivotFixed) {
  // A body turning about (2, 0) with omega = -2/3: v (velocity of the body point at the origin) = omega J (0 - c).
  const Vec2<Q> c{Q(2), Q(0)};
  const Q omega(-2, 3);
  const Vec2<Q> v = omega * perp2(Vec2<Q>{Q(0) - c.x, Q(0) - c.y});
  const Pose<Q> step = twist_step(v, omega, Q(1, 10));
  EXPECT_EQ(step.apply(c), c);
  EXPECT_EQ(step.c * step.c + step.s * step.s, Q(1));
  // The Cayley parameter is omega h / 2: tan of half the turned angle.
  EXPECT_EQ(step.s / (Q(1) + step.c), Q(-1, 30));
  // Composition keeps the pivot too.
  const Pose<Q> twice = compose(step, step);
  EXPECT_EQ(twice.apply(c), c);
  EXPECT_EQ(twice.c * twice.c + twice.s * twice.s, Q(1));
}

TEST(RigidMotion, ZeroOmegaIsATranslation) {
  const Pose<Q> step = twist_step(Vec2<Q>{Q(1), Q(-2)}, Q(0), Q(3, 10));
  EXPECT_EQ(step.c, Q(1));
  EXPECT_EQ(step.s, Q(0));
  EXPECT_EQ(step.t, (Vec2<Q>{Q(3, 10), Q(-3, 5)}));
}

// Pose<Q>::apply and apply_all work over common denominators: the same reduced rationals as R p + t computed
// operation by operation (== compares reduced rationals: the result is in lowest terms), for a pose whose numbers share
// one denominator and for one whose numbers do not.
TEST(RigidMotion, ApplyOverCommonDenominatorsIsRotatePlusTranslate) {
  const Pose<Q> shared = compose(twist_step<Q>({Q(1, 3), Q(-2)}, Q(5, 7), Q(1, 10)), cayley_rotation<Q>(Q(2, 9)));
  Pose<Q> mixed = cayley_rotation<Q>(Q(3, 4));  // t over other denominators
  mixed.t = {Q(-7, 6), Q(5, 11)};
  const std::vector<Vec2<Q>> points{{Q(0), Q(0)}, {Q(2), Q(-3)}, {Q(1, 2), Q(7, 3)}, {Q(-5, 8), Q(4)}};
  for (const Pose<Q>* pose : {&shared, static_cast<const Pose<Q>*>(&mixed)}) {
    const std::vector<Vec2<Q>> all = apply_all(*pose, points);
    ASSERT_EQ(all.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec2<Q>& p = points[i];
      const Vec2<Q> want{pose->c * p.x - pose->s * p.y + pose->t.x, pose->s * p.x + pose->c * p.y + pose->t.y};
      EXPECT_EQ(pose->apply(p), want);
      EXPECT_EQ(all[i], want);
    }
  }
}

/// True if q is stored in lowest terms with a positive denominator (what every Q operation assumes).
bool canonical(const Q& q) {
  exact::Z g;
  mpz_gcd(g.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return g == 1 && sgn(q.get_den()) > 0;
}
bool canonical(const Pose<Q>& p) { return canonical(p.c) && canonical(p.s) && canonical(p.t.x) && canonical(p.t.y); }

// The exact specialisations (rotate, compose, cayley_rotation, twist_step over integer numerators, one reduction per
// number) give the reduced rationals that the formulas of rigid_motion.h give operation by operation; both parities
// of the Cayley parameter's numerator and denominator, negative parameters and a translation of other denominators.
TEST(RigidMotion, ExactSpecialisationsAreTheFormulas) {
  const Vec2<Q> p{Q(-5, 8), Q(7, 3)};
  for (const Q& u : {Q(1, 3), Q(2, 3), Q(-7, 5), Q(3, 4), Q(-123456789, 1000), Q(0), Q(1)}) {
    const Pose<Q> r = cayley_rotation<Q>(u);
    EXPECT_EQ(r.c, (1 - u * u) / (1 + u * u));
    EXPECT_EQ(r.s, 2 * u / (1 + u * u));
    EXPECT_TRUE(canonical(r));
    EXPECT_EQ(r.rotate(p), (Vec2<Q>{r.c * p.x - r.s * p.y, r.s * p.x + r.c * p.y}));
    EXPECT_TRUE(canonical(r.rotate(p).x) && canonical(r.rotate(p).y));
  }
  for (const Q& omega : {Q(5, 7), Q(-2, 3), Q(3), Q(-1, 9)})
    for (const Vec2<Q>& v : {Vec2<Q>{Q(1, 3), Q(-2)}, Vec2<Q>{Q(0), Q(4, 5)}}) {
      const Q h(1, 10);
      const Pose<Q> step = twist_step(v, omega, h);
      const Pose<Q> r = cayley_rotation<Q>(omega * h / 2);
      const Vec2<Q> centre{-v.y / omega, v.x / omega};
      const Vec2<Q> t{centre.x - (r.c * centre.x - r.s * centre.y), centre.y - (r.s * centre.x + r.c * centre.y)};
      EXPECT_EQ(step.c, r.c);
      EXPECT_EQ(step.s, r.s);
      EXPECT_EQ(step.t, t);
      EXPECT_TRUE(canonical(step));
      Pose<Q> other = cayley_rotation<Q>(Q(2, 9));
      other.t = {Q(-7, 6), Q(5, 11)};
      for (const Pose<Q>* b : {&step, static_cast<const Pose<Q>*>(&other)}) {
        const Pose<Q> ab = compose(step, *b);
        EXPECT_EQ(ab.c, step.c * b->c - step.s * b->s);
        EXPECT_EQ(ab.s, step.s * b->c + step.c * b->s);
        EXPECT_EQ(ab.t, (Vec2<Q>{step.c * b->t.x - step.s * b->t.y + step.t.x,
                                 step.s * b->t.x + step.c * b->t.y + step.t.y}));
        EXPECT_TRUE(canonical(ab));
      }
    }
}

}  // namespace
}  // namespace contactcert::geometry
