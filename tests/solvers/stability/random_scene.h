// Seeded random planar scenes for the stability tests.
#pragma once

#include <random>
#include <sstream>
#include <string>

#include "exact/number.h"

namespace contactcert::solvers::test {

using exact::Q;

inline std::string q(long p, long r) {  // "p/r" as a JSON string
  std::ostringstream s;
  s << '"' << p << '/' << r << '"';
  return s.str();
}

// A random scene of k fixels: a unit disk (fixels along Pythagorean directions) or a square / 3-4-5 triangle
// (fixels on edges), each fixel touching or at a small gap, an off-centre com, mu from {0, 1/3, 1}.
inline std::string random_scene(std::mt19937_64& rng, std::size_t k) {
  std::uniform_int_distribution<long> small(-3, 3), den(1, 4), coin(0, 2);
  const char* mus[] = {"0", "1/3", "1"};
  std::ostringstream s;
  const int shape = static_cast<int>(rng() % 3);
  s << R"({"kind":"planar","workpiece":{"shape":)";
  if (shape == 0) s << R"({"type":"disk","center":[0,0],"radius":1})";
  if (shape == 1) s << R"({"type":"polygon","vertices":[[-1,-1],[1,-1],[1,1],[-1,1]]})";
  if (shape == 2) s << R"({"type":"polygon","vertices":[[0,0],[4,0],[0,3]]})";
  s << R"(,"com":[)" << q(small(rng), 10) << "," << q(small(rng), 10) << R"(],"mass":1,"inertia":)" << q(den(rng), 2)
    << R"(},"mu_s":")" << mus[coin(rng)] << R"(","mu_k":")" << mus[coin(rng)] << R"(","fixels":[)";
  for (std::size_t i = 0; i < k; ++i) {
    const long gap = coin(rng) == 0 ? 1 : 0;  // a third of the fixels at a gap
    Q x, y;
    if (shape == 0) {  // direction ((1 - t^2), 2t) / (1 + t^2), t = a / b
      // Denominator drawn first, then numerator, in sequence: as function arguments their order would differ
      // between compilers (gcc and clang make different scenes from one seed).
      const long b = static_cast<long>(1 + rng() % 3);
      const long a = static_cast<long>(rng() % 13) - 6;
      const Q t = Q(a, b);
      const Q r = Q(1) + Q(gap, 10);
      x = r * (1 - t * t) / (1 + t * t);
      y = r * 2 * t / (1 + t * t);
    } else {
      const Q u = Q(static_cast<long>(2 + rng() % 7), 10);  // along the edge, away from its ends
      const int e = static_cast<int>(rng() % (shape == 1 ? 4 : 3));
      const Q off(gap, 10);
      if (shape == 1) {
        const Q along = 2 * u - 1;
        if (e == 0) x = along, y = -1 - off;
        if (e == 1) x = 1 + off, y = along;
        if (e == 2) x = -along, y = 1 + off;
        if (e == 3) x = -1 - off, y = -along;
      } else {  // edges (0,0)-(4,0), (4,0)-(0,3) with outward normal (3,4)/5, (0,3)-(0,0)
        if (e == 0) x = 4 * u, y = -off;
        if (e == 1) x = 4 - 4 * u + 3 * off / 5, y = 3 * u + 4 * off / 5;
        if (e == 2) x = -off, y = 3 - 3 * u;
      }
    }
    s << (i ? "," : "") << R"({"position":[")" << x << R"(",")" << y << R"("]})";
  }
  s << "]}";
  return s.str();
}

}  // namespace contactcert::solvers::test
