// The prefix tree of contact modes (mode_tree.h) against the 4^k route it replaces, on seeded random scenes and
// on scenes whose modes are derived by hand; the completeness proofs it writes, and forged ones.
#include "solvers/stability/mode_tree.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <set>
#include <sstream>

#include "checker/modes_check.h"
#include "checker/stability_check.h"
#include "exact/json_input.h"
#include "geometry/nnc_cone.h"
#include "geometry/scene_json.h"
#include "runtime/scenes.h"
#include "solvers/stability/contact_modes.h"
#include "solvers/stability/stability_certificate.h"
#include "solvers/stability/stable_region.h"
#include "solvers/wrench_cone/wrench_cone.h"
#include "tests/solvers/stability/random_scene.h"

namespace contactcert::solvers {
namespace {

using exact::Q;
using exact::Vec;
using test::random_scene;

geometry::PlanarScene parse(const std::string& text) {
  return geometry::read_planar_scene(exact::JsonInput::parse(text, "scene.json"));
}

std::vector<bool> touching_of(const geometry::PlanarScene& scene) {
  std::vector<bool> t;
  for (const auto& f : scene.fixels) t.push_back(f.frame.touching());
  return t;
}

// The 4^k route: every mode string over the alphabet, each decided by its own LP.
std::set<std::string> feasible_by_brute_force(const MotionModel<Q>& model, const ModeAlphabet& alphabet,
                                              std::size_t k) {
  std::set<std::string> out;
  ModeString m;
  std::function<void()> all = [&] {
    if (m.letters.size() == k) {
      auto f = exact::strict_feasibility(kinematic_system(model, m, alphabet.rules), exact::Arith::kVerified);
      if (f.status == exact::StrictStatus::kFeasible) out.insert(m.text());
      return;
    }
    for (Interaction L : alphabet.letters(m.letters.size())) {
      m.letters.push_back(L);
      all();
      m.letters.pop_back();
    }
  };
  all();
  return out;
}

// Strong stability by the 4^k route: a resting LP, then every moving mode's LP in g.
StabilityVerdict verdict_by_brute_force(const geometry::PlanarScene& full, const Vec<Q>& g) {
  const geometry::PlanarScene scene = touching_scene(full);
  const std::size_t k = scene.fixels.size();
  const MotionModel<Q> model = motion_model<Q>(scene);
  const ModeString rolling{std::vector<Interaction>(k, Interaction::kRoll)};
  const auto rest =
      exact::strict_feasibility(motion_system(model, rolling, true).with_wrench(g), exact::Arith::kVerified);
  if (rest.status != exact::StrictStatus::kFeasible) return StabilityVerdict::kUnstable;
  for (const ModeString& m : moving_modes(k))
    if (exact::strict_feasibility(motion_system(model, m).with_wrench(g), exact::Arith::kVerified).status ==
        exact::StrictStatus::kFeasible)
      return StabilityVerdict::kWeaklyStable;
  return StabilityVerdict::kStronglyStable;
}

// The moving modes of the touching fixels whose wrench cone is non-empty, among all 4^k - 1 strings.
std::set<std::string> nonempty_cones_by_brute_force(const geometry::PlanarScene& scene) {
  const geometry::PlanarScene touching = touching_scene(scene);
  const ContactModel<Q> model = contact_model<Q>(touching);
  std::set<std::string> out;
  for (const ModeString& m : moving_modes(touching.fixels.size()))
    if (!is_empty_cone<Q>(wrench_cone_face<Q>(touching, model, m, Route::kPaper))) out.insert(m.text());
  return out;
}

// The moving modes of the stable region (from the mode tree).
std::set<std::string> region_modes(const geometry::PlanarScene& scene) {
  std::set<std::string> out;
  for (const ModeString& m : stable_region<Q>(scene).modes) out.insert(m.text());
  return out;
}

TEST(ModeTree, RandomScenesGiveTheModesOfThe4ToTheKRouteWithValidCertificates) {
  std::mt19937_64 rng(2026);
  long scenes = 0, modes = 0, with_gap = 0;
  for (int t = 0; t < 200; ++t) {
    const std::size_t k = t % 20 == 19 ? 6 : 1 + static_cast<std::size_t>(rng() % 5);
    const std::string text = random_scene(rng, k);
    const geometry::PlanarScene scene = parse(text);
    for (bool printed : {false, true}) {
      ContactModeOptions options;
      options.printed_separation = printed;
      options.unions = t % 7 == 0;
      const ContactModes m = contact_modes(scene, options);
      std::set<std::string> tree;
      for (std::size_t i = 0; i < m.tree.modes.size(); ++i) {
        tree.insert(m.tree.modes[i].text());
        EXPECT_TRUE(realises(m.model, m.alphabet.rules, m.tree.accelerations[i], m.tree.modes[i]));
      }
      EXPECT_EQ(tree.size(), m.tree.modes.size()) << "a mode listed twice";
      ASSERT_EQ(tree, feasible_by_brute_force(m.model, m.alphabet, k)) << text;
      const auto check =
          checker::check_modes_certificate(exact::JsonInput::parse(modes_certificate(text, m), "modes.json"));
      EXPECT_TRUE(check.valid) << check.reason << "\n" << text;
      modes += static_cast<long>(tree.size());
    }
    ++scenes;
    for (bool touching : touching_of(scene)) with_gap += !touching;
  }
  EXPECT_EQ(scenes, 200);
  EXPECT_GT(with_gap, 100);  // gap fixels are well represented
  EXPECT_GT(modes, 1000);
}

TEST(ModeTree, RandomStabilityVerdictsRegionsAndCertificatesEqualThe4ToTheKRoute) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<long> d(-3, 3);
  int strong = 0, weak = 0, unstable = 0;
  for (int t = 0; t < 60; ++t) {
    const std::string text = random_scene(rng, 1 + static_cast<std::size_t>(rng() % 4));
    const geometry::PlanarScene scene = parse(text);
    const StabilityOracle<Q> oracle(scene);
    std::vector<Vec<Q>> wrenches{(Vec<Q>(3) << 0, -1, 0).finished()};
    for (int w = 0; w < 2; ++w) wrenches.push_back((Vec<Q>(3) << d(rng), d(rng), d(rng)).finished());
    for (const Vec<Q>& g : wrenches) {
      const auto r = strong_stability<Q>(scene, g);
      ASSERT_EQ(r.verdict, verdict_by_brute_force(scene, g)) << text << "\ng = " << g.transpose();
      EXPECT_EQ(oracle.verdict(g).verdict, r.verdict);
      EXPECT_EQ(checker::check_stability(scene, g, r), "") << text;
      const auto c = checker::check_stability_certificate(
          exact::JsonInput::parse(stability_certificate(text, g, r), "stability.json"));
      EXPECT_TRUE(c.valid) << c.reason;
      strong += r.verdict == StabilityVerdict::kStronglyStable;
      weak += r.verdict == StabilityVerdict::kWeaklyStable;
      unstable += r.verdict == StabilityVerdict::kUnstable;
    }
    // The region's moving modes are those with a non-empty wrench cone among all 4^k - 1.
    if (t % 4 == 0) {
      EXPECT_EQ(region_modes(scene), nonempty_cones_by_brute_force(scene)) << text;
    }
  }
  EXPECT_GT(strong, 10);
  EXPECT_GT(weak, 10);
  EXPECT_GT(unstable, 10);
}

TEST(ModeTree, EveryBundledPlanarSceneGivesTheModesVerdictsAndRegionOfThe4ToTheKRoute) {
  int planar = 0;
  for (const auto& entry : std::filesystem::directory_iterator(contactcert::runtime::bundled_scenes_dir())) {
    const std::string text = exact::JsonInput::read_text(entry.path().string());
    if (text.find("\"planar\"") == std::string::npos || text.find("\"bodies\"") != std::string::npos)
      continue;  // assemblies (docs/formats.md section 3a) have their own tests
    const geometry::PlanarScene scene = parse(text);
    ++planar;
    for (bool printed : {false, true}) {
      ContactModeOptions options;
      options.printed_separation = printed;
      const ContactModes m = contact_modes(scene, options);
      std::set<std::string> tree;
      for (const ModeString& s : m.tree.modes) tree.insert(s.text());
      EXPECT_EQ(tree, feasible_by_brute_force(m.model, m.alphabet, scene.fixels.size())) << entry.path();
    }
    EXPECT_EQ(region_modes(scene), nonempty_cones_by_brute_force(scene)) << entry.path();
    for (const Vec<Q>& g : {(Vec<Q>(3) << 0, -1, 0).finished(), (Vec<Q>(3) << 1, -2, 1).finished()}) {
      const auto r = strong_stability<Q>(scene, g);
      EXPECT_EQ(r.verdict, verdict_by_brute_force(scene, g)) << entry.path();
      EXPECT_EQ(checker::check_stability(scene, g, r), "") << entry.path();
    }
  }
  EXPECT_GE(planar, 7);
}

std::set<std::string> mode_set(const std::string& scene) {
  const ContactModes m = contact_modes(parse(scene));
  std::set<std::string> out;
  for (const ModeString& s : m.tree.modes) out.insert(s.text());
  return out;
}

TEST(ModeTree, TwoAntipodalContactsByHand) {
  // Unit disk between fixels at (0,-1) (n = (0,1), t = (-1,0)) and (0,1) (n = (0,-1), t = (1,0)). With
  // vdot = (ax, ay, w): a_1n = ay, a_2n = -ay, so both are 0 (no s: it needs a_n > 0 at one and >= 0 at the
  // other); a_1t = -(ax + w) and a_2t = ax - w take every pair of signs: the 9 modes of {l, r, n}^2.
  const auto modes = mode_set(
      R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1}},
          "fixels":[{"position":[0,-1]},{"position":[0,1]}],"mu_s":"1/2","mu_k":"1/2"})");
  EXPECT_EQ(modes, (std::set<std::string>{"ll", "lr", "ln", "rl", "rr", "rn", "nl", "nr", "nn"}));
}

TEST(ModeTree, SquareTouchedAtItsFourEdgeMidpointsByHand) {
  // Every normal passes through the centre: a_n = (ay, -ax, -ay, ax) must all be >= 0, so ax = ay = 0 and no
  // fixel separates; each a_t is -w (rotation about the centre at unit distance, t = n turned by +90 deg):
  // w > 0 slides every contact right, w < 0 left, w = 0 is rest.
  const auto modes = mode_set(
      R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[-1,-1],[1,-1],[1,1],[-1,1]]}},
          "fixels":[{"position":[0,-1]},{"position":[1,0]},{"position":[0,1]},{"position":[-1,0]}],
          "mu_s":"1/2","mu_k":"1/2"})");
  EXPECT_EQ(modes, (std::set<std::string>{"rrrr", "llll", "nnnn"}));
}

TEST(ModeTree, BoxInACornerByHand) {
  // The square [0,2]^2 (com (1,1)) on floor fixels at (1/2,0), (3/2,0) and against a wall fixel at (0,1):
  //   a_1n = ay - w/2, a_2n = ay + w/2, a_1t = a_2t = -(ax + w), a_3n = ax, a_3t = ay - w.
  // Both floor contacts stay (w = ay = 0): rrs (ax > 0), nnn. Pivot on the left one (w > 0, ay = w/2): rss, rsr.
  // Pivot on the right one (w < 0, ay = -w/2, a_3t > 0): sls sns srs (ax > 0 with ax + w > 0, = 0, < 0) and sll
  // (ax = 0). Lift off the floor (ay > |w|/2): sss, and with ax = 0 the wall contact slides or rolls: ssl ssn ssr.
  const auto modes = mode_set(
      R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[2,0],[2,2],[0,2]]}},
          "fixels":[{"position":["1/2",0]},{"position":["3/2",0]},{"position":[0,1]}],"mu_s":"1/2","mu_k":"1/2"})");
  EXPECT_EQ(modes, (std::set<std::string>{"rrs", "nnn", "rss", "rsr", "sls", "sns", "srs", "sll", "sss", "ssl", "ssn",
                                          "ssr"}));
}

TEST(ModeTree, PegInASlotTouchingSixContactsByHand) {
  // The rectangle [-1,1] x [0,4] (com (0,2)) in a slot: fixels at the bottom (-1/2,0), (1/2,0), on the left wall
  // (-1,1), (-1,3) (n = (1,0), t = (0,1)) and on the right wall (1,1), (1,3) (n = (-1,0), t = (0,-1)). The wall
  // normals give a_n = ax + w, ax - w (left) and -(ax + w), -(ax - w) (right), all >= 0: ax = w = 0. Then the
  // bottom has a_n = ay >= 0, a_t = -ax = 0, the walls a_t = ay (left) and -ay (right): ay > 0 lifts the peg
  // (s s, l l, r r), ay = 0 is rest.
  const auto modes = mode_set(
      R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[-1,0],[1,0],[1,4],[-1,4]]}},
          "fixels":[{"position":["-1/2",0]},{"position":["1/2",0]},{"position":[-1,1]},{"position":[-1,3]},
                    {"position":[1,1]},{"position":[1,3]}],"mu_s":"1/2","mu_k":"1/2"})");
  EXPECT_EQ(modes, (std::set<std::string>{"ssllrr", "nnnnnn"}));
}

// A block [0, k] x [0, 1] resting on k fixels along its bottom, under gravity.
std::string block(std::size_t k) {
  std::ostringstream s;
  s << R"({"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[[0,0],[)" << k << "," << 0 << "],[" << k
    << R"(,1],[0,1]]}},"mu_s":"1/2","mu_k":"1/2","fixels":[)";
  for (std::size_t i = 0; i < k; ++i) s << (i ? "," : "") << R"({"position":[")" << 2 * i + 1 << R"(/2",0]})";
  s << "]}";
  return s.str();
}

TEST(ModeTree, BlocksOnSixteenAndThirtyTwoFixelsAreStronglyStableWithCheckedCertificates) {
  const Vec<Q> g = (Vec<Q>(3) << 0, -1, 0).finished();
  for (std::size_t k : {16u, 32u}) {
    const std::string text = block(k);
    const auto scene = parse(text);
    const auto r = strong_stability<Q>(scene, g);
    ASSERT_EQ(r.verdict, StabilityVerdict::kStronglyStable);
    // Lift (all s), pivot on either end (3 letters each), slide or rest (l..l, r..r; n..n is not moving).
    EXPECT_EQ(r.modes_kinematically_feasible, 9);
    const std::string cert = stability_certificate(text, g, r);
    const auto c = checker::check_stability_certificate(exact::JsonInput::parse(cert, "block.json"));
    EXPECT_TRUE(c.valid) << c.reason;
  }
}

TEST(ModeTree, ForgedCompletenessProofsAreRejected) {
  const std::string text = block(6);
  const auto scene = parse(text);
  const Vec<Q> g = (Vec<Q>(3) << 0, -1, 0).finished();
  const auto r = strong_stability<Q>(scene, g);
  ASSERT_EQ(r.verdict, StabilityVerdict::kStronglyStable);
  ASSERT_EQ(checker::check_stability(scene, g, r), "");
  auto with_proofs = [&r](auto keep) {
    StabilityResult<Q> bad = r;
    bad.proofs = ModeProofs<Q>();
    for (std::size_t i = 0; i < r.proofs.size(); ++i) keep(i, r.proofs[i], bad.proofs);
    return bad;
  };
  // An empty tree proves nothing.
  EXPECT_NE(checker::check_stability(scene, g, with_proofs([](auto, auto&, auto&) {})), "");
  for (std::size_t drop = 0; drop < r.proofs.size(); ++drop) {
    // A missing branch: one dead prefix or one mode's proof left out.
    const auto missing = with_proofs([&](std::size_t i, const ModeProof<Q>& p, ModeProofs<Q>& out) {
      if (i != drop) out.push_back(p);
    });
    EXPECT_NE(checker::check_stability(scene, g, missing), "") << "without " << r.proofs[drop].mode.text();
    // A dead node with a wrong vector.
    const auto wrong = with_proofs([&](std::size_t i, const ModeProof<Q>& p, ModeProofs<Q>& out) {
      ModeProof<Q> c = p;
      if (i == drop) c.motzkin(0) += 1;
      out.push_back(c);
    });
    EXPECT_NE(checker::check_stability(scene, g, wrong), "") << "changed " << r.proofs[drop].mode.text();
  }
  // A dead prefix claimed for a prefix it does not prove (its letters changed).
  const auto relabelled = with_proofs([&](std::size_t, const ModeProof<Q>& p, ModeProofs<Q>& out) {
    ModeProof<Q> c = p;
    if (c.kinematic && c.mode.letters.back() == Interaction::kSeparate) c.mode.letters.back() = Interaction::kSlideLeft;
    out.push_back(c);
  });
  EXPECT_NE(checker::check_stability(scene, g, relabelled), "");
  // A moving witness in a letter that is no motion from rest (m) is refused, in the API and in a file.
  StabilityResult<Q> maintain = r;
  maintain.verdict = StabilityVerdict::kWeaklyStable;
  maintain.has_moving = true;
  maintain.proofs = ModeProofs<Q>();
  maintain.moving = {ModeString{std::vector<Interaction>(6, Interaction::kMaintain)}, Vec<Q>::Zero(12),
                     (Vec<Q>(3) << 0, 1, 0).finished()};
  EXPECT_NE(checker::check_stability(scene, g, maintain), "");
  std::string cert = stability_certificate(text, g, strong_stability<Q>(scene, (Vec<Q>(3) << 0, 1, 0).finished()));
  const std::size_t at = cert.find("\"mode\": \"");
  ASSERT_NE(at, std::string::npos);
  cert.replace(at + 9, 6, "mmmmmm");
  EXPECT_THROW(checker::check_stability_certificate(exact::JsonInput::parse(cert, "forged.json")), exact::InputError);
}

// The mode tree by plain recursion, as it was written before the walk became iterative: at a live prefix, each
// letter in alphabet order either extends it (its rows feasible: recurse) or is a dead prefix.
void recursive_walk(const MotionModel<Q>& model, const ModeAlphabet& alphabet, std::size_t k, ModeString& prefix,
                    std::vector<std::string>& modes, std::vector<std::string>& dead) {
  if (prefix.letters.size() == k) {
    modes.push_back(prefix.text());
    return;
  }
  for (Interaction L : alphabet.letters(prefix.letters.size())) {
    prefix.letters.push_back(L);
    if (exact::strict_feasibility(kinematic_system(model, prefix, alphabet.rules), exact::Arith::kExact).status ==
        exact::StrictStatus::kFeasible)
      recursive_walk(model, alphabet, k, prefix, modes, dead);
    else
      dead.push_back(prefix.text());
    prefix.letters.pop_back();
  }
}

// The iterative walk's modes and dead prefixes, in order, against recursive_walk's.
void expect_recursive_order(const geometry::PlanarScene& scene, bool unions, bool printed, const std::string& what) {
  ContactModeOptions options;
  options.unions = unions;
  options.printed_separation = printed;
  const ContactModes m = contact_modes(scene, options);
  std::vector<std::string> modes, dead, tree_modes, tree_dead;
  ModeString prefix;
  recursive_walk(m.model, m.alphabet, scene.fixels.size(), prefix, modes, dead);
  for (const ModeString& mode : m.tree.modes) tree_modes.push_back(mode.text());
  for (const DeadPrefix<Q>& d : m.tree.dead) tree_dead.push_back(d.prefix.text());
  EXPECT_EQ(tree_modes, modes) << what;
  EXPECT_EQ(tree_dead, dead) << what;
}

TEST(ModeTree, TheIterativeWalkListsWhatTheRecursiveOneDidInItsOrder) {
  std::mt19937_64 rng(29);
  for (int t = 0; t < 60; ++t) {
    const std::string text = random_scene(rng, 1 + static_cast<std::size_t>(rng() % 5));
    for (bool unions : {false, true}) expect_recursive_order(parse(text), unions, t % 2 == 1, text);
  }
  for (const auto& entry : std::filesystem::directory_iterator(runtime::bundled_scenes_dir())) {
    const std::string text = exact::JsonInput::read_text(entry.path().string());
    if (text.find("\"planar\"") == std::string::npos || text.find("\"bodies\"") != std::string::npos)
      continue;  // assemblies (docs/formats.md section 3a) have their own tests
    for (bool unions : {false, true})
      for (bool printed : {false, true}) expect_recursive_order(parse(text), unions, printed, entry.path());
  }
  for (const std::string& text : {block(6), block(12)}) expect_recursive_order(parse(text), false, false, text);
}

TEST(ModeTree, TwentyThousandFixelsDoNotDeepenTheCallStack) {
  // 20 000 gap fixels under a bar: vdot = 0 realises s at each, so the first path of the walk is s..s, 20 000
  // live prefixes deep, with no LP. The node budget ends the walk right after it: its depth was a vector, not the
  // call stack (the recursive walk overflowed 8 MiB of stack near 17 000 fixels).
  const int k = 20000;
  std::ostringstream text;
  text << R"({"kind": "planar", "workpiece": {"shape": {"type": "polygon", "vertices": [[0,0],[)" << 2 * k << R"(,0],[)"
       << 2 * k << R"(,1],[0,1]]}}, "mu_s": "1/2", "mu_k": "1/2", "fixels": [)";
  for (int i = 0; i < k; ++i) text << (i ? "," : "") << R"({"position": [)" << 2 * i + 1 << ", -1]}";
  text << "]}";
  ContactModeOptions options;
  options.tree.max_nodes = k + 1;  // the empty prefix and the k letters of s..s
  try {
    contact_modes(parse(text.str()), options);
    FAIL() << "no budget error";
  } catch (const exact::BudgetExceeded& e) {
    EXPECT_EQ(std::string(e.covered), std::to_string(k + 1) + " prefixes visited, 1 feasible modes found");
  }
}

TEST(ModeTree, BudgetsStopTheWalkWithWhatItCovered) {
  const auto scene = parse(block(12));
  const MotionModel<Q> model = motion_model<Q>(scene);
  ModeTreeOptions options;
  options.max_nodes = 20;
  try {
    walk_modes(model, moving_alphabet(12), options);
    FAIL() << "no budget error";
  } catch (const exact::BudgetExceeded& e) {
    EXPECT_NE(std::string(e.covered).find("prefixes visited"), std::string::npos);
  }
  // The output budget: the unions of 12 gap fixels list many overlapping modes.
  options = ModeTreeOptions();
  options.max_modes = 50;
  ModeAlphabet unions = moving_alphabet(12);
  unions.unions = true;
  try {
    walk_modes(model, unions, options);
    FAIL() << "no budget error";
  } catch (const exact::BudgetExceeded& e) {
    EXPECT_NE(std::string(e.what()).find("output budget of 50 modes"), std::string::npos);
    EXPECT_NE(std::string(e.covered).find("50 feasible modes found"), std::string::npos);
  }
}

}  // namespace
}  // namespace contactcert::solvers
