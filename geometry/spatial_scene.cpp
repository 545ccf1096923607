#include "geometry/spatial_scene.h"

#include <string>

#include "geometry/scene_json.h"

namespace contactcert::geometry {

using exact::JsonInput;
using exact::Q;

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Q dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 SpatialContact::edge(std::size_t j) const {
  const auto& [u, v] = edges[j];
  return {u * t1[0] + v * t2[0], u * t1[1] + v * t2[1], u * t1[2] + v * t2[2]};
}

std::pair<Vec3, Vec3> default_tangent_frame(const Vec3& n) {
  std::size_t j = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (abs(n[i]) > abs(n[j])) j = i;
  Vec3 t1{Q(0), Q(0), Q(0)};
  t1[(j + 1) % 3] = n[j];
  t1[j] = -n[(j + 1) % 3];
  return {t1, cross(n, t1)};
}

bool is_spatial_scene(const JsonInput& root) {
  const auto kind = root.is_object() ? root.find("kind") : std::nullopt;
  return kind && kind->is_string_or_number() && kind->string() == "spatial";
}

namespace {

Vec3 read_vec3(const JsonInput& j) {
  const exact::Vec<Q> v = j.rational_vector(3);
  return {v(0), v(1), v(2)};
}

bool is_zero3(const Vec3& v) { return sgn(v[0]) == 0 && sgn(v[1]) == 0 && sgn(v[2]) == 0; }

SpatialBody read_body(const JsonInput& b) {
  b.expect_keys({"mass", "inertia", "com", "box"});
  SpatialBody body;
  body.mass = read_positive(b.at("mass"));
  const exact::Mat<Q> I = b.at("inertia").rational_matrix(3, 3);
  for (Eigen::Index r = 0; r < 3; ++r)
    for (Eigen::Index c = 0; c < 3; ++c) body.inertia[r][c] = I(r, c);
  if (I(0, 1) != I(1, 0) || I(0, 2) != I(2, 0) || I(1, 2) != I(2, 1)) b.at("inertia").fail("a symmetric 3x3 matrix");
  // Sylvester's criterion: positive definite iff the leading principal minors are positive.
  const Q m2 = I(0, 0) * I(1, 1) - I(0, 1) * I(1, 0);
  const Q m3 = I(0, 0) * (I(1, 1) * I(2, 2) - I(1, 2) * I(2, 1)) - I(0, 1) * (I(1, 0) * I(2, 2) - I(1, 2) * I(2, 0)) +
               I(0, 2) * (I(1, 0) * I(2, 1) - I(1, 1) * I(2, 0));
  if (sgn(I(0, 0)) <= 0 || sgn(m2) <= 0 || sgn(m3) <= 0) b.at("inertia").fail("a positive definite matrix");
  body.com = read_vec3(b.at("com"));
  if (const auto box = b.find("box")) {
    box->expect_keys({"center", "half"});
    Box3 x{read_vec3(box->at("center")), read_vec3(box->at("half"))};
    for (const Q& h : x.half)
      if (sgn(h) <= 0) box->at("half").fail("three positive half extents");
    body.box = x;
  }
  return body;
}

// On the box: inside it and on one of its faces; the normal points into it: n_i >= 0 where p is on the lower face
// of axis i, <= 0 where on the upper one (n in the box's tangent cone at p).
void check_on_box(const Box3& box, const SpatialContact& c, const JsonInput& j) {
  bool on_face = false;
  for (std::size_t i = 0; i < 3; ++i) {
    const Q lo = box.center[i] - box.half[i], hi = box.center[i] + box.half[i];
    if (c.point[i] < lo || c.point[i] > hi) j.at("point").fail("a point on the body's box (it is outside)");
    if (c.point[i] == lo && sgn(c.normal[i]) < 0) j.at("normal").fail("a normal pointing into the box");
    if (c.point[i] == hi && sgn(c.normal[i]) > 0) j.at("normal").fail("a normal pointing into the box");
    on_face = on_face || c.point[i] == lo || c.point[i] == hi;
  }
  if (!on_face) j.at("point").fail("a point on the body's box (it is inside)");
}

// The edges: counterclockwise about n (each turn u_j v_{j+1} - v_j u_{j+1} > 0, less than half a turn), once
// around the origin, and strictly convex (each a vertex of their polygon).
void check_edges(const std::vector<std::array<Q, 2>>& d, const JsonInput& j) {
  const std::size_t m = d.size();
  auto turn = [](const std::array<Q, 2>& a, const std::array<Q, 2>& b) -> Q { return a[0] * b[1] - a[1] * b[0]; };
  auto upper = [](const std::array<Q, 2>& a) { return sgn(a[1]) > 0 || (sgn(a[1]) == 0 && sgn(a[0]) > 0); };
  std::size_t windings = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const auto &a = d[i], &b = d[(i + 1) % m], &c = d[(i + 2) % m];
    if (sgn(turn(a, b)) <= 0) j.fail("edges counterclockwise about the normal, less than half a turn apart");
    if (sgn(turn({b[0] - a[0], b[1] - a[1]}, {c[0] - b[0], c[1] - b[1]})) <= 0)
      j.fail("the vertices of a strictly convex polygon (edge " + std::to_string((i + 1) % m) + " is not one)");
    windings += !upper(a) && upper(b);
  }
  if (windings != 1) j.fail("edges once around the normal");
}

SpatialContact read_contact(const JsonInput& j, const SpatialBody& body, const std::optional<Q>& mu) {
  j.expect_keys({"name", "point", "normal", "tangent", "edges", "mu"});
  SpatialContact c;
  c.point = read_vec3(j.at("point"));
  c.normal = read_vec3(j.at("normal"));
  if (is_zero3(c.normal)) j.at("normal").fail("a non-zero normal");
  if (body.box) check_on_box(*body.box, c, j);
  if (const auto t = j.find("tangent")) {
    if (t->size() != 2) t->fail("two vectors t1, t2");
    c.t1 = read_vec3(t->at(std::size_t{0}));
    c.t2 = read_vec3(t->at(std::size_t{1}));
    if (is_zero3(c.t1) || is_zero3(c.t2) || sgn(dot(c.t1, c.normal)) != 0 || sgn(dot(c.t2, c.normal)) != 0 ||
        sgn(dot(c.t1, c.t2)) != 0 || sgn(dot(cross(c.t1, c.t2), c.normal)) <= 0)
      t->fail("t1, t2 non-zero, orthogonal to the normal and to each other, with t1 x t2 along +normal");
  } else {
    std::tie(c.t1, c.t2) = default_tangent_frame(c.normal);
  }
  if (const auto e = j.find("edges")) {
    if (j.find("mu")) j.at("mu").fail("no mu beside edges (the edges are the friction polygon)");
    if (e->size() < 4 || e->size() > 13) e->fail("4 to 13 edges [u, v]");
    for (const JsonInput& x : e->elements()) {
      const exact::Vec<Q> uv = x.rational_vector(2);
      c.edges.push_back({uv(0), uv(1)});
    }
    check_edges(c.edges, *e);
  } else {
    const auto own = j.find("mu");
    if (!own && !mu) j.fail("edges, or a friction coefficient mu here or at the top level");
    const Q m = own ? read_positive(*own) : *mu;
    const Q z(0);
    c.edges = {{m, z}, {z, m}, {-m, z}, {z, -m}};
  }
  return c;
}

}  // namespace

SpatialScene read_spatial_scene(const JsonInput& root) {
  if (!is_spatial_scene(root)) root.at("kind").fail("\"spatial\"");
  root.expect_keys({"kind", "name", "description", "source", "note", "body", "mu", "contacts"});
  SpatialScene s{read_body(root.at("body")), {}};
  const auto mu = root.find("mu");
  const std::optional<Q> m = mu ? std::optional<Q>(read_positive(*mu)) : std::nullopt;
  const JsonInput contacts = root.at("contacts");
  for (const JsonInput& c : contacts.elements()) s.contacts.push_back(read_contact(c, s.body, m));
  if (s.contacts.empty()) contacts.fail("at least one contact");
  return s;
}

}  // namespace contactcert::geometry
