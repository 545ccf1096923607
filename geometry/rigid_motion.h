// Exact planar rigid motion: poses with a rational rotation matrix, and the step of a body with a constant twist
// (v, omega) over a time h as a rotation by the Cayley map about the instantaneous centre of rotation.
//
// The Cayley map R(u) = (I - u J)^-1 (I + u J) = [[1 - u^2, -2u], [2u, 1 - u^2]] / (1 + u^2), J = [[0, -1], [1, 0]],
// of u = omega h / 2 is rational and exactly orthogonal (det 1): it is the Cayley approximation of exp(omega h J).
// It turns by the angle 2 atan(omega h / 2) (not omega h: the relative error is (omega h)^2 / 12 to first order),
// but it is an exact rigid motion, so shapes stay exactly rigid. The step rotates about the instantaneous centre
// c = (-v_y, v_x) / omega, the point whose velocity v + omega J c is zero, so a pivot stays exactly where it is;
// omega = 0 is the translation by h v. The body point at parameter u in [0, omega h / 2] is where the same twist
// puts it after the time 2 u / omega: a step cut at u is the step of that shorter time.
#pragma once

#include <vector>

#include "exact/number.h"

namespace contactcert::geometry {

/// A point or vector of the plane over T (double or Q).
template <class T>
struct Vec2 {
  T x, y;
};

template <class T>
Vec2<T> operator+(const Vec2<T>& a, const Vec2<T>& b) {
  return {a.x + b.x, a.y + b.y};
}
template <class T>
Vec2<T> operator-(const Vec2<T>& a, const Vec2<T>& b) {
  return {a.x - b.x, a.y - b.y};
}
template <class T>
Vec2<T> operator*(const T& s, const Vec2<T>& a) {
  return {s * a.x, s * a.y};
}
template <class T>
bool operator==(const Vec2<T>& a, const Vec2<T>& b) {
  return a.x == b.x && a.y == b.y;
}
/// a . b
template <class T>
T dot2(const Vec2<T>& a, const Vec2<T>& b) {
  return a.x * b.x + a.y * b.y;
}
/// a x b = a_x b_y - a_y b_x
template <class T>
T cross2(const Vec2<T>& a, const Vec2<T>& b) {
  return a.x * b.y - a.y * b.x;
}
/// J a = (-a_y, a_x): a turned by +90 degrees.
template <class T>
Vec2<T> perp2(const Vec2<T>& a) {
  return {-a.y, a.x};
}

/// A rigid pose: world = R body + t with R = [[c, -s], [s, c]], c^2 + s^2 = 1 (exactly, for T = Q).
template <class T>
struct Pose {
  T c = T(1), s = T(0);
  Vec2<T> t{T(0), T(0)};

  /// R p (a body vector in world axes).
  Vec2<T> rotate(const Vec2<T>& p) const { return {c * p.x - s * p.y, s * p.x + c * p.y}; }
  /// R^T p (a world vector in body axes).
  Vec2<T> unrotate(const Vec2<T>& p) const { return {c * p.x + s * p.y, -s * p.x + c * p.y}; }
  /// R p + t (a body point in the world).
  Vec2<T> apply(const Vec2<T>& p) const { return rotate(p) + t; }
};

/// a after b: (a o b)(p) = a(b(p)).
template <class T>
Pose<T> compose(const Pose<T>& a, const Pose<T>& b) {
  return {a.c * b.c - a.s * b.s, a.s * b.c + a.c * b.s, a.apply(b.t)};
}

/// R(u), the Cayley rotation of parameter u = tan(phi / 2): c = (1 - u^2)/(1 + u^2), s = 2u/(1 + u^2).
template <class T>
Pose<T> cayley_rotation(const T& u) {
  const T den = T(1) + u * u;
  return {(T(1) - u * u) / den, T(2) * u / den, {T(0), T(0)}};
}

/// The displacement of a body with twist (v, omega) (v: velocity of the body point at the world origin) over
/// time h: rotation by R(omega h / 2) about the instantaneous centre c = (-v_y, v_x) / omega, p -> c + R (p - c);
/// for omega = 0 the translation by h v. Exact for T = Q.
template <class T>
Pose<T> twist_step(const Vec2<T>& v, const T& omega, const T& h) {
  if (omega == T(0)) return {T(1), T(0), h * v};
  Pose<T> r = cayley_rotation<T>(omega * h / T(2));
  const Vec2<T> centre{-v.y / omega, v.x / omega};
  r.t = centre - r.rotate(centre);
  return r;
}

/// R p + t for every point p of `points`: for T = Q over the pose's least common denominator L and each point's,
/// (c, s, t) = (C, S, T) / L and p = P / M: R p + t = (C P_x - S P_y + T_x M, S P_x + C P_y + T_y M) / (L M), integer
/// products and one reduction per coordinate instead of a reduced rational after every operation.
template <class T>
std::vector<Vec2<T>> apply_all(const Pose<T>& pose, const std::vector<Vec2<T>>& points) {
  std::vector<Vec2<T>> out;
  for (const Vec2<T>& p : points) out.push_back(pose.apply(p));
  return out;
}

// For T = Q the same values over common denominators (rigid_motion.cpp), one reduction per output number.
template <>
std::vector<Vec2<exact::Q>> apply_all(const Pose<exact::Q>& pose, const std::vector<Vec2<exact::Q>>& points);
/// R p + t over common denominators (as apply_all).
template <>
Vec2<exact::Q> Pose<exact::Q>::apply(const Vec2<exact::Q>& p) const;
/// R p over common denominators.
template <>
Vec2<exact::Q> Pose<exact::Q>::rotate(const Vec2<exact::Q>& p) const;
/// a o b over common denominators: R_a R_b's first column is R_a (c_b, s_b), its translation a(t_b).
template <>
Pose<exact::Q> compose(const Pose<exact::Q>& a, const Pose<exact::Q>& b);
/// R(a / b) in lowest terms without a gcd: ((b^2 - a^2), 2ab) / (a^2 + b^2), halved when a and b are both odd.
template <>
Pose<exact::Q> cayley_rotation(const exact::Q& u);
/// The step with t = (I - R) c = h b (b v + a J v) / (a^2 + b^2) for u = omega h / 2 = a / b (as 1 - c = 2a^2 /
/// (a^2 + b^2), s = 2ab / (a^2 + b^2) and 2a / omega = b h): one reduction per coordinate.
template <>
Pose<exact::Q> twist_step(const Vec2<exact::Q>& v, const exact::Q& omega, const exact::Q& h);

/// The angle (radians, a float view) that the rotation of a pose turns: atan2(s, c).
double turned_angle(const Pose<double>& p);

/// The pose rounded to doubles (a view).
Pose<double> to_double(const Pose<exact::Q>& p);

}  // namespace contactcert::geometry
