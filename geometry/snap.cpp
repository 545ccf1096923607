#include "geometry/snap.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/contact_frame.h"
#include "geometry/scene_json.h"

namespace contactcert::geometry {

using exact::Z;

Q rational_length(const Q& squared, bool* rational, unsigned long bits) {
  if (mpz_perfect_square_p(squared.get_num_mpz_t()) && mpz_perfect_square_p(squared.get_den_mpz_t())) {
    Z n, d;
    mpz_sqrt(n.get_mpz_t(), squared.get_num_mpz_t());
    mpz_sqrt(d.get_mpz_t(), squared.get_den_mpz_t());
    return Q(n, d);
  }
  if (rational) *rational = false;
  const Z scale = Z(1) << bits;
  const Z scaled = Z(squared * Q(scale * scale));  // floor: squared >= 0
  Z root;
  mpz_sqrt(root.get_mpz_t(), scaled.get_mpz_t());
  Q r(root, scale);
  r.canonicalize();
  return r;
}

Point2 circle_point(const Point2& c, const Q& r, const Q& t, long quadrant) {
  const Q den = 1 + t * t;
  Point2 u{(1 - t * t) / den, 2 * t / den};
  for (long q = 0; q < quadrant; ++q) u = perp(u);
  return c + r * u;
}

Q simplest_between(const Q& lo, const Q& hi) {
  if (sgn(lo) <= 0 && sgn(hi) >= 0) return Q(0);
  if (sgn(hi) < 0) return -simplest_between(-hi, -lo);
  Z n;  // 0 < lo <= hi: the smallest integer >= lo, if it is <= hi; else floor(lo) + 1 / (the simplest reciprocal)
  mpz_cdiv_q(n.get_mpz_t(), lo.get_num_mpz_t(), lo.get_den_mpz_t());
  if (Q(n) <= hi) return Q(n);
  const Q f(Z(n - 1));
  Q s = f + 1 / simplest_between(1 / (hi - f), 1 / (lo - f));
  s.canonicalize();
  return s;
}

namespace {

using Json = nlohmann::ordered_json;

std::string text(const Point2& p) {
  std::string s = "[";  // appended, not "[" + string: gcc 12's -Wrestrict false positive
  s += exact::to_string(p.x);
  s += ", ";
  s += exact::to_string(p.y);
  return s += "]";
}

/// A float view of a tolerance or distance for messages ("1e-09"), never an exact text thousands of digits long.
std::string view(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}
std::string view(const Q& q) { return q.get_d() == 0 && sgn(q) > 0 ? "< 1e-308" : view(q.get_d()); }

/// 2^-bits <= tol / 8: the bits of the square roots bracketing a distance.
unsigned long bits_for(const Q& tol) {
  const Q inv = Q(8) / tol;
  Z n;
  mpz_cdiv_q(n.get_mpz_t(), inv.get_num_mpz_t(), inv.get_den_mpz_t());
  return mpz_sizeinbase(n.get_mpz_t(), 2) + 1;
}

/// The numbers of the tree, but for fixel points, replaced by the simplest rational within tol.
void snap_numbers(Json& j, const std::string& path, const Q& tol, std::vector<Snap>& snaps) {
  if (j.is_object()) {
    const bool fixel = path.rfind("$.fixels[", 0) == 0 && path.back() == ']';
    for (auto it = j.begin(); it != j.end(); ++it)
      if (!(fixel && (it.key() == "position" || it.key() == "point" || it.key() == "normal")))
        snap_numbers(it.value(), path + "." + it.key(), tol, snaps);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) snap_numbers(j[i], path + "[" + std::to_string(i) + "]", tol, snaps);
  } else if (j.is_string()) {
    Q x;
    if (!exact::parse_rational_into(j.get<std::string>(), x)) return;  // not a number ("planar", "disk")
    const Q s = simplest_between(x - tol, x + tol);
    if (s == x) return;
    snaps.push_back({path, exact::to_string(x), exact::to_string(s), Q((s - x) * (s - x))});
    j = exact::to_string(s);
  }
}

/// p on the circle (c, rho) at a rational point within tol of p, or nullopt: the direction's t = tan(phi / 2) as
/// the simplest rational in a shrinking interval around its bracket, each candidate checked exactly.
std::optional<Point2> onto_circle(const Point2& c, const Q& rho, const Point2& p, const Q& tol, unsigned long bits) {
  Point2 u = p - c;
  long quadrant = 0;
  while (!(sgn(u.x) > 0 && sgn(u.y) >= 0)) {  // turn u clockwise into phi in [0, pi/2)
    u = {u.y, -u.x};
    ++quadrant;
  }
  const Q ulp(Z(1), Z(1) << bits);
  const Q s = rational_length(norm2(u), nullptr, bits);  // s <= |u| <= s + ulp
  const Q t_lo = u.y / (s + ulp + u.x), t_hi = u.y / (s + u.x);
  Q delta = tol / (4 * rho);
  for (int k = 0; k < 256; ++k, delta /= 2) {  // bounded: a point this close to the limit is refused
    const Point2 q = circle_point(c, rho, simplest_between(t_lo - delta, t_hi + delta), quadrant);
    if (norm2(q - p) <= tol * tol) return q;
  }
  return std::nullopt;
}

Point2 snap_on_disk(const DiskShape& d, const Point2& p, const Q& tol, bool must_touch, const exact::JsonInput& field) {
  const Q d2 = norm2(p - d.center), r2 = d.radius * d.radius;
  if (d2 == r2) return p;
  if (sgn(d2) == 0) field.fail("a point away from the disk centre (its direction is undefined)");
  const Q far = d.radius + tol, near = d.radius - tol;
  const bool touching = d2 <= far * far && (sgn(near) <= 0 || d2 >= near * near);
  const std::string tol_text = view(tol);
  if (!touching && must_touch)
    field.fail("a point within " + tol_text + " of the disk boundary (--snap tolerance); it is " +
               view(std::abs(std::sqrt(d2.get_d()) - d.radius.get_d())) + " away");
  const unsigned long bits = bits_for(tol);
  bool rational = true;
  const Q s = rational_length(d2, &rational, bits);
  if (!touching && (rational || d2 < r2)) return p;  // a rational distance: its frame is exact; inside: refused later
  const Q ulp(Z(1), Z(1) << bits);
  const Q rho = touching ? d.radius : simplest_between(s + ulp - tol / 2, s + tol / 2);
  if (auto q = onto_circle(d.center, rho, p, tol, bits)) return *q;
  field.fail("a point that a rational point of the circle of radius ~" + view(rho) + " lies within " + tol_text +
             " of (--snap tolerance)");
}

Point2 snap_on_polygon(const std::vector<Point2>& V, const Point2& p, const Q& tol, bool must_touch,
                       const exact::JsonInput& field) {
  Point2 best = V[0];
  Q best_d2 = norm2(p - V[0]);
  for (std::size_t e = 0; e < V.size(); ++e) {
    // The exact projection of p onto the edge segment [a, b]: a + clamp(t, 0, 1) (b - a).
    const Point2& a = V[e];
    const Point2 ab = V[(e + 1) % V.size()] - a;
    Q t = dot(p - a, ab) / norm2(ab);
    if (sgn(t) < 0) t = 0;
    if (t > 1) t = 1;
    const Point2 q = a + t * ab;
    if (const Q d2 = norm2(p - q); d2 < best_d2) best_d2 = d2, best = q;
  }
  if (sgn(best_d2) == 0) return p;
  if (best_d2 <= tol * tol) return best;
  if (must_touch)
    field.fail("a point within " + view(tol) + " of the polygon boundary (--snap tolerance); it is " +
               view(std::sqrt(best_d2.get_d())) + " away");
  // Not meant to touch: its coordinates are plain numbers, each moved by at most tol / 2.
  const Q h = tol / 2;
  return {simplest_between(p.x - h, p.x + h), simplest_between(p.y - h, p.y + h)};
}

/// An explicit contact's normal n at its snapped point q: the projection (n . m / |m|^2) m of n onto the inward
/// normal m there when their angle theta has sin^2 theta <= tol^2 (exactly: cross(n, m)^2 <= tol^2 |n|^2 |m|^2),
/// so that the frame holds exactly; at a vertex (no unique m) its coordinates snapped as numbers.
Point2 snap_normal(const Shape& shape, const Point2& q, const Point2& n, const Q& tol) {
  const FrameResult at = frame_from_position(shape, q);
  if (at.status != FrameStatus::kOk) {
    const Q h = tol / 2;
    return {simplest_between(n.x - h, n.x + h), simplest_between(n.y - h, n.y + h)};
  }
  const Point2& m = at.frame.normal;
  const Q c = cross(n, m);
  if (sgn(dot(n, m)) <= 0 || c * c > tol * tol * norm2(n) * norm2(m)) return n;  // the reader says why
  return Q(dot(n, m) / norm2(m)) * m;
}

}  // namespace

SnappedScene snap_planar_scene(const std::string& text_in, const std::string& file, const Q& tol) {
  if (sgn(tol) <= 0) throw exact::InputError(file, "--snap", "a tolerance > 0");
  const exact::JsonInput original = exact::JsonInput::parse(text_in, file);
  if (!original.is_object()) original.fail("a planar scene object");
  Json j = Json::parse(original.canonical_text());  // every number an exact text in lowest terms
  SnappedScene out;
  snap_numbers(j, "$", tol, out.snaps);
  const exact::JsonInput root = exact::JsonInput::parse(j.dump(), file);
  const Shape shape = read_shape(root.at("workpiece").at("shape"));
  if (const auto fixels = root.find("fixels"); fixels && fixels->is_array()) {
    for (std::size_t i = 0; i < fixels->size(); ++i) {
      const exact::JsonInput f = fixels->at(i);
      if (!f.is_object()) continue;  // the reader names it
      for (const char* key : {"position", "point"}) {
        const auto node = f.find(key);
        if (!node) continue;
        const exact::Vec<Q> v = node->rational_vector(2);
        const Point2 p{v(0), v(1)};
        const bool must_touch = std::string(key) == "point";
        const Point2 q = std::holds_alternative<DiskShape>(shape)
                             ? snap_on_disk(std::get<DiskShape>(shape), p, tol, must_touch, *node)
                             : snap_on_polygon(std::get<PolygonShape>(shape).vertices, p, tol, must_touch, *node);
        if (q != p) {
          out.snaps.push_back({node->path(), text(p), text(q), norm2(q - p)});
          j["fixels"][i][key] = Json::array({exact::to_string(q.x), exact::to_string(q.y)});
        }
        const auto normal = f.find("normal");
        if (!must_touch || !normal) continue;
        const exact::Vec<Q> w = normal->rational_vector(2);
        const Point2 n{w(0), w(1)}, m = snap_normal(shape, q, n, tol);
        if (m == n) continue;
        out.snaps.push_back({normal->path(), text(n), text(m), norm2(m - n)});
        j["fixels"][i]["normal"] = Json::array({exact::to_string(m.x), exact::to_string(m.y)});
      }
    }
  }
  // The labels canonical_text leaves out, back where the reader allows them.
  const auto keep_labels = [](const exact::JsonInput& from, Json& to, std::initializer_list<const char*> keys) {
    for (const char* key : keys)
      if (const auto label = from.find(key); label && label->is_string_or_number()) try {
          to[key] = label->string();
        } catch (const exact::InputError&) {  // a number where a label was expected: the reader ignores it too
        }
  };
  keep_labels(original, j, {"name", "description"});
  if (const auto fixels = original.find("fixels"); fixels && fixels->is_array() && j["fixels"].is_array())
    for (std::size_t i = 0; i < fixels->size() && i < j["fixels"].size(); ++i)
      if (fixels->at(i).is_object()) keep_labels(fixels->at(i), j["fixels"][i], {"name"});
  out.text = j.dump(2);
  return out;
}

}  // namespace contactcert::geometry
