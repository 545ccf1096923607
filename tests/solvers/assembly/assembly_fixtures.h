// Assemblies for the tests, written as scene files (so that the reader is exercised too): axis-aligned boxes on a
// ground obstacle, contacts at the ends of each interface.
#pragma once

#include <string>
#include <tuple>
#include <vector>

#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/assembly.h"

namespace contactcert::solvers::assembly::testing {

using exact::Q;

inline std::string num(const Q& q) { return std::string("\"") + exact::to_string(q) + "\""; }
inline std::string point(const Q& x, const Q& y) { return std::string("[") + num(x) + ", " + num(y) + "]"; }

/// {"type": "polygon"} of the box [x0, x1] x [y0, y1].
inline std::string box(const Q& x0, const Q& y0, const Q& x1, const Q& y1) {
  return "{\"type\": \"polygon\", \"vertices\": [" + point(x0, y0) + ", " + point(x1, y0) + ", " + point(x1, y1) +
         ", " + point(x0, y1) + "]}";
}

/// A scene under construction: bodies, obstacles and contacts as JSON texts.
struct SceneText {
  std::string kind = "planar";
  std::vector<std::string> bodies, obstacles, fixels, fingers, contacts;
  std::string top;  ///< more top-level members, e.g. "\"gravity\": [0, -1]"
  std::size_t body(const std::string& shape, const std::string& more = "") {
    bodies.push_back("{\"shape\": " + shape + (more.empty() ? "" : ", " + more) + "}");
    return bodies.size() - 1;
  }
  std::size_t obstacle(const std::string& shape) {
    obstacles.push_back("{\"shape\": " + shape + "}");
    return obstacles.size() - 1;
  }
  /// A contact; `from`/`to` as {"body": 0} texts.
  void contact(const std::string& from, const std::string& to, const std::string& p, const std::string& n,
               const std::string& friction) {
    contacts.push_back("{\"from\": " + from + ", \"to\": " + to + ", \"point\": " + p + ", \"normal\": " + n + ", " +
                       friction + "}");
  }
  std::string json() const {
    const auto list = [](const std::vector<std::string>& v) {
      std::string s = "[";
      for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
      return s + "]";
    };
    std::string s = "{\"kind\": \"" + kind + "\", \"bodies\": " + list(bodies) + ", \"contacts\": " + list(contacts);
    if (!obstacles.empty()) s += ", \"obstacles\": " + list(obstacles);
    if (!fixels.empty()) s += ", \"fixels\": " + list(fixels);
    if (!fingers.empty()) s += ", \"fingers\": " + list(fingers);
    if (!top.empty()) s += ", " + top;
    return s + "}";
  }
  geometry::Assembly read() const { return geometry::read_assembly(exact::JsonInput::parse(json(), "test.json")); }
};

inline std::string body(std::size_t i) { return "{\"body\": " + std::to_string(i) + "}"; }
inline std::string obstacle(std::size_t i) { return "{\"obstacle\": " + std::to_string(i) + "}"; }
inline std::string mu(const char* m) { return std::string("\"mu\": \"") + m + "\""; }

/// The ground: obstacle [-100, 100] x [-1, 0].
inline std::size_t ground(SceneText& s) { return s.obstacle(box(-100, -1, 100, 0)); }

/// A box [x0, x1] x [y0, y1] resting on `below` (a body or obstacle text whose top is at y0) with contacts at the
/// ends of the overlap [lo, hi] of their x-ranges; returns the body's index.
inline std::size_t stack_box(SceneText& s, const std::string& below, const Q& x0, const Q& y0, const Q& x1, const Q& y1,
                             const Q& lo, const Q& hi, const char* m) {
  const std::size_t b = s.body(box(x0, y0, x1, y1));
  for (const Q& x : {lo, hi}) s.contact(below, body(b), point(x, y0), "[0, 1]", mu(m));
  return b;
}

/// A stack of n boxes [0, 2] x [i, i + 1] on the ground, two contacts per interface (k = 2n).
inline SceneText box_stack(std::size_t n, const char* m = "1/2") {
  SceneText s;
  std::string below = obstacle(ground(s));
  for (std::size_t i = 0; i < n; ++i)
    below = body(stack_box(s, below, 0, Q(static_cast<long>(i)), 2, Q(static_cast<long>(i + 1)), 0, 2, m));
  return s;
}

/// A row of n boxes [2i, 2i + 2] x [0, 1] on the ground, each touching the next along x = 2i + 2: two contacts per
/// interface (k = 2n + 2(n - 1)), normals (0, 1) from the ground and (1, 0) from each box into the next.
inline SceneText box_row(std::size_t n, const char* m = "1/2") {
  SceneText s;
  const std::string g = obstacle(ground(s));
  for (std::size_t i = 0; i < n; ++i) {
    const Q x(static_cast<long>(2 * i));
    const std::size_t b = stack_box(s, g, x, 0, x + 2, 1, x, x + 2, m);
    if (i == 0) continue;
    for (const Q& y : {Q(0), Q(1)}) s.contact(body(b - 1), body(b), point(x, y), "[1, 0]", mu(m));
  }
  return s;
}

/// A corbelled arch of 9 blocks: two piers of four 2 x 1 blocks stepping 1/4 inward per course (left from [0, 2],
/// right from [6, 8]) and a keystone [7/4, 25/4] x [4, 5] over both; two contacts per interface (k = 20).
inline SceneText corbel_arch(const char* m = "1/2") {
  SceneText s;
  const std::string g = obstacle(ground(s));
  std::string left = g, right = g;
  for (long i = 0; i < 4; ++i) {
    const Q step(i, 4), below_step(i == 0 ? 0 : i - 1, 4);  // the course below starts at below_step (ground: 0)
    // Left block [step, step + 2] on [below_step, below_step + 2] (the ground: [0, 2]); the right one mirrored.
    left = body(stack_box(s, left, step, i, step + 2, i + 1, step, Q(below_step + 2), m));
    right = body(stack_box(s, right, 6 - step, i, 8 - step, i + 1, Q(6 - below_step), 8 - step, m));
  }
  const std::size_t key = s.body(box(Q(7, 4), 4, Q(25, 4), 5));
  for (const auto& [below, lo, hi] : {std::tuple{left, Q(7, 4), Q(11, 4)}, std::tuple{right, Q(21, 4), Q(25, 4)}})
    for (const Q& x : {lo, hi}) s.contact(below, body(key), point(x, 4), "[0, 1]", mu(m));
  return s;
}

}  // namespace contactcert::solvers::assembly::testing
