// The contact modes of a body in space from rest (solvers/spatial/spatial_modes.h): the hand-derived counts of a box
// on a plane and in a corner, seeded random bodies against a brute force over all mode strings (an LP each in its
// own formulation, unless a letter or a pair of its letters alone has none), extruded planar scenes against the planar
// tree, the reader's refusals, and forged certificates, which the independent checker (checker/spatial_modes_check.h)
// must reject.
#include "solvers/spatial/spatial_modes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>

#include "checker/certificate_lines.h"
#include "checker/spatial_modes_check.h"
#include "exact/input_error.h"
#include "exact/strict_feasibility.h"
#include "geometry/scene_json.h"
#include "runtime/scenes.h"
#include "solvers/spatial/spatial_modes_certificate.h"
#include "solvers/stability/contact_modes.h"
#include "tests/solvers/spatial/extruded_scene.h"

namespace contactcert::solvers::spatial {
namespace {

using geometry::SpatialContact;
using geometry::SpatialScene;
using geometry::Vec3;

std::string read(const std::string& scene) {
  return exact::JsonInput::read_text(runtime::bundled_scenes_dir() + "/" + scene + ".json");
}

SpatialScene parse(const std::string& text) { return geometry::read_spatial_scene(exact::JsonInput::parse(text, "t")); }

checker::ModesCertificateCheck check_text(const std::string& certificate) {
  return checker::check_spatial_modes_certificate(checker::CertificateLines(certificate, "certificate.json"));
}

// The certificate in lines with one line changed: element i of list `name` (or the head member `name` if i < 0)
// replaced by edit(its value), or dropped if edit returns null (a list's last element: the comma before it too).
std::string forge_line(const std::string& text, const std::string& name, int i,
                       const std::function<nlohmann::json(nlohmann::json)>& edit) {
  std::vector<std::string> lines;
  for (std::size_t at = 0, end; at < text.size(); at = end + 1)
    lines.push_back(text.substr(at, (end = text.find('\n', at)) - at));
  std::size_t at = 0;
  const std::string key = " \"" + name + "\": ";
  while (lines[at].rfind(key, 0) != 0) ++at;
  at += i < 0 ? 0 : static_cast<std::size_t>(i) + 1;
  std::string& line = lines[at];
  const bool comma = line.back() == ',';
  const std::size_t from = i < 0 ? key.size() : 2;
  const nlohmann::json value = edit(nlohmann::json::parse(line.substr(from, line.size() - from - (comma ? 1 : 0))));
  if (value.is_null()) {
    if (!comma) lines[at - 1].pop_back();
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(at));
  } else {
    line = line.substr(0, from) + value.dump() + (comma ? "," : "");
  }
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

std::set<std::string> mode_set(const SpatialModeTree& t) { return {t.modes.begin(), t.modes.end()}; }

// Box on a plane on its 4 bottom corners (x, y) in {-1, 1}^2, r_z = -1/2, square pyramids along x and y.
// a_n = a_z + alpha_x y - alpha_y x: the cone {a_n >= 0} in (a_z, alpha_x, alpha_y) is a square pyramid, and its
// faces are the contact patterns: its interior (all separate, 1), 4 facets (one corner touches), 4 edges (two
// adjacent corners), the apex (all four): 10 patterns. A touching corner's tangential acceleration v has the letter
// of (sign(v_x + v_y), sign(v_x - v_y)): 9 letters (f, 4 sectors, 4 diagonal rays).
//   one corner: v free (a_x, a_y free): 9 modes each, 36.
//   two corners on x = 1: v at (1, +-1) is (U -+ alpha_z, V): same y component, free x components: per V > 0 the x's
//     fall among {-V, V} in 5 x 5 ways, V < 0 as many, V = 0 3 x 3; 4 patterns counted twice, 4 of V = 0's too:
//     25 + 25 - 4 + 5 = 51 per edge, 204.
//   all four: a_z = alpha_x = alpha_y = 0, v_i = T + alpha_z (-y_i, x_i): in P = T_x + T_y, R = T_x - T_y, w = alpha_z
//     the forms are P, P +- 2w, R, R +- 2w: 7 x 7 sign patterns for w > 0, as many for w < 0 (4 shared), 3 x 3 at
//     w = 0 (4 of them seen before): 49 + 49 - 4 + 5 = 99.
// Total 1 + 36 + 204 + 99 = 340.
TEST(SpatialModes, BoxOnPlaneHasTheHandCountedModes) {
  const std::string text = read("spatial_box_on_plane");
  const SpatialModeTree t = spatial_modes(spatial_model(parse(text)));
  EXPECT_EQ(t.modes.size(), 340u);
  std::map<std::string, int> per_pattern;  // touching pattern (t or s per corner) -> modes
  for (const std::string& m : t.modes) {
    std::string p;
    for (const char c : m) p += c == 's' ? 's' : 't';
    ++per_pattern[p];
  }
  EXPECT_EQ(per_pattern.size(), 10u);
  EXPECT_EQ(per_pattern["ssss"], 1);
  EXPECT_EQ(per_pattern["tttt"], 99);
  EXPECT_EQ(per_pattern["ttss"], 51);  // corners (1, 1) and (1, -1)
  EXPECT_EQ(per_pattern["stss"], 9);
  EXPECT_EQ(per_pattern.count("tsts"), 0u);  // diagonal corners cannot touch without the other two
  const checker::ModesCertificateCheck c = check_text(spatial_modes_certificate(text, t));
  EXPECT_TRUE(c.valid) << c.reason;
  EXPECT_EQ(c.modes, 340);
}

// Box in a corner: on the floor and against the wall x = -1 at two top corners. All six touch only for
// a_z = alpha = 0 and a_x = 0: the box slides along the wall's y axis or sticks, 3 modes. Sliding along +y puts the
// friction on the edge along -y: the floor's edge 3 (G), the octagon's edge 4 stated in the frame (y, z) (I), the
// default square's edge 2 in the frame (y, z) of the normal x (E); along -y the edges along +y (C, A, A).
// The nodes budget stops the walk with what it covered.
TEST(SpatialModes, BudgetsStopTheWalk) {
  const SpatialModel model = spatial_model(parse(read("spatial_box_on_plane")));
  SpatialModeOptions nodes;
  nodes.max_nodes = 50;
  EXPECT_THROW(spatial_modes(model, nodes), exact::BudgetExceeded);
  EXPECT_EQ(spatial_modes(model).modes.size(), 340u);  // the default budgets hold it
}

// A dead prefix holds the index of its proof, which most share: the box on a plane's 2199 dead prefixes take 79
// proofs (one per LP that found a prefix dead, of 426 with the 4 that choose the later rows a_n >= 0 to keep; one
// proof serves 829), and each one's vector weighs exactly its proof's rows.
TEST(SpatialModes, DeadPrefixesShareTheirProofs) {
  const SpatialModeTree t = spatial_modes(spatial_model(parse(read("spatial_box_on_plane"))));
  EXPECT_EQ(t.dead.size(), 2199u);
  EXPECT_EQ(t.proofs.size(), 79u);
  EXPECT_EQ(t.lps, 426);
  std::vector<long> takers(t.proofs.size(), 0);
  for (const SpatialDeadPrefix& d : t.dead) {
    ASSERT_LT(d.proof, t.proofs.size());
    ++takers[d.proof];
    const Vec<Q> y = dead_motzkin(t, d);
    EXPECT_EQ(static_cast<std::size_t>((y.array() != Q(0)).count()), t.proofs[d.proof].support.size()) << d.prefix;
  }
  EXPECT_EQ(*std::max_element(takers.begin(), takers.end()), 829);
  EXPECT_EQ(std::count(takers.begin(), takers.end(), 0), 0);  // every proof proves its own LP's prefix
}

TEST(SpatialModes, BoxInCornerSlidesAlongTheWallOnly) {
  const std::string text = read("spatial_box_in_corner");
  const SpatialModeTree t = spatial_modes(spatial_model(parse(text)));
  std::set<std::string> touching;
  for (const std::string& m : t.modes)
    if (m.find('s') == std::string::npos) touching.insert(m);
  EXPECT_EQ(touching, (std::set<std::string>{"ffffff", "GGGGIE", "CCCCAA"}));
  EXPECT_TRUE(check_text(spatial_modes_certificate(text, t)).valid);
}

// Peg in a square hole that it fits exactly, 8 contacts (4 walls, 2 heights): opposite contacts at one height share
// the acceleration along their normal line, so neither separates, and every contact keeps touching: a = (0, 0, a_z),
// alpha = (0, 0, alpha_z). A contact's tangential acceleration is then (+-alpha_z, a_z) in its frame (t1 horizontal,
// t2 = z), whose letter is fixed by the signs of alpha_z +- a_z: the 9 faces of two lines through the origin of the
// plane (a_z, alpha_z) - rest, 4 sectors, 4 rays.
TEST(SpatialModes, PegInHoleSlidesAndTwistsOnly) {
  const std::string text = read("spatial_peg_in_hole");
  const SpatialModeTree t = spatial_modes(spatial_model(parse(text)));
  EXPECT_EQ(t.modes.size(), 9u);
  for (const std::string& m : t.modes) EXPECT_EQ(m.find('s'), std::string::npos) << m;
  EXPECT_EQ(t.modes.front(), "ffffffff");
  EXPECT_TRUE(check_text(spatial_modes_certificate(text, t)).valid);
}

// A peg in a square hole as bench/spatial_bench's family: the four walls' middle lines at `heights` heights from
// z = 1/2 to 7/2 (opposite walls one after the other), normals into the peg.
std::string peg_text(int heights) {
  std::string text =
      R"({"kind": "spatial", "body": {"mass": 1, "inertia": [["5/3", 0, 0], [0, "5/3", 0], [0, 0, "2/3"]],
      "com": [0, 0, 2], "box": {"center": [0, 0, 2], "half": [1, 1, 2]}}, "mu": "1/2", "contacts": [)";
  const int wall[4][4] = {{1, 0, -1, 0}, {-1, 0, 1, 0}, {0, 1, 0, -1}, {0, -1, 0, 1}};
  for (int h = 0, i = 0; h < heights; ++h)
    for (const auto& w : wall) {
      const Q z = Q(1, 2) + Q(3 * h, heights - 1);
      text += std::string(i++ ? ", " : "") + "{\"point\": [" + std::to_string(w[0]) + ", " + std::to_string(w[1]) +
              ", \"" + z.get_str() + "\"], \"normal\": [" + std::to_string(w[2]) + ", " + std::to_string(w[3]) +
              ", 0]}";
    }
  return text + "]}";
}

// The tree is output-sensitive on the jammed peg: every letter implies a_n >= 0, so a prefix is decided with the
// later contacts' rows a_n >= 0 (prefix_system), and a prefix whose every acceleration pushes into a later wall dies
// at once. 9 modes at 8 and 16 contacts; without those rows the tree visited 18 621 and 16 541 prefixes.
TEST(SpatialModes, PegTreeIsOutputSensitive) {
  for (const std::string& text : {read("spatial_peg_in_hole"), peg_text(4)}) {
    const SpatialModeTree t = spatial_modes(spatial_model(parse(text)));
    EXPECT_EQ(t.modes.size(), 9u);
    EXPECT_LT(t.nodes, 2000);
    const checker::ModesCertificateCheck c = check_text(spatial_modes_certificate(text, t));
    EXPECT_TRUE(c.valid) << c.reason;
  }
}

// The brute force's own reading: contact i's point accelerates by a + alpha x r_i = P_i vdot; a letter is feasible
// with P's rows and the global argmin of d_j . (P vdot) over all edges (not the neighbours alone). Its rows on vdot:
// (row, strict > 0) or (row, = 0).
using BruteRows = std::vector<std::pair<Vec<Q>, bool>>;
BruteRows brute_rows(const SpatialScene& s, std::size_t i, char letter) {
  BruteRows rows;
  const SpatialContact& c = s.contacts[i];
  exact::Mat<Q> P = exact::Mat<Q>::Zero(3, 6);  // a + alpha x r: alpha x r = -r x alpha
  const Vec3 r{c.point[0] - s.body.com[0], c.point[1] - s.body.com[1], c.point[2] - s.body.com[2]};
  for (Eigen::Index k = 0; k < 3; ++k) P(k, k) = 1;
  P(0, 4) = r[2], P(0, 5) = -r[1], P(1, 3) = -r[2], P(1, 5) = r[0], P(2, 3) = r[1], P(2, 4) = -r[0];
  auto along = [&](const Vec3& u) -> Vec<Q> {
    Vec<Q> f = Vec<Q>::Zero(6);
    for (Eigen::Index k = 0; k < 3; ++k) f += u[static_cast<std::size_t>(k)] * Vec<Q>(P.row(k).transpose());
    return f;
  };
  const Vec<Q> n = along(c.normal);
  if (letter == 's') return {{n, true}};
  if (letter == 'f') {
    for (Eigen::Index k = 0; k < 3; ++k) rows.push_back({Vec<Q>(P.row(k).transpose()), false});
    return rows;
  }
  rows.push_back({n, false});
  const std::size_t m = c.edges.size(), L = static_cast<std::size_t>(letter - 'A'), j = L / 2;
  const std::set<std::size_t> active = L % 2 ? std::set<std::size_t>{j, (j + 1) % m} : std::set<std::size_t>{j};
  for (const std::size_t e : active)
    if (e != j) rows.push_back({along(c.edge(e)) - along(c.edge(j)), false});
  for (std::size_t e = 0; e < m; ++e)
    if (!active.count(e)) rows.push_back({along(c.edge(e)) - along(c.edge(j)), true});
  return rows;
}

// Whether some vdot satisfies every row: one exact LP.
bool brute_feasible(const BruteRows& rows) {
  exact::StrictSystem<Q> sys;
  const auto R = static_cast<Eigen::Index>(rows.size());
  sys.A = exact::Mat<Q>::Zero(R, 6 + R);
  sys.b = Vec<Q>::Zero(R);
  sys.is_free.assign(static_cast<std::size_t>(6 + R), false);
  sys.strict.assign(static_cast<std::size_t>(6 + R), false);
  for (std::size_t k = 0; k < 6; ++k) sys.is_free[k] = true;
  for (Eigen::Index k = 0; k < R; ++k) {
    sys.A.row(k).head(6) = rows[static_cast<std::size_t>(k)].first.transpose();
    sys.A(k, 6 + k) = -1;  // slack: = 0 rows fix it at 0 below
    if (rows[static_cast<std::size_t>(k)].second)
      sys.strict[static_cast<std::size_t>(6 + k)] = true;
    else
      sys.A(k, 6 + k) = 0;
  }
  return exact::strict_feasibility(sys, exact::Arith::kVerified).status == exact::StrictStatus::kFeasible;
}

BruteRows joined(BruteRows a, const BruteRows& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Every string of letters (the product of the contacts' alphabets, in its own order), each decided by one LP on its
// own rows. A string is rejected without its LP when one of its letters or two of them already have no solution
// (their rows are a subset of the string's): those LPs are asked once per letter and per pair of letters.
std::set<std::string> brute_force(const SpatialScene& s) {
  const std::size_t k = s.contacts.size();
  std::vector<std::string> alphabet;
  std::vector<std::vector<BruteRows>> rows(k);
  std::vector<std::vector<bool>> alone(k);
  for (std::size_t i = 0; i < k; ++i) {
    alphabet.push_back(letters(s.contacts[i].edges.size()));
    for (const char L : alphabet[i]) {
      rows[i].push_back(brute_rows(s, i, L));
      alone[i].push_back(brute_feasible(rows[i].back()));
    }
  }
  std::map<std::array<std::size_t, 4>, bool> pair;  // (i, letter, j, letter), i < j
  auto pair_feasible = [&](std::size_t i, std::size_t a, std::size_t j, std::size_t b) {
    const auto [it, fresh] = pair.try_emplace({i, a, j, b}, false);
    if (fresh) it->second = brute_feasible(joined(rows[i][a], rows[j][b]));
    return it->second;
  };
  std::set<std::string> out;
  std::vector<std::size_t> at(k, 0);  // the string's letters as indices, the last contact fastest
  for (bool more = true; more;) {
    bool possible = true;
    for (std::size_t i = 0; possible && i < k; ++i) possible = alone[i][at[i]];
    for (std::size_t i = 0; possible && i < k; ++i)
      for (std::size_t j = i + 1; possible && j < k; ++j) possible = pair_feasible(i, at[i], j, at[j]);
    BruteRows all;
    for (std::size_t i = 0; possible && i < k; ++i) all = joined(std::move(all), rows[i][at[i]]);
    if (possible && brute_feasible(all)) {
      std::string mode;
      for (std::size_t i = 0; i < k; ++i) mode += alphabet[i][at[i]];
      out.insert(mode);
    }
    more = false;
    for (std::size_t i = k; i-- > 0 && !more;) {
      more = ++at[i] < alphabet[i].size();
      if (!more) at[i] = 0;
    }
  }
  return out;
}

// A body with k contacts at small integer points with small integer normals (degenerate often: parallel normals,
// shared points), square pyramids or a stated hexagon.
SpatialScene random_scene(std::mt19937& rng, std::size_t k, bool hexagon) {
  std::uniform_int_distribution<int> coord(-2, 2);
  SpatialScene s;
  s.body.mass = 1;
  s.body.com = {Q(coord(rng)), Q(coord(rng)), Q(coord(rng))};
  for (std::size_t i = 0; i < k; ++i) {
    SpatialContact c;
    c.point = {Q(coord(rng)), Q(coord(rng)), Q(coord(rng))};
    do c.normal = {Q(coord(rng)), Q(coord(rng)), Q(coord(rng))};
    while (sgn(c.normal[0]) == 0 && sgn(c.normal[1]) == 0 && sgn(c.normal[2]) == 0);
    std::tie(c.t1, c.t2) = geometry::default_tangent_frame(c.normal);
    if (hexagon)
      c.edges = {{2, 0}, {1, 2}, {-1, 2}, {-2, 0}, {-1, -2}, {1, -2}};
    else
      c.edges = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    s.contacts.push_back(std::move(c));
  }
  return s;
}

// 100 seeded bodies of 1 to 3 contacts (square pyramids; hexagons up to 2 contacts), then 100 of 4 contacts (square
// pyramids: 10^4 strings each): the tree's list is the brute force's and every listed vdot realises its mode. The
// ASan + UBSan build of CI (-O0, some 20 times slower) checks the first 20 bodies and 5 of 4 contacts.
#ifdef CONTACTCERT_SANITIZED
constexpr int kSmall = 20, kFour = 5;
#else
constexpr int kSmall = 100, kFour = 100;
#endif
TEST(SpatialModes, RandomBodiesAgainstBruteForce) {
  std::mt19937 rng(34);
  for (int trial = 0; trial < 100 + kFour; ++trial) {
    if (trial == kSmall) trial = 100;
    const bool hexagon = trial < 100 && trial % 5 == 0;
    const std::size_t k = trial >= 100 ? 4 : hexagon ? 1 + trial % 2 : 1 + static_cast<std::size_t>(trial % 3);
    const SpatialScene s = random_scene(rng, k, hexagon);
    const SpatialModel model = spatial_model(s);
    const SpatialModeTree t = spatial_modes(model);
    EXPECT_EQ(mode_set(t), brute_force(s)) << "trial " << trial;
    for (std::size_t i = 0; i < t.modes.size(); ++i) EXPECT_TRUE(realises(model, t.modes[i], t.accelerations[i]));
  }
}

// The letters partition {a_n >= 0}: at a random acceleration every contact with a_n >= 0 meets exactly one letter.
TEST(SpatialModes, LettersPartitionTheAccelerations) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> small(-1, 1);
  const SpatialScene s = random_scene(rng, 3, true);
  const SpatialModel model = spatial_model(s);
  for (int trial = 0; trial < 300; ++trial) {
    Vec<Q> vdot(6);
    for (Eigen::Index d = 0; d < 6; ++d) vdot(d) = small(rng);
    for (std::size_t i = 0; i < 3; ++i) {
      if (sgn(Q(model.contacts[i].n.dot(vdot))) < 0) continue;
      int hits = 0;
      for (const char L : letters(6)) hits += realises(SpatialModel{{model.contacts[i]}}, std::string(1, L), vdot);
      EXPECT_EQ(hits, 1) << "trial " << trial << " contact " << i;
    }
  }
}

// An extruded planar scene (each touching fixel twice, at z = +-1, normals in the plane, frame (t, z) with t the
// planar tangent): its modes whose two copies agree on a letter of {s, f, A, E} are the planar modes, read
// s = s, f = n, E (friction along -t: sliding along +t) = l, A = r.
TEST(SpatialModes, ExtrudedPlanarScenesHaveThePlanarModes) {
  for (const char* name :
       {"bt2002_fig4b_nnn", "bt2002_fig4d_peg_nn", "bt2002_section7_disk", "bt2002_fig10_pentagon_insert"}) {
    const geometry::PlanarScene ps = geometry::load_planar_scene(runtime::bundled_scenes_dir() + "/" + name + ".json");
    std::set<std::string> planar;
    for (const ModeString& m : contact_modes(ps).tree.modes) planar.insert(m.text());
    const SpatialScene s = extruded(ps, /*mu_of_fixels=*/false);
    std::set<std::string> in_plane;
    for (const std::string& m : spatial_modes(spatial_model(s)).modes) {
      std::string p;
      for (std::size_t i = 0; i < m.size(); i += 2) {
        const char L = m[i];
        if (m[i + 1] != L || std::string("sfAE").find(L) == std::string::npos) break;
        p += L == 's' ? 's' : L == 'f' ? 'n' : L == 'E' ? 'l' : 'r';
      }
      if (p.size() == ps.fixels.size()) in_plane.insert(p);
    }
    EXPECT_EQ(in_plane, planar) << name;
  }
}

// The reader names the field of each defect (exit 2 in the CLI).
TEST(SpatialScene, ReaderNamesTheField) {
  const std::string box = read("spatial_box_on_plane");
  auto refuses = [&](const std::string& from, const std::string& to, const std::string& field) {
    std::string text = box;
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    try {
      parse(text);
      ADD_FAILURE() << "accepted: " << to;
    } catch (const exact::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  refuses("\"mass\": 1", "\"mass\": 0", "$.body.mass");
  refuses("[0, 0, \"2/3\"]", "[0, 0, \"-2/3\"]", "$.body.inertia");
  refuses("[[\"5/12\", 0, 0]", "[[\"5/12\", 1, 0]", "$.body.inertia");
  refuses("[1, 1, 0], \"normal\": [0, 0, 1]", "[1, 1, 0], \"normal\": [0, 0, 0]", "$.contacts[0].normal");
  refuses("[1, 1, 0], \"normal\": [0, 0, 1]", "[1, 1, 0], \"normal\": [0, 0, -1]", "$.contacts[0].normal");
  refuses("\"point\": [1, 1, 0]", "\"point\": [2, 1, 0]", "$.contacts[0].point");
  refuses("\"point\": [1, 1, 0]", "\"point\": [0, 0, \"1/2\"]", "$.contacts[0].point");
  refuses("\"normal\": [0, 0, 1]}", "\"normal\": [0, 0, 1], \"edges\": [[1, 0], [0, 1], [-1, 0]]}", "edges");
  refuses("\"normal\": [0, 0, 1]}", "\"normal\": [0, 0, 1], \"edges\": [[1, 0], [-1, 0], [0, 1], [0, -1]]}", "edges");
  refuses("\"normal\": [0, 0, 1]}", "\"normal\": [0, 0, 1], \"edges\": [[2, 0], [1, 1], [0, 2], [-1, 0], [0, -1]]}",
          "edges");
  refuses("\"normal\": [0, 0, 1]}", "\"normal\": [0, 0, 1], \"tangent\": [[0, 1, 0], [1, 0, 0]]}", "tangent");
  refuses("\"mu\": \"1/2\",", "", "$.contacts[0]");
}

// The default frame: rational, orthogonal, right-handed, and (x, y) for the normal z.
TEST(SpatialScene, DefaultFrame) {
  const auto [t1, t2] = geometry::default_tangent_frame({Q(0), Q(0), Q(1)});
  EXPECT_EQ(t1, (Vec3{Q(1), Q(0), Q(0)}));
  EXPECT_EQ(t2, (Vec3{Q(0), Q(1), Q(0)}));
  const Vec3 n{Q(2), Q(-3), Q(5, 7)};
  const auto [u1, u2] = geometry::default_tangent_frame(n);
  EXPECT_EQ(geometry::dot(u1, n), 0);
  EXPECT_EQ(geometry::dot(u2, n), 0);
  EXPECT_EQ(geometry::dot(u1, u2), 0);
  EXPECT_GT(geometry::dot(geometry::cross(u1, u2), n), 0);
}

// Forged certificates, one line edited in the line layout: each change below must be rejected (INVALID or an
// InputError naming the field).
TEST(SpatialModes, ForgedCertificatesAreRejected) {
  const std::string text = read("spatial_box_on_plane");
  const SpatialModeTree t = spatial_modes(spatial_model(parse(text)));
  const std::string good = spatial_modes_certificate(text, t);
  auto rejected = [](const std::string& forged) {
    try {
      return !check_text(forged).valid;
    } catch (const exact::InputError&) {
      return true;
    }
  };
  using J = nlohmann::json;
  const auto drop = [](J) { return J(); };
  EXPECT_TRUE(rejected(forge_line(good, "modes", 5, drop)));   // a feasible mode left out
  EXPECT_TRUE(rejected(forge_line(good, "modes", 5, [](J m) {  // a witness that does not realise its mode
    m["acceleration"][0] = "123";
    return m;
  })));
  EXPECT_TRUE(rejected(forge_line(good, "dead", 0, drop)));   // a parent's dead prefixes left out
  EXPECT_TRUE(rejected(forge_line(good, "dead", 0, [](J d) {  // one dead prefix left out
    d["letters"] = d["letters"].get<std::string>().substr(1);
    d["vectors"].erase(0);
    return d;
  })));
  EXPECT_TRUE(rejected(forge_line(good, "vectors", 0, [](J v) {  // a Motzkin weight changed
    v["motzkin"][0][1] = "-7";
    return v;
  })));
  EXPECT_TRUE(rejected(forge_line(good, "dead", 0, [](J d) {  // a dead prefix listed twice
    d["letters"] = d["letters"].get<std::string>() + d["letters"].get<std::string>()[0];
    d["vectors"].push_back(d["vectors"][0]);
    return d;
  })));
  EXPECT_TRUE(rejected(forge_line(good, "dead", 0, [](J d) {  // a vector that does not exist
    d["vectors"][0] = 100000;
    return d;
  })));
  EXPECT_TRUE(rejected(forge_line(good, "modes", 0, [](J m) {  // not a letter
    m["mode"] = "ssZs";
    return m;
  })));
  std::string moved = text;
  moved.replace(moved.find("[1, -1, 0]"), 10, "[1, 0, 0]");
  EXPECT_TRUE(rejected(forge_line(good, "scene", -1, [&](J) { return J(moved); })));  // the scene under its digest
  EXPECT_FALSE(rejected(forge_line(good, "modes", 5, [](J m) { return m; })));
  EXPECT_FALSE(rejected(good));
}

// A dead prefix's vector may weigh the row n . A vdot >= 0 of a contact past its letters (docs/formats.md section
// 5c), with weight <= 0, and nothing else there. The peg's certificate with its vectors and dead prefixes replaced by
// one hand-made vector and one prefix naming it: check verifies the proofs before the coverage, so a proof that
// holds ends in a coverage gap, one that does not in "does not verify". Its functionals (w_u = (u, r x u), r = p -
// com): n0 = (-1, 0, 0, 0, 3/2, 0) = -n1, n4 = (-1, 0, 0, 0, -3/2, 0) = -n5, and the t2 = (1, 0, 0) of the walls
// y+ (contacts 2 and 6, normal -y) u2 = (1, 0, 0, 0, -3/2, -1), u6 = (1, 0, 0, 0, 3/2, -1).
TEST(SpatialModes, ForgedLaterContactWeightsAreRejected) {
  const std::string text = read("spatial_peg_in_hole");
  const std::string good = spatial_modes_certificate(text, spatial_modes(spatial_model(parse(text))));
  auto one_proof = [&](const std::string& vector, const std::string& prefix) {
    const std::size_t vectors = good.find(" \"vectors\": [\n"), modes = good.find(" \"modes\": [\n");
    const std::string certificate = good.substr(0, vectors) + " \"vectors\": [\n  " + vector +
                                    "\n ],\n \"dead\": [\n  " +
                                    nlohmann::json{{"parent", prefix.substr(0, prefix.size() - 1)},
                                                   {"letters", prefix.substr(prefix.size() - 1)},
                                                   {"vectors", {0}}}
                                        .dump() +
                                    "\n ],\n" + good.substr(modes);
    return check_text(certificate).reason;
  };
  auto refused = [&](const std::string& vector, const std::string& prefix) {
    return one_proof(vector, prefix) == "the kinematic proof for prefix " + prefix + " does not verify";
  };
  // -n0 - n1 = 0: a_n0 > 0 (s) and a_n1 >= 0 (later, or any letter of contact 1).
  const std::string opposite = R"({"rows":[[0,"s",0],[1,"s",0]],"motzkin":[[0,"-1"],[1,"-1"]]})";
  EXPECT_FALSE(refused(opposite, "s"));
  EXPECT_FALSE(refused(opposite, "ss"));
  EXPECT_FALSE(refused(opposite, "sA"));
  // -n0 - n1 + n4 + n5 = 0: weight 1 on n4 and n5, right on equality rows, wrong on a_n >= 0 or a_n > 0.
  const std::string positive = R"({"rows":[[0,"s",0],[1,"s",0],[4,"s",0],[5,"s",0]],)"
                               R"("motzkin":[[0,"-1"],[1,"-1"],[2,"1"],[3,"1"]]})";
  EXPECT_TRUE(refused(positive, "s"));       // contacts 4 and 5 past the prefix: a_n >= 0 weighed 1
  EXPECT_TRUE(refused(positive, "sffff"));   // contact 5 past it
  EXPECT_TRUE(refused(positive, "sffffs"));  // contact 5's letter s: a_n > 0 weighed 1
  EXPECT_FALSE(refused(positive, "sfffff"));
  EXPECT_FALSE(refused(positive, "sfffEA"));
  // -n0 - u2 - n5 + u6 = 0: t2 weighed at contacts 2 and 6, which only their letters f have.
  const std::string tangent = R"({"rows":[[0,"s",0],[2,"f",2],[5,"s",0],[6,"f",2]],)"
                              R"("motzkin":[[0,"-1"],[1,"-1"],[2,"-1"],[3,"1"]]})";
  EXPECT_TRUE(refused(tangent, "s"));
  EXPECT_TRUE(refused(tangent, "sfffff"));   // contact 6 past the prefix
  EXPECT_TRUE(refused(tangent, "sfAffff"));  // letter A at contact 2 has no t2 row
  EXPECT_FALSE(refused(tangent, "sffffff"));
  EXPECT_FALSE(refused(tangent, "sfffffff"));
}

}  // namespace
}  // namespace contactcert::solvers::spatial
