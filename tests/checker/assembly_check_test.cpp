// The assembly checker: N = 1 against the one-body stability solver (solvers/stability) on the bundled scenes, and
// forged evidence refused (a dropped branch, a wrong vector, a relabelled body, a claimed verdict without its
// evidence).
#include "checker/assembly_check.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/scene_json.h"
#include "runtime/scenes.h"
#include "solvers/stability/strong_stability.h"
#include "tests/solvers/assembly/assembly_fixtures.h"

namespace contactcert::solvers::assembly {
namespace {

using testing::body;
using testing::box;
using testing::obstacle;
using testing::point;
using testing::SceneText;

/// The one-body scene as an assembly: the workpiece with mass 1 and inertia I/m (the single-body model's M =
/// diag(1, 1, I/m)), load g, and each touching fixel a point fixel at its contact point with its frame.
geometry::Assembly as_assembly(const geometry::PlanarScene& scene, const Vec<Q>& g) {
  geometry::Assembly a;
  const geometry::Workpiece& w = scene.workpiece;
  a.bodies.push_back({w.shape, w.com, Q(1), w.inertia_per_mass, g(0), g(1), g(2)});
  for (const geometry::Fixel& f : scene.fixels) {
    if (!f.frame.touching()) continue;
    a.fixels.push_back(f.frame.point);
    a.contacts.push_back({{geometry::Party::Kind::kFixel, a.fixels.size() - 1},
                          {geometry::Party::Kind::kBody, 0},
                          f.frame.point,
                          f.frame.normal,
                          f.mu_s,
                          f.mu_k});
  }
  return a;
}

AssemblyVerdict from_single(StabilityVerdict v) {
  switch (v) {
    case StabilityVerdict::kStronglyStable:
      return AssemblyVerdict::kStronglyStable;
    case StabilityVerdict::kWeaklyStable:
      return AssemblyVerdict::kWeaklyStable;
    default:
      return AssemblyVerdict::kUnstable;
  }
}

TEST(AssemblyCheck, OneBodyAgreesWithTheSingleBodySolverOnTheBundledScenes) {
  std::mt19937_64 rng(29);
  std::uniform_int_distribution<int> d(-3, 3);
  int compared = 0, counts[3] = {0, 0, 0};
  for (const char* name :
       {"bt2002_fig4a_lla.json", "bt2002_fig4b_nnn.json", "bt2002_fig4c_peg_lra.json", "bt2002_fig4d_peg_nn.json",
        "bt2002_section4_disk.json", "bt2002_section7_disk.json", "bt2002_fig10_pentagon_insert.json"}) {
    const geometry::PlanarScene scene = geometry::load_planar_scene(runtime::bundled_scenes_dir() + "/" + name);
    for (int w = 0; w < 12; ++w) {
      Vec<Q> g(3);
      g(2) = d(rng);
      g(1) = d(rng);
      g(0) = d(rng);
      const geometry::Assembly a = as_assembly(scene, g);
      if (a.contacts.empty()) continue;
      const StabilityResult<Q> one = strong_stability<Q>(scene, g);
      const AssemblyStabilityResult many = assembly_stability(a);
      ASSERT_EQ(many.status, AssemblyStatus::kDecided);
      EXPECT_EQ(many.verdict, from_single(one.verdict)) << name << " g = " << g.transpose();
      EXPECT_EQ(checker::check_assembly_stability(a, many), "") << name;
      ++compared;
      ++counts[static_cast<int>(many.verdict)];
    }
  }
  EXPECT_EQ(compared, 7 * 12);
  for (const int c : counts) EXPECT_GT(c, 0) << counts[0] << " " << counts[1] << " " << counts[2];
}

/// Two stacked boxes of different masses (the lower 2 x 1, the upper 1 x 1 on its left half) under a sideways
/// load, bodies in the order given: the walk needs several dead prefixes.
SceneText two_boxes(bool swapped, const char* lateral) {
  SceneText s;
  const std::size_t g = testing::ground(s);
  const std::string lower = box(0, 0, 2, 1), upper = box(0, 1, 1, 2);
  const std::string load_lower = std::string("\"load\": [") + lateral + ", -2, 0]";
  const std::string load_upper = std::string("\"load\": [") + lateral + ", -1, 0]";
  const std::size_t L = swapped ? 1 : 0, U = swapped ? 0 : 1;
  if (swapped) {
    s.body(upper, load_upper);
    s.body(lower, load_lower);
  } else {
    s.body(lower, load_lower);
    s.body(upper, load_upper);
  }
  for (const Q& x : {Q(0), Q(2)}) s.contact(obstacle(g), body(L), point(x, 0), "[0, 1]", testing::mu("1/2"));
  for (const Q& x : {Q(0), Q(1)}) s.contact(body(L), body(U), point(x, 1), "[0, 1]", testing::mu("1/2"));
  return s;
}

TEST(AssemblyCheck, ForgedStronglyStableCertificatesAreRefused) {
  const geometry::Assembly a = two_boxes(false, "\"1/4\"").read();
  const AssemblyStabilityResult r = assembly_stability(a);
  ASSERT_EQ(r.verdict, AssemblyVerdict::kStronglyStable);
  ASSERT_EQ(checker::check_assembly_stability(a, r), "");
  ASSERT_GE(r.dead.size(), 3u);
  for (std::size_t j = 0; j < r.dead.size(); j += 3) {  // a dropped branch
    AssemblyStabilityResult f = r;
    f.dead.erase(f.dead.begin() + static_cast<std::ptrdiff_t>(j));
    EXPECT_NE(checker::check_assembly_stability(a, f), "") << "dropped " << r.dead[j].prefix;
  }
  {  // a wrong vector: one certificate's entries shifted by one place
    AssemblyStabilityResult f = r;
    Vec<Q>& y = f.dead[0].motzkin;
    const Q first = y(0);
    for (Eigen::Index i = 0; i + 1 < y.size(); ++i) y(i) = y(i + 1);
    y(y.size() - 1) = first;
    EXPECT_NE(checker::check_assembly_stability(a, f), "");
  }
  {  // a wrong vector: a dead prefix relabelled to another letter
    AssemblyStabilityResult f = r;
    std::string& p = f.dead.back().prefix;
    p.back() = p.back() == 's' ? 'l' : 's';
    EXPECT_NE(checker::check_assembly_stability(a, f), "");
  }
  {  // the resting forces of another load
    AssemblyStabilityResult f = r;
    f.resting_forces(0) += 1;
    EXPECT_NE(checker::check_assembly_stability(a, f), "");
  }
  // A relabelled body: the same certificate against the scene with its bodies listed the other way round.
  const geometry::Assembly swapped = two_boxes(true, "\"1/4\"").read();
  EXPECT_EQ(assembly_stability(swapped).verdict, AssemblyVerdict::kStronglyStable);
  EXPECT_NE(checker::check_assembly_stability(swapped, r), "");
  {  // a claimed weak verdict without a moving solution, an undecided one
    AssemblyStabilityResult f = r;
    f.verdict = AssemblyVerdict::kWeaklyStable;
    EXPECT_NE(checker::check_assembly_stability(a, f), "");
    f = r;
    f.status = AssemblyStatus::kTimeLimit;
    EXPECT_NE(checker::check_assembly_stability(a, f), "");
  }
}

TEST(AssemblyCheck, ForgedWitnessesAreRefused) {
  // mu_s = 1/2 everywhere; with mu_k = 1/8 at the ground and a lateral load of 1/2 per unit weight the stack
  // slides: weakly stable with a moving witness.
  SceneText s = two_boxes(false, "\"1/2\"");
  for (std::size_t i = 0; i < 2; ++i) {
    const std::size_t at = s.contacts[i].find("\"mu\"");
    s.contacts[i] = s.contacts[i].substr(0, at) + "\"mu_s\": \"1/2\", \"mu_k\": \"1/8\"}";
  }
  s.bodies[0] = "{\"shape\": " + box(0, 0, 2, 1) + ", \"load\": [1, -2, 0]}";
  const geometry::Assembly a = s.read();
  const AssemblyStabilityResult r = assembly_stability(a);
  ASSERT_EQ(r.verdict, AssemblyVerdict::kWeaklyStable);
  ASSERT_EQ(checker::check_assembly_stability(a, r), "");
  {  // the bodies' accelerations relabelled
    AssemblyStabilityResult f = r;
    for (Eigen::Index d = 0; d < 3; ++d) std::swap(f.moving.acceleration(d), f.moving.acceleration(3 + d));
    if (f.moving.acceleration != r.moving.acceleration) {
      EXPECT_NE(checker::check_assembly_stability(a, f), "");
    }
  }
  {  // a force scaled
    AssemblyStabilityResult f = r;
    f.moving.forces *= 2;
    EXPECT_NE(checker::check_assembly_stability(a, f), "");
  }
  {  // another mode's letter
    AssemblyStabilityResult f = r;
    f.moving.mode[0] = f.moving.mode[0] == 'n' ? 'r' : 'n';
    EXPECT_NE(checker::check_assembly_stability(a, f), "");
  }
  {  // at rest, passed off as moving
    AssemblyStabilityResult f = r;
    f.moving.acceleration.setZero();
    EXPECT_NE(checker::check_assembly_stability(a, f), "");
  }
  {  // strongly stable claimed, the moving witness removed and no dead prefixes
    AssemblyStabilityResult f = r;
    f.verdict = AssemblyVerdict::kStronglyStable;
    f.has_moving = false;
    EXPECT_NE(checker::check_assembly_stability(a, f), "");
  }
}

TEST(AssemblyCheck, ForgedUnstableCertificatesAreRefused) {
  SceneText s;
  const std::size_t g = testing::ground(s);
  const std::size_t b0 = testing::stack_box(s, obstacle(g), 0, 0, 2, 1, 0, 2, "1/2");
  testing::stack_box(s, body(b0), Q(3, 2), 1, Q(7, 2), 2, Q(3, 2), 2, "1/2");
  const geometry::Assembly a = s.read();
  const AssemblyStabilityResult r = assembly_stability(a);
  ASSERT_EQ(r.verdict, AssemblyVerdict::kUnstable);
  ASSERT_EQ(checker::check_assembly_stability(a, r), "");
  AssemblyStabilityResult f = r;
  f.resting_farkas = -f.resting_farkas;
  EXPECT_NE(checker::check_assembly_stability(a, f), "");
  f = r;
  f.resting_farkas.setZero();
  EXPECT_NE(checker::check_assembly_stability(a, f), "");
  // The same certificate for the stable stack (the top box back over the lower one) does not prove it unstable.
  const geometry::Assembly stable = testing::box_stack(2).read();
  EXPECT_NE(checker::check_assembly_stability(stable, r), "");
}

// The walk's contact order (AssemblyStabilityResult::contact_order): a row of three boxes under a lateral push goes
// body by body from the first box (no box hangs off the others and all stand on the ground: the fewest open contacts,
// ties to the earlier body): box 0's ground and interface contacts 0, 1, 4, 5, box 1's ground and interface 2, 3, 8,
// 9, box 2's ground 6, 7. Its dead prefixes are letters in that order; the checker places them itself, so the file's
// order, two swapped contacts or an index listed twice are refused.
TEST(AssemblyCheck, ContactOrderIsCheckedNotTrusted) {
  SceneText s = testing::box_row(3);
  for (std::string& b : s.bodies) b.insert(b.size() - 1, R"(, "load": ["1/2", -2, 0])");
  const geometry::Assembly a = s.read();
  EXPECT_EQ(walk_order(a), (std::vector<std::size_t>{0, 1, 4, 5, 2, 3, 8, 9, 6, 7}));
  EXPECT_EQ(file_letters(walk_order(a), "slr"), "sl**r*****");
  const AssemblyStabilityResult r = assembly_stability(a);
  ASSERT_EQ(r.verdict, AssemblyVerdict::kStronglyStable);
  ASSERT_EQ(r.contact_order, walk_order(a));
  ASSERT_EQ(checker::check_assembly_stability(a, r), "");
  AssemblyStabilityResult f = r;
  f.contact_order.clear();  // read in the file's order
  EXPECT_NE(checker::check_assembly_stability(a, f), "");
  f = r;
  std::swap(f.contact_order[0], f.contact_order[9]);
  EXPECT_NE(checker::check_assembly_stability(a, f), "");
  f = r;
  f.contact_order[1] = f.contact_order[0];
  EXPECT_EQ(checker::check_assembly_stability(a, f), "contact_order is not an order of the contacts (each index once)");
  f.contact_order.pop_back();
  EXPECT_NE(checker::check_assembly_stability(a, f), "");
}

}  // namespace
}  // namespace contactcert::solvers::assembly
