// The contact modes of N bodies (solvers/assembly/assembly_modes.h): a hand-derived two-box count, N = 1 against
// the single-body `modes` on the bundled scenes, and seeded random small assemblies against a brute force over all
// 4^k mode strings; every list's certificate is verified by the independent checker.
#include "solvers/assembly/assembly_modes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <set>

#include "checker/assembly_modes_check.h"
#include "exact/strict_feasibility.h"
#include "geometry/scene_json.h"
#include "runtime/scenes.h"
#include "solvers/stability/contact_modes.h"
#include "tests/solvers/assembly/assembly_fixtures.h"

namespace contactcert::solvers::assembly {
namespace {

using geometry::Point2;
using namespace testing;  // the fixtures' scene builders

std::set<std::string> mode_set(const AssemblyModes& m) {
  std::set<std::string> out;
  for (const ModeString& s : m.tree.modes) out.insert(s.text());
  return out;
}

/// The modes of the assembly in `text`, with the checker's verdict on their certificate.
AssemblyModes checked_modes(const std::string& text) {
  const geometry::Assembly a = geometry::read_assembly(exact::JsonInput::parse(text, "test.json"));
  AssemblyModes m = assembly_modes(a);
  const checker::ModesCertificateCheck c = checker::check_assembly_modes_certificate(
      exact::JsonInput::parse(assembly_modes_certificate(text, m), "certificate.json"));
  EXPECT_TRUE(c.valid) << c.reason;
  EXPECT_EQ(c.modes, static_cast<long>(m.tree.modes.size()));
  return m;
}

// Box 0 = [0, 2] x [0, 1] (com (1, 1/2)) on the ground at its corners (contacts 0, 1, n = (0, 1), t = (-1, 0)); box
// 1 = [0, 2] x [1, 2] on box 0 at the single point (1, 1) (contact 2). With vdot_0 = (ax, ay, al):
//   contact 0 (r = (-1, -1/2)): a_n = ay - al, a_t = -ax - al/2;  contact 1 (r = (1, -1/2)): a_n = ay + al,
//   a_t = -ax - al/2 - the same a_t. Contacts 0 and 1: ss (1), s with l r n (3), l r n with s (3), and with both
//   a_n = 0 (ay = al = 0) a_t = -ax is shared: ll, rr, nn (3) but not the 6 mixed pairs: 10 modes. Contact 2's a_n
//   and a_t contain ay_1 and ax_1, which no other row has, so each of its 4 letters goes with each of the 10:
//   40 modes (of 64 strings).
TEST(AssemblyModes, TwoBoxesHandDerived) {
  SceneText s;
  const std::string g = obstacle(testing::ground(s));
  const std::size_t b0 = s.body(box(0, 0, 2, 1)), b1 = s.body(box(0, 1, 2, 2));
  for (const Q& x : {Q(0), Q(2)}) s.contact(g, body(b0), point(x, 0), "[0, 1]", mu("1/2"));
  s.contact(body(b0), body(b1), point(1, 1), "[0, 1]", mu("1/2"));
  const AssemblyModes m = checked_modes(s.json());
  EXPECT_EQ(m.tree.modes.size(), 40U);
  const std::set<std::string> modes = mode_set(m);
  for (const char* mixed : {"lr", "ln", "rl", "rn", "nl", "nr"})
    for (const char c : std::string("slrn")) EXPECT_EQ(modes.count(std::string(mixed) + c), 0U) << mixed << c;
  for (const char* fine : {"sss", "ssn", "lls", "nnn", "rrl", "srs"}) EXPECT_EQ(modes.count(fine), 1U) << fine;
}

// N = 1: a bundled scene whose fixels all touch, as an assembly of its workpiece and its fixels (each contact from
// its fixel into the body, at the scene's frame), has the single-body modes.
TEST(AssemblyModes, OneBodyAgreesWithTheSingleBodyModes) {
  int compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(runtime::bundled_scenes_dir())) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("bt2002_", 0) != 0) continue;
    const geometry::PlanarScene scene =
        geometry::read_planar_scene(exact::JsonInput::parse(exact::JsonInput::read_text(entry.path().string()), name));
    if (!std::all_of(scene.fixels.begin(), scene.fixels.end(), [](const auto& f) { return f.frame.touching(); }))
      continue;
    geometry::Assembly a;
    a.bodies.push_back({scene.workpiece.shape, scene.workpiece.com, Q(1), scene.workpiece.inertia_per_mass, 0, 0, 0});
    for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
      const geometry::Fixel& f = scene.fixels[i];
      a.fixels.push_back(f.frame.point);
      a.contacts.push_back({{geometry::Party::Kind::kFixel, i},
                            {geometry::Party::Kind::kBody, 0},
                            f.frame.point,
                            f.frame.normal,
                            f.mu_s,
                            f.mu_k});
    }
    std::vector<std::string> one, many;
    for (const ModeString& m : contact_modes(scene).tree.modes) one.push_back(m.text());
    for (const ModeString& m : assembly_modes(a).tree.modes) many.push_back(m.text());
    EXPECT_EQ(one, many) << name;
    ++compared;
  }
  EXPECT_GE(compared, 4);
}

/// Whether some vdot realises the mode, by a brute force of its own: one strict LP on the dense rows of the
/// relative accelerations (the contact point's acceleration on body b from rest: (a_x, a_y) + alpha (-r_y, r_x)).
bool feasible(const geometry::Assembly& a, const std::string& mode) {
  const auto N3 = static_cast<Eigen::Index>(3 * a.bodies.size()), k = static_cast<Eigen::Index>(mode.size());
  exact::StrictSystem<Q> S;
  S.A = exact::Mat<Q>::Zero(2 * k, N3 + k);
  S.b = Vec<Q>::Zero(2 * k);
  S.is_free.assign(static_cast<std::size_t>(N3 + k), false);
  S.strict.assign(static_cast<std::size_t>(N3 + k), true);
  for (Eigen::Index j = 0; j < N3; ++j) S.is_free[static_cast<std::size_t>(j)] = true, S.strict[j] = false;
  for (Eigen::Index i = 0; i < k; ++i) {
    const geometry::AssemblyContact& c = a.contacts[static_cast<std::size_t>(i)];
    const Point2 d[2] = {c.normal, {-c.normal.y, c.normal.x}};
    for (Eigen::Index row = 0; row < 2; ++row)
      for (const auto& [p, s] : {std::pair{c.from, -1}, std::pair{c.to, 1}}) {
        if (!p.movable()) continue;
        const Point2 r = c.point - a.bodies[p.index].com;
        const auto b = static_cast<Eigen::Index>(3 * p.index);
        S.A(2 * i + row, b) += s * d[row].x;
        S.A(2 * i + row, b + 1) += s * d[row].y;
        S.A(2 * i + row, b + 2) += s * (d[row].y * r.x - d[row].x * r.y);
      }
    // The slack of contact i: s: a_n = sigma > 0 (a_t free: its row is dropped by a zero slack... kept as a_t -
    // sigma' with sigma' free); l: a_t = sigma > 0; r: a_t = -sigma; n: none (a_t = 0).
    const char L = mode[static_cast<std::size_t>(i)];
    const Eigen::Index sigma = N3 + i;
    if (L == 's') {
      S.A(2 * i, sigma) = -1;
      S.A.row(2 * i + 1).setZero();
    } else if (L == 'n') {
      S.strict[static_cast<std::size_t>(sigma)] = false;  // an unused column, zero in every row
    } else {
      S.A(2 * i + 1, sigma) = L == 'l' ? -1 : 1;
    }
  }
  return exact::strict_feasibility(S, exact::Arith::kExact).status == exact::StrictStatus::kFeasible;
}

// Seeded random stacks of N = 2 or 3 boxes (widths 1-3, offsets in halves, one or two contacts per interface, so
// k <= 6): the tree's list equals the brute force over all 4^k strings.
TEST(AssemblyModes, RandomAssembliesAgreeWithABruteForce) {
  std::mt19937 rng(31);
  for (int draw = 0; draw < 12; ++draw) {
    SceneText s;
    std::string below = obstacle(testing::ground(s));
    Q lo = -100, hi = 100;
    const int n = draw < 8 ? 2 : 3;
    for (int i = 0; i < n; ++i) {
      Q x0, x1;
      do {
        x0 = Q(static_cast<long>(rng() % 5) - 2, 2);
        x1 = x0 + Q(static_cast<long>(1 + rng() % 3));
      } while (!(std::max(x0, lo) < std::min(x1, hi)));
      const Q a = std::max(x0, lo), b = std::min(x1, hi);
      const std::size_t id = s.body(box(x0, i, x1, i + 1));
      const bool two = rng() % 2 == 0;
      for (const Q& x : two ? std::vector<Q>{a, b} : std::vector<Q>{(a + b) / 2})
        s.contact(below, body(id), point(x, i), "[0, 1]", mu("1/2"));
      below = body(id), lo = x0, hi = x1;
    }
    const geometry::Assembly a = s.read();
    const AssemblyModes m = checked_modes(s.json());
    const auto k = a.contacts.size();
    std::set<std::string> brute;
    std::string mode(k, 's');
    for (long code = 0; code < (1L << (2 * k)); ++code) {
      for (std::size_t i = 0; i < k; ++i) mode[i] = "slrn"[(code >> (2 * i)) & 3];
      if (feasible(a, mode)) brute.insert(mode);
    }
    EXPECT_EQ(mode_set(m), brute) << s.json();
  }
}

}  // namespace
}  // namespace contactcert::solvers::assembly
